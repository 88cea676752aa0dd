#include "ToolBarRows.h"

#include <QEvent>
#include <QMainWindow>
#include <QTimer>
#include <QToolBar>

namespace stylos::app {

ToolBarRows::ToolBarRows(QMainWindow& window, QToolBar& first, QToolBar& second)
    : QObject(&window), m_window(window), m_first(first), m_second(second)
{
    for (QObject* watched : {static_cast<QObject*>(&window), static_cast<QObject*>(&first), static_cast<QObject*>(&second)})
        watched->installEventFilter(this);
    schedule();
}

bool ToolBarRows::isSplit() const { return m_window.toolBarBreak(&m_second); }

void ToolBarRows::update()
{
    m_scheduled = false;
    if (m_window.toolBarArea(&m_first) != Qt::TopToolBarArea || m_window.toolBarArea(&m_second) != Qt::TopToolBarArea)
        return; // the user moved one: their layout
    // Both rows' full widths (every button at its size hint) against the window's: the main window's layout
    // gives a row no more than the window has, and a toolbar squeezed below its hint hides buttons.
    const int needed = (m_first.isVisible() ? m_first.sizeHint().width() : 0) +
                       (m_second.isVisible() ? m_second.sizeHint().width() : 0) + 8;
    const bool split = needed > m_window.width();
    if (split == isSplit()) return;
    if (split) m_window.insertToolBarBreak(&m_second);
    else m_window.removeToolBarBreak(&m_second);
}

void ToolBarRows::schedule()
{
    if (m_scheduled) return;
    m_scheduled = true;
    QTimer::singleShot(0, this, &ToolBarRows::update);
}

bool ToolBarRows::eventFilter(QObject* watched, QEvent* event)
{
    switch (event->type()) {
    case QEvent::Resize:
        if (watched == &m_window) schedule();
        break;
    case QEvent::LayoutRequest:
    case QEvent::LanguageChange:
    case QEvent::Show:
    case QEvent::Hide:
        schedule();
        break;
    default:
        break;
    }
    return QObject::eventFilter(watched, event);
}

} // namespace stylos::app
