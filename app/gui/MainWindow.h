#pragma once
/** @file
 * @brief The Stylos main window. It only wires: the scene session, the summary as central widget, the
 *        task strip in the status bar, the menu actions, window settings and error reporting.
 */
#include <QMainWindow>
#include <QStringList>

namespace stylos::widgets {
class SceneSession;
class SceneSummaryWidget;
class TaskStatusWidget;
}

namespace stylos::app {

class MainActions;

class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    /** The demo scene goes to @p demoDirectory, or to the user cache when empty. */
    explicit MainWindow(const QString& demoDirectory = {}, QWidget* parent = nullptr);
    ~MainWindow() override;

    widgets::SceneSession& session() const { return *m_session; }
    widgets::SceneSummaryWidget& summary() const { return *m_summary; }
    widgets::TaskStatusWidget& taskStatus() const { return *m_taskStatus; }
    MainActions& actions() const { return *m_actions; }

    /** When false, errors go to stderr only (automation); by default also to a message box. */
    void setErrorDialogsEnabled(bool enabled) { m_errorDialogs = enabled; }

protected:
    void closeEvent(QCloseEvent* event) override;
    void changeEvent(QEvent* event) override;

private:
    void retranslateUi();
    void reportFinished(const QStringList& errors, bool cancelled);

    widgets::SceneSession* m_session;
    widgets::SceneSummaryWidget* m_summary;
    widgets::TaskStatusWidget* m_taskStatus;
    MainActions* m_actions;
    bool m_errorDialogs = true;
};

} // namespace stylos::app
