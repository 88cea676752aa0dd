#include "TasksDock.h"

#include "stylos/widgets/tasks/TaskListWidget.h"

#include <QEvent>

namespace stylos::app {

TasksDock::TasksDock(widgets::TaskManager& tasks, QWidget* parent) : QDockWidget(parent)
{
    setObjectName(QStringLiteral("tasksDock"));
    setWidget(new widgets::TaskListWidget(tasks));
    retranslateUi();
}

void TasksDock::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) retranslateUi();
    QDockWidget::changeEvent(event);
}

void TasksDock::retranslateUi() { setWindowTitle(tr("Tasks")); }

} // namespace stylos::app
