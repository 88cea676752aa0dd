#pragma once
/** @file
 * @brief The annotation in 3D: Tools › Annotate in 3D (lasso) (K in the 3D view) sets the view's LassoTool; a
 *        lasso labels the visible leaves of the selected fragment (else the one under the press) with the
 *        class chosen in the toolbar's class box (the legend's classes of the layer), or erases them with Ctrl
 *        or the Erase toggle: one undo step (SceneDocument::setLabels). View › Shading › Material / Tool marks
 *        choose the layer the Annotation shading shows and the lasso labels (AnnotationSync). The class box shows
 *        the workbench's active class (the Legend dock's) while the layers agree, and choosing in it makes that
 *        class the active one (classChosen()). GUI thread only.
 */
#include "stylos/core/annotation/Legend.h"
#include "stylos/core/view/LassoVisibility.h"

#include <QObject>
#include <QString>

#include <cstdint>
#include <vector>

class QAction;
class QActionGroup;
class QComboBox;
class QMenu;
class QToolBar;
class QWidget;

namespace stylos::widgets {
class SceneDocument;
class ViewportTool;
class ViewportWidget;
} // namespace stylos::widgets

namespace stylos::app {

class AnnotationSync;

class AnnotationActions : public QObject {
    Q_OBJECT

public:
    /** None owned. Without a 3D view (@p viewport and @p sync null) the lasso and the layer choice are disabled. */
    AnnotationActions(widgets::SceneDocument& document, widgets::ViewportWidget* viewport, AnnotationSync* sync,
                      QWidget& window);

    /** @brief Adds the lasso to @p tools, the layer choice to @p shading, the lasso, its class box and Erase to @p toolBar. */
    void populate(QMenu& tools, QMenu* shading, QToolBar& toolBar);
    /** @brief Unchecks the lasso when @p other is checked and @p other when the lasso is (tools that share the view). */
    void setExclusiveWith(QAction* other);
    void retranslateUi();

    QAction* lassoAction() const { return m_lasso; }
    QAction* eraseAction() const { return m_erase; }
    QComboBox* classBox() const { return m_classBox; }
    /** @brief The class id the lasso gives (0 when the layer has no class). */
    std::uint8_t activeClass() const;
    /** @brief Labels @p hits as a lasso released now would (the lasso's handler): one undo step per fragment. */
    void applyLasso(const std::vector<core::view::LassoLeaves>& hits, bool erase);
    /** @brief The workbench's active class (the Legend dock's, the développée's): the box shows it while its layer is
     *         the lasso's, so the 3D lasso and the développée paint with the same class. */
    void showActive(core::annotation::AnnotationLayer layer, std::uint8_t classId);

Q_SIGNALS:
    void reported(const QString& message, bool failed);
    /** @brief The user chose @p classId of @p layer in the class box (the Legend dock and the développée follow). */
    void classChosen(core::annotation::AnnotationLayer layer, std::uint8_t classId);

private:
    void setLassoActive(bool active);
    void fillClasses();

    widgets::SceneDocument& m_document;
    widgets::ViewportWidget* m_viewport;
    AnnotationSync* m_sync;
    core::annotation::AnnotationLayer m_activeLayer = core::annotation::AnnotationLayer::Material; ///< showActive()'s
    std::uint8_t m_activeClass = 0;
    QAction* m_lasso;
    QAction* m_erase;
    QActionGroup* m_layers;
    QComboBox* m_classBox;
    QAction* m_classBoxAction = nullptr;
    const widgets::ViewportTool* m_tool = nullptr; ///< the lasso set on the view (compared, never dereferenced)
};

} // namespace stylos::app
