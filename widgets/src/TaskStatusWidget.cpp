#include "stylos/widgets/TaskStatusWidget.h"

#include "stylos/widgets/TaskRunner.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>

namespace stylos::widgets {

TaskStatusWidget::TaskStatusWidget(TaskRunner& runner, QWidget* parent)
    : QWidget(parent), m_runner(runner), m_label(new QLabel(this)), m_progress(new QProgressBar(this)),
      m_cancel(new QPushButton(this))
{
    setObjectName(QStringLiteral("TaskStatusWidget"));
    m_progress->setObjectName(QStringLiteral("taskProgressBar"));
    m_cancel->setObjectName(QStringLiteral("taskCancelButton"));
    m_progress->setRange(0, ProgressScale);
    m_progress->setMaximumWidth(240);
    m_progress->setTextVisible(true);

    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_label);
    layout->addWidget(m_progress);
    layout->addWidget(m_cancel);

    connect(&m_runner, &TaskRunner::started, this, &TaskStatusWidget::onStarted);
    connect(&m_runner, &TaskRunner::progressChanged, m_progress, &QProgressBar::setValue);
    connect(&m_runner, &TaskRunner::finished, this, &TaskStatusWidget::onFinished);
    connect(m_cancel, &QPushButton::clicked, this, [this] {
        m_cancel->setEnabled(false);
        m_runner.cancel();
    });
    retranslateUi();
    setVisible(m_runner.isBusy());
}

void TaskStatusWidget::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) retranslateUi();
    QWidget::changeEvent(event);
}

void TaskStatusWidget::retranslateUi()
{
    m_cancel->setText(tr("Cancel"));
    m_cancel->setToolTip(tr("Stop the running task"));
}

void TaskStatusWidget::onStarted(const QString& label)
{
    m_label->setText(label);
    m_progress->setValue(0);
    m_cancel->setEnabled(true);
    show();
}

void TaskStatusWidget::onFinished()
{
    // The runner may already be running the next step of a chain (demo generation, then loading).
    if (!m_runner.isBusy()) hide();
}

} // namespace stylos::widgets
