#include "StatusMessage.h"

#include <QTimer>

#include <algorithm>

namespace stylos::app {

StatusMessage::StatusMessage(QWidget* parent) : QLabel(parent), m_timer(new QTimer(this))
{
    setObjectName(QStringLiteral("statusMessage"));
    setTextFormat(Qt::PlainText);
    setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    m_timer->setSingleShot(true);
    connect(m_timer, &QTimer::timeout, this, &StatusMessage::clearMessage);
}

void StatusMessage::showMessage(const QString& message, int timeoutMs)
{
    m_message = message;
    refresh();
    if (timeoutMs > 0) m_timer->start(timeoutMs);
    else m_timer->stop();
}

void StatusMessage::clearMessage()
{
    m_timer->stop();
    m_message.clear();
    refresh();
}

void StatusMessage::setTip(const QString& tip)
{
    m_tip = tip;
    refresh();
}

bool StatusMessage::isElided() const { return text() != (m_tip.isEmpty() ? m_message : m_tip).section(QLatin1Char('\n'), 0, 0); }

QSize StatusMessage::minimumSizeHint() const { return {0, QLabel::minimumSizeHint().height()}; }

QSize StatusMessage::sizeHint() const { return {0, QLabel::sizeHint().height()}; }

void StatusMessage::resizeEvent(QResizeEvent* event)
{
    QLabel::resizeEvent(event);
    refresh();
}

void StatusMessage::refresh()
{
    const QString& shown = m_tip.isEmpty() ? m_message : m_tip;
    setToolTip(shown);
    const QString line = shown.section(QLatin1Char('\n'), 0, 0);
    const int width = contentsRect().width() - 2 * margin();
    setText(fontMetrics().elidedText(line, Qt::ElideRight, std::max(0, width)));
}

} // namespace stylos::app
