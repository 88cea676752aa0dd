#pragma once
/** @file
 * @brief The contents of the Tasks dock: one row per background task of a TaskManager — its label, a
 *        progress bar ("Waiting…" until a worker picks it up) and a Cancel button — and a line saying so
 *        when there is none. Rows come and go with the tasks. GUI thread only.
 */
#include "stylos/widgets/tasks/TaskManager.h"

#include <QWidget>

#include <map>

class QLabel;
class QProgressBar;
class QPushButton;
class QVBoxLayout;

namespace stylos::widgets {

class TaskListWidget : public QWidget {
    Q_OBJECT

public:
    /** Observes and cancels the tasks of @p manager (not owned; it must outlive the widget). */
    explicit TaskListWidget(TaskManager& manager, QWidget* parent = nullptr);

    /** @brief Rows shown (one per unfinished task). */
    int rowCount() const { return static_cast<int>(m_rows.size()); }
    /** @brief The row widgets of task @p id (nullptr when it has none): for tests. */
    QProgressBar* progressBar(TaskManager::TaskId id) const;
    QPushButton* cancelButton(TaskManager::TaskId id) const;
    QLabel* labelOf(TaskManager::TaskId id) const;

protected:
    void changeEvent(QEvent* event) override;

private:
    struct Row {
        QWidget* widget = nullptr;
        QLabel* label = nullptr;
        QProgressBar* progress = nullptr;
        QPushButton* cancel = nullptr;
        bool running = false;
    };

    void retranslateUi();
    void retranslateRow(Row& row);
    void addRow(TaskManager::TaskId id, const QString& label);
    void removeRow(TaskManager::TaskId id);
    void setRunning(TaskManager::TaskId id);
    void updateEmptyLine();

    TaskManager& m_manager;
    QVBoxLayout* m_rowsLayout;
    QLabel* m_empty;
    std::map<TaskManager::TaskId, Row> m_rows;
};

} // namespace stylos::widgets
