#pragma once
/** @file
 * @brief The Tasks dock: every background job of the TaskManager with its progress bar and Cancel
 *        (widgets::TaskListWidget). GUI thread only.
 */
#include <QDockWidget>

namespace stylos::widgets {
class TaskManager;
} // namespace stylos::widgets

namespace stylos::app {

class TasksDock : public QDockWidget {
    Q_OBJECT

public:
    /** @p tasks is not owned and must outlive the dock. */
    explicit TasksDock(widgets::TaskManager& tasks, QWidget* parent = nullptr);

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslateUi();
};

} // namespace stylos::app
