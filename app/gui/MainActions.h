#pragma once
/** @file
 * @brief The main window's menu actions and their handlers: File › Open scans…, File › Quit,
 *        Help › Open demo, Help › About. MainWindow only places the menus.
 */
#include <QObject>

class QAction;
class QMenu;
class QMenuBar;
class QWidget;

namespace stylos::widgets {
class SceneSession;
}

namespace stylos::app {

class MainActions : public QObject {
    Q_OBJECT

public:
    /** Acts on @p session for @p window (both not owned). */
    MainActions(widgets::SceneSession& session, QWidget& window);

    /** Fills @p menuBar with the File and Help menus. */
    void populate(QMenuBar& menuBar);
    void retranslateUi();

    /** The name filter of the open dialog, listing every supported extension. */
    static QString scanFileFilter();

    QAction* openScansAction() const { return m_openScans; }
    QAction* openDemoAction() const { return m_openDemo; }

private:
    void openScans();
    void about();
    void updateEnabled();

    widgets::SceneSession& m_session;
    QWidget& m_window;
    QMenu* m_fileMenu = nullptr;
    QMenu* m_helpMenu = nullptr;
    QAction* m_openScans;
    QAction* m_quit;
    QAction* m_openDemo;
    QAction* m_about;
};

} // namespace stylos::app
