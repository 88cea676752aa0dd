#include "StatusReadout.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>

#include <cmath>

namespace stylos::app {

StatusReadout::StatusReadout(QWidget* parent) : QWidget(parent), m_cursor(new QLabel(this)), m_frame(new QLabel(this))
{
    setObjectName(QStringLiteral("statusReadout"));
    m_cursor->setObjectName(QStringLiteral("cursorLabel"));
    m_frame->setObjectName(QStringLiteral("frameLabel"));
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(16);
    layout->addWidget(m_cursor);
    layout->addWidget(m_frame);
    m_cursor->setMinimumWidth(m_cursor->fontMetrics().horizontalAdvance(formatPoint({-100.0, -100.0, -100.0})));
}

void StatusReadout::setCursor3d(const Eigen::Vector3d& point) { m_cursor->setText(formatPoint(point)); }

void StatusReadout::setFrameTime(double ms)
{
    m_ms = ms;
    refreshFrame();
}

void StatusReadout::setPointsDrawn(quint64 points)
{
    m_points = points;
    refreshFrame();
}

QString StatusReadout::cursorText() const { return m_cursor->text(); }
QString StatusReadout::frameText() const { return m_frame->text(); }

QString StatusReadout::formatPoint(const Eigen::Vector3d& point)
{
    const QLocale locale;
    const auto number = [&locale](double v) { return locale.toString(v, 'f', 3); };
    return tr("x %1  y %2  z %3 m").arg(number(point.x()), number(point.y()), number(point.z()));
}

QString StatusReadout::formatFrame(double ms, quint64 points)
{
    const QLocale locale;
    const double fps = ms > 0 ? 1000.0 / ms : 0.0;
    return tr("%1 fps · %2 ms · %3 M points")
        .arg(locale.toString(std::round(fps), 'f', 0), locale.toString(ms, 'f', 1),
             locale.toString(static_cast<double>(points) / 1e6, 'f', 2));
}

void StatusReadout::refreshFrame()
{
    if (m_ms > 0) m_frame->setText(formatFrame(m_ms, m_points));
}

void StatusReadout::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) refreshFrame();
    QWidget::changeEvent(event);
}

} // namespace stylos::app
