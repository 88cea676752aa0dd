#pragma once
/** @file
 * @brief The Edit, View, Tools and Help menus and the toolbar: undo/redo (the document's stack), remove,
 *        fit, standard views, projection and shading of the 3D view, Compute skydome and Développée,
 *        the demo, the language and About. Actions that need the window's parts (the selection, the demo)
 *        go out as signals; MainWindow connects them. GUI thread only.
 */
#include <QObject>

#include <array>

class QAction;
class QActionGroup;
class QMenu;
class QMenuBar;
class QToolBar;
class QWidget;

namespace stylos::widgets {
class SceneDocument;
class ViewportWidget;
} // namespace stylos::widgets

namespace stylos::app {

class Translations;

class MainActions : public QObject {
    Q_OBJECT

public:
    /** None owned; @p viewport may be null (no OpenGL: the View actions are disabled). */
    MainActions(widgets::SceneDocument& document, widgets::ViewportWidget* viewport, Translations& translations,
                QWidget& window);

    /** @brief Adds Edit, View, Tools and Help after the menus already in @p menuBar; returns the View menu. */
    QMenu* populate(QMenuBar& menuBar);
    /** @brief Adds Undo and Redo to @p edit (after the File actions the window put there), the view's and the
     *         tools' actions to @p view. */
    void populateToolBars(QToolBar& edit, QToolBar& view);
    void retranslateUi();

    /** @brief Enables what needs a selection. */
    void setSelectionCount(int count);
    /** @brief Checks the shading action matching the view's shading. */
    void syncShading();

    QAction* undoAction() const { return m_undo; }
    QAction* redoAction() const { return m_redo; }
    QAction* removeAction() const { return m_remove; }
    QAction* skydomeAction() const { return m_skydome; }
    QAction* developpeeAction() const { return m_developpee; }
    QAction* openDemoAction() const { return m_openDemo; }
    QAction* orthographicAction() const { return m_orthographic; }
    /** @brief The Tools menu (after populate()), for the other handlers' actions. */
    QMenu* toolsMenu() const { return m_tools; }
    /** @brief View › Shading (after populate()), for the annotation layer choice. */
    QMenu* shadingMenu() const { return m_shadingMenu; }

Q_SIGNALS:
    void removeRequested();
    void skydomeRequested();
    void developpeeRequested();
    void openDemoRequested();
    /** @brief The shading was changed from the menu. */
    void shadingChanged();

private:
    void about();
    void addViewActions();

    widgets::SceneDocument& m_document;
    widgets::ViewportWidget* m_viewport;
    Translations& m_translations;
    QWidget& m_window;
    QMenu* m_edit = nullptr;
    QMenu* m_view = nullptr;
    QMenu* m_standard = nullptr;
    QMenu* m_shadingMenu = nullptr;
    QMenu* m_tools = nullptr;
    QMenu* m_help = nullptr;
    QMenu* m_language = nullptr;
    QAction* m_undo;
    QAction* m_redo;
    QAction* m_remove;
    QAction* m_fitScene;
    QAction* m_fitSelection;
    std::array<QAction*, 7> m_views{};
    QAction* m_orthographic;
    QActionGroup* m_shading;
    QAction* m_skydome;
    QAction* m_developpee;
    QAction* m_openDemo;
    QActionGroup* m_languages;
    QAction* m_about;
};

} // namespace stylos::app
