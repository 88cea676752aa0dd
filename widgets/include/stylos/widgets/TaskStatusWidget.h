#pragma once
/** @file
 * @brief A status-bar strip for the running background task: its label, a progress bar and a Cancel
 *        button. Hidden while the runner is idle.
 */
#include <QWidget>

class QLabel;
class QProgressBar;
class QPushButton;

namespace stylos::widgets {

class TaskRunner;

class TaskStatusWidget : public QWidget {
    Q_OBJECT

public:
    /** Observes and cancels @p runner (not owned; it must outlive the widget). */
    explicit TaskStatusWidget(TaskRunner& runner, QWidget* parent = nullptr);

    QPushButton* cancelButton() const { return m_cancel; }
    QProgressBar* progressBar() const { return m_progress; }

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslateUi();
    void onStarted(const QString& label);
    void onFinished();

    TaskRunner& m_runner;
    QLabel* m_label;
    QProgressBar* m_progress;
    QPushButton* m_cancel;
};

} // namespace stylos::widgets
