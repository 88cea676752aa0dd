#pragma once
/** @file
 * @brief The Scene dock: the document's assemblies and fragments as a tree (SceneTreeModel: name,
 *        visibility, colour, members under their assembly, guides below each fragment), several selectable
 *        at once. Renaming and the visibility check go through the undo stack (the model does it); fragments
 *        are dragged onto an assembly to move them in, onto the empty space to take them out (one undo step
 *        each drop); Delete removes the selected fragments. A reset of the tree (an assembly made or
 *        removed) keeps the selection. GUI thread only.
 */
#include "stylos/core/scene/Assembly.h"
#include "stylos/core/scene/Fragment.h"

#include <QDockWidget>
#include <QList>

class QTreeView;

namespace stylos::widgets {
class SceneDocument;
class SceneTreeModel;
} // namespace stylos::widgets

namespace stylos::app {

class SceneDock : public QDockWidget {
    Q_OBJECT

public:
    SceneDock(widgets::SceneDocument& document, QWidget* parent = nullptr);

    QTreeView* view() const { return m_view; }
    widgets::SceneTreeModel* model() const { return m_model; }

    /** @brief The fragments of the selected rows (a guide row counts for its fragment), in scene order. */
    QList<core::scene::FragmentId> selectedFragments() const;
    /** @brief The fragment of the current row; NoFragment when none. */
    core::scene::FragmentId currentFragment() const;
    /** @brief Makes fragment @p id the current and only selected row. */
    void selectFragment(core::scene::FragmentId id);
    /** @brief The assembly of the current row when it is an assembly row; NoAssembly otherwise. */
    core::scene::AssemblyId currentAssembly() const;

Q_SIGNALS:
    /** @brief The selection or the current fragment changed. */
    void selectionChanged();

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslateUi();

    widgets::SceneDocument& m_document;
    widgets::SceneTreeModel* m_model;
    QTreeView* m_view;
    QList<core::scene::FragmentId> m_keptSelection;     ///< across a reset of the tree
    core::scene::AssemblyId m_keptAssembly = core::scene::NoAssembly;
};

} // namespace stylos::app
