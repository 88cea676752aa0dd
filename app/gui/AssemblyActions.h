#pragma once
/** @file
 * @brief The assembly actions, in the Tools menu and the Scene dock's context menu: New assembly from the
 *        selection (Ctrl+G; a selected fragment with an axis guide becomes the assembly's drum), Take out of
 *        the assembly (Ctrl+Shift+G), Remove assembly (its fragments stay where they are), Use as the
 *        assembly's drum, Développée of the assembly. Each edit is one undo step through the SceneDocument; they act on the Scene dock's
 *        selection. GUI thread only.
 */
#include "stylos/core/scene/Assembly.h"

#include <QObject>

class QAction;
class QMenu;
class QWidget;

namespace stylos::widgets {
class SceneDocument;
}

namespace stylos::app {

class SceneDock;

class AssemblyActions : public QObject {
    Q_OBJECT

public:
    /** Neither owned; both must outlive the actions. */
    AssemblyActions(widgets::SceneDocument& document, SceneDock& scene, QWidget& window);

    /** @brief Adds the actions to @p menu (and to the Scene dock's context menu). */
    void populate(QMenu& menu);
    /** @brief Enables what the current selection allows. */
    void updateEnabled();
    void retranslateUi();

    QAction* newAssemblyAction() const { return m_new; }
    QAction* takeOutAction() const { return m_takeOut; }
    QAction* removeAction() const { return m_remove; }
    QAction* useAsDrumAction() const { return m_useAsDrum; }
    QAction* developpeeAction() const { return m_developpee; }

Q_SIGNALS:
    /** @brief A message for the log. */
    void reported(const QString& message, bool failed);
    /** @brief "Développée of the assembly" on assembly @p id (the window runs it: DeveloppeeLink). */
    void developpeeRequested(quint64 id);

private:
    void newAssembly();
    void takeOut();
    void removeAssembly();
    void useAsDrum();
    /** The current row's assembly, or the current fragment's. */
    core::scene::AssemblyId currentAssembly() const;

    widgets::SceneDocument& m_document;
    SceneDock& m_scene;
    QAction* m_new;
    QAction* m_takeOut;
    QAction* m_remove;
    QAction* m_useAsDrum;
    QAction* m_developpee;
};

} // namespace stylos::app
