#pragma once
/** @file
 * @brief The `stylos` command line: FILES to open (a `.stylos` project, or scans and `.poct` octrees to
 *        import; none: the demo scene), --grab OUT.png, --orbit-benchmark N and --pose-benchmark N for
 *        automation (--gizmo: the docking gizmo in the grab; --dock: a dock and its contact readout; --paint: a painted développée), --help and --version (handled by QCommandLineParser, which exits).
 */
#include <QString>
#include <QStringList>

class QCoreApplication;

namespace stylos::app {

struct CommandLine {
    QStringList files;       ///< what to open; empty: the demo scene
    QString grabPath;        ///< non-empty: render the window to this PNG once everything is ready, then exit
    bool grabDock = false;   ///< with grabPath: dock the second fragment to the first's flutes, contact shown
    bool grabPaint = false;  ///< with grabPath: the first fragment's développée painted with a few regions
    bool grabGizmo = false;  ///< with grabPath: dock the second fragment against the first's guides, gizmo shown
    QString plateBase;       ///< with grabPath: the demo plate written to BASE.pdf and BASE.png, the dialog grabbed
    bool grabAnnotation = false; ///< with grabPath: three regions of the first fragment lassoed, Annotation shading
    int orbitFrames = 0;     ///< > 0: orbit the camera for this many frames, print JSON, exit
    int poseFrames = 0;      ///< > 0: turn the first fragment (a pose change) for this many frames, print JSON, exit

    /** Parses the application's arguments; exits the process for --help, --version and usage errors (2). */
    static CommandLine parse(const QCoreApplication& app);
};

} // namespace stylos::app
