#include "LogDock.h"

#include <QEvent>
#include <QPlainTextEdit>
#include <QTime>

#include <cstdio>

namespace stylos::app {

LogDock::LogDock(QWidget* parent) : QDockWidget(parent), m_text(new QPlainTextEdit(this))
{
    setObjectName(QStringLiteral("logDock"));
    m_text->setObjectName(QStringLiteral("logText"));
    m_text->setReadOnly(true);
    m_text->setMaximumBlockCount(5000);
    m_text->setLineWrapMode(QPlainTextEdit::WidgetWidth);
    setWidget(m_text);
    retranslateUi();
}

void LogDock::append(Level level, const QString& message)
{
    const QString stamp = QTime::currentTime().toString(QStringLiteral("HH:mm:ss"));
    QString html = QStringLiteral("<span style=\"color:gray\">[%1]</span> ").arg(stamp);
    const QString body = message.toHtmlEscaped().replace(QLatin1Char('\n'), QStringLiteral("<br>"));
    if (level == Level::Error) {
        ++m_errors;
        html += QStringLiteral("<span style=\"color:#b00020\">%1</span>").arg(body);
        std::fprintf(stderr, "stylos: %s\n", qPrintable(message));
    } else {
        html += body;
    }
    m_text->appendHtml(html);
}

QString LogDock::text() const
{
    return m_text->toPlainText();
}

void LogDock::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) retranslateUi();
    QDockWidget::changeEvent(event);
}

void LogDock::retranslateUi()
{
    setWindowTitle(tr("Log"));
}

} // namespace stylos::app
