#include "stylos/widgets/tasks/TaskListWidget.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QVBoxLayout>

namespace stylos::widgets {

TaskListWidget::TaskListWidget(TaskManager& manager, QWidget* parent)
    : QWidget(parent), m_manager(manager), m_rowsLayout(nullptr), m_empty(new QLabel)
{
    setObjectName(QStringLiteral("TaskListWidget"));
    auto* content = new QWidget;
    m_rowsLayout = new QVBoxLayout(content);
    m_rowsLayout->setContentsMargins(4, 4, 4, 4);
    m_empty->setObjectName(QStringLiteral("taskListEmpty"));
    m_empty->setEnabled(false);
    m_rowsLayout->addWidget(m_empty);
    m_rowsLayout->addStretch(1);

    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(content);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(scroll);

    connect(&m_manager, &TaskManager::taskAdded, this, &TaskListWidget::addRow);
    connect(&m_manager, &TaskManager::taskRunning, this, &TaskListWidget::setRunning);
    connect(&m_manager, &TaskManager::taskProgress, this, [this](TaskManager::TaskId id, int value) {
        if (QProgressBar* bar = progressBar(id)) bar->setValue(value);
    });
    connect(&m_manager, &TaskManager::taskFinished, this, &TaskListWidget::removeRow);
    for (TaskManager::TaskId id : m_manager.tasks()) {
        addRow(id, m_manager.label(id));
        if (m_manager.isRunning(id)) setRunning(id);
        m_rows[id].progress->setValue(m_manager.progress(id));
    }
    retranslateUi();
    updateEmptyLine();
}

QProgressBar* TaskListWidget::progressBar(TaskManager::TaskId id) const
{
    const auto it = m_rows.find(id);
    return it == m_rows.end() ? nullptr : it->second.progress;
}

QPushButton* TaskListWidget::cancelButton(TaskManager::TaskId id) const
{
    const auto it = m_rows.find(id);
    return it == m_rows.end() ? nullptr : it->second.cancel;
}

QLabel* TaskListWidget::labelOf(TaskManager::TaskId id) const
{
    const auto it = m_rows.find(id);
    return it == m_rows.end() ? nullptr : it->second.label;
}

void TaskListWidget::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) retranslateUi();
    QWidget::changeEvent(event);
}

void TaskListWidget::retranslateUi()
{
    m_empty->setText(tr("No background tasks"));
    for (auto& entry : m_rows) retranslateRow(entry.second);
}

void TaskListWidget::retranslateRow(Row& row)
{
    row.cancel->setText(tr("Cancel"));
    row.cancel->setToolTip(tr("Stop this task"));
    row.progress->setFormat(row.running ? QStringLiteral("%p%") : tr("Waiting…"));
}

void TaskListWidget::addRow(TaskManager::TaskId id, const QString& label)
{
    Row row;
    row.widget = new QWidget;
    row.widget->setObjectName(QStringLiteral("task%1").arg(id));
    row.label = new QLabel(label, row.widget);
    row.label->setObjectName(QStringLiteral("taskLabel"));
    row.label->setWordWrap(true);
    row.progress = new QProgressBar(row.widget);
    row.progress->setObjectName(QStringLiteral("taskProgressBar"));
    row.progress->setRange(0, ProgressScale);
    row.progress->setValue(0);
    row.cancel = new QPushButton(row.widget);
    row.cancel->setObjectName(QStringLiteral("taskCancelButton"));
    auto* layout = new QVBoxLayout(row.widget);
    layout->setContentsMargins(0, 0, 0, 4);
    layout->addWidget(row.label);
    auto* line = new QHBoxLayout;
    line->addWidget(row.progress, 1);
    line->addWidget(row.cancel);
    layout->addLayout(line);
    connect(row.cancel, &QPushButton::clicked, this, [this, id] {
        if (QPushButton* button = cancelButton(id)) button->setEnabled(false);
        m_manager.cancel(id);
    });
    retranslateRow(row);
    // Before the empty line's stretch, after the rows already there.
    m_rowsLayout->insertWidget(m_rowsLayout->count() - 1, row.widget);
    m_rows[id] = row;
    updateEmptyLine();
}

void TaskListWidget::removeRow(TaskManager::TaskId id)
{
    const auto it = m_rows.find(id);
    if (it == m_rows.end()) return;
    delete it->second.widget;
    m_rows.erase(it);
    updateEmptyLine();
}

void TaskListWidget::setRunning(TaskManager::TaskId id)
{
    const auto it = m_rows.find(id);
    if (it == m_rows.end()) return;
    it->second.running = true;
    retranslateRow(it->second);
}

void TaskListWidget::updateEmptyLine()
{
    m_empty->setVisible(m_rows.empty());
}

} // namespace stylos::widgets
