#pragma once
/** @file
 * @brief The automation behind `stylos --grab`, `--orbit-benchmark` and `--pose-benchmark`: wait until the window is
 *        ready — no task running, no import or octree load pending, the demo prepared, and the 3D view
 *        showing every opened fragment at full detail — then act and quit the application. Polls every
 *        200 ms (the window is never blocked); gives up after @p timeoutMs with exit status 1.
 */
#include <QString>

namespace stylos::app {

class MainWindow;

/** @brief True when @p window is ready as described above. */
bool isWindowReady(const MainWindow& window);

/**
 * @brief Once ready, saves the window as a PNG to @p path and quits: status 0, or 1 when an error was
 *        logged meanwhile (a file that did not load, a failed task) or the image could not be written.
 */
void grabWhenReady(MainWindow& window, const QString& path, int timeoutMs = 15 * 60 * 1000);

/**
 * @brief As grabWhenReady(), with the docking gizmo in the picture: once ready, fits the first fragment's drum
 *        guides (unless it has flute guides), docks against it, selects the second fragment and shows the Move tool in
 *        the Drum frame; then, once ready again, grabs. Status 1 as above, or when the scene has fewer than two
 *        fragments.
 */
void grabGizmoWhenReady(MainWindow& window, const QString& path, int timeoutMs = 15 * 60 * 1000);

/**
 * @brief As grabWhenReady(), with the annotation in 3D in the picture: once ready, selects the first fragment,
 *        labels three regions of it with the 3D lasso (polygons over its projected bounds: preserved marble,
 *        fractured marble, plaster — the visible cells only), switches to the Annotation shading; once ready
 *        again, grabs. Status 1 as above, or without a fragment or the 3D view.
 */
void grabAnnotationWhenReady(MainWindow& window, const QString& path, int timeoutMs = 15 * 60 * 1000);

/**
 * @brief As grabWhenReady(), with a dock in the picture: once ready, fits the first fragment's drum guides (unless it
 *        has flute guides), makes it the docking drum, selects the second fragment and docks it to the flutes from
 *        where it stands (Dock to flutes); once its contact readout is in, grabs. Status 1 as above, or when the
 *        scene has fewer than two fragments or the dock fails.
 */
void grabDockWhenReady(MainWindow& window, const QString& path, int timeoutMs = 15 * 60 * 1000);

/**
 * @brief As grabWhenReady(), with a painted développée: once ready, computes the first fragment's développée and,
 *        when it is shown, paints a few regions through the développée view's painting signals (the path the
 *        mouse takes): preserved marble, a band of fractured marble and plaster in the material layer, a
 *        claw-chisel area in the tool-mark layer; shows the material layer and the Legend dock; once the class
 *        areas are measured, grabs. Status 1 as above, or when there is no fragment or it cannot be painted.
 */
void grabPaintWhenReady(MainWindow& window, const QString& path, int timeoutMs = 15 * 60 * 1000);
/**
 * @brief As grabDockWhenReady() up to the dock, then the développée of the second fragment's assembly (its drum with
 *        the docked fragment at its place), painted through the view's painting signals across the drum and the
 *        fragment (preserved marble over the fragment's left part and the drum beside it, plaster across its right
 *        part onto the drum), zoomed on the fragment; grabs once ready. Status 1 as above, or when the fragment is in
 *        no assembly or does not show in its développée.
 */
void grabAssemblyPaintWhenReady(MainWindow& window, const QString& path, int timeoutMs = 15 * 60 * 1000);
/** @brief As grabPaintWhenReady, then the demo plate (développée and front view of the first fragment, its material
 *         layer in colour and in hatches) written to BASE.pdf (300 dpi) and BASE.png (200 dpi) and kept in the
 *         project; the Export plate dialog with its preview grabbed into @p path. */
void grabPlateWhenReady(MainWindow& window, const QString& path, const QString& base, int timeoutMs = 15 * 60 * 1000);

/**
 * @brief Hides the docks and toolbar, sizes the 3D view to 1280 × 800, and once ready orbits the camera
 *        for @p frames frames (widgets::OrbitBenchmark), prints the JSON result on stdout and quits (0;
 *        1 without a 3D view, or when the scene failed to open). The result adds "openToFirstFrameMs":
 *        from this call (made just before the file is opened) to the first frame that drew points.
 */
void orbitWhenReady(MainWindow& window, int frames, int timeoutMs = 15 * 60 * 1000);

/**
 * @brief As orbitWhenReady(), but the camera stays and the first fragment turns about the vertical axis through
 *        its centre, 1° a frame (widgets::PoseBenchmark), each pose an edit of the document
 *        (SceneDocument::setFragmentPose, one merged undo step, as a drag) pushed to the view at once
 *        (ViewportSync::pushNow: a pose only, no new cut); the frame time covers the edit, the push and the frame.
 */
void poseWhenReady(MainWindow& window, int frames, int timeoutMs = 15 * 60 * 1000);

} // namespace stylos::app
