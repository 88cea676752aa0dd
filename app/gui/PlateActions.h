#pragma once
/** @file
 * @brief File › Export plate…, Export développée image… and Export view image…: the actions and their handlers.
 *        Export plate opens the plate dialog (widgets/plate/PlateDialog) on the project's kept plate (or a
 *        default), keeps the stated plate in the project (one undo step), asks for the file (PDF, SVG, TIFF, PNG)
 *        and draws it at full resolution as a background task (the Tasks dock shows it; the plate reads the
 *        document's labels as they are, saved or not). Export développée image writes the développée on show
 *        as PNG or TIFF with its pixel size in the file, and its map sidecar (OUT.json) beside it.
 *        Export view image renders the visible fragments orthographically along the 3D view's camera at a chosen
 *        width in pixels (every leaf, skydome shading when every octree has it, else headlight) as PNG or TIFF, as
 *        a background task. Outcomes go out as messages (reported()). GUI thread only.
 */
#include "stylos/core/plate/PlateSources.h"

#include <QObject>

#include <array>
#include <functional>
#include <memory>
#include <optional>

class QAction;
class QMenu;
class QWidget;

namespace stylos::widgets {
class DeveloppeeView;
class SceneDocument;
} // namespace stylos::widgets

namespace stylos::app {

class PlateActions : public QObject {
    Q_OBJECT

public:
    PlateActions(widgets::SceneDocument& document, widgets::DeveloppeeView& developpee, QWidget& window);

    /** @brief Adds the actions to @p menu (File) before @p before (Quit), with a separator. */
    void populate(QMenu& menu, QAction* before);
    void retranslateUi();

    /** @brief What a plate of the document is made from: every fragment with its world pose, visibility, octree
     *         and labels as the document holds them, and the project's legend. */
    static std::shared_ptr<const core::plate::PlateSources> sourcesOf(const widgets::SceneDocument& document);

    /** @brief Where the dialog reads the 3D view's camera from (offered as "Current view"); none by default. */
    void setCameraSource(std::function<std::optional<std::array<double, 4>>()> camera) { m_camera = std::move(camera); }
    /** @brief Where the dialog reads the fragment the user works on from (the scene's current row): a project with
     *         no kept plate opens on that fragment's développée. None by default (the first visible fragment). */
    void setFragmentSource(std::function<core::scene::FragmentId()> fragment) { m_fragment = std::move(fragment); }

    /** @brief Draws @p spec into @p path as a background task (no dialog; automation and tests). */
    void exportPlate(const core::plate::PlateSpec& spec, const QString& path);
    /** @brief Renders the view along the current camera @p widthPx wide into @p path as a task (plateFinished()). */
    void exportViewImage(int widthPx, const QString& path);
    /** @brief Writes the développée on show to @p path (PNG or TIFF) and its sidecar; false with a report. */
    bool exportDeveloppee(const QString& path);

    QAction* plateAction() const { return m_plate; }
    QAction* developpeeAction() const { return m_developpee; }
    QAction* viewImageAction() const { return m_viewImage; }

Q_SIGNALS:
    void reported(const QString& message, bool failed);
    /** @brief An export task ended (written, failed or cancelled). */
    void plateFinished(bool written);

private:
    void choosePlate();
    void chooseDeveloppee();
    void chooseViewImage();
    void updateEnabled();

    widgets::SceneDocument& m_document;
    widgets::DeveloppeeView& m_view;
    QWidget& m_window;
    QAction* m_plate;
    QAction* m_developpee;
    QAction* m_viewImage;
    std::function<std::optional<std::array<double, 4>>()> m_camera;
    std::function<core::scene::FragmentId()> m_fragment;
};

} // namespace stylos::app
