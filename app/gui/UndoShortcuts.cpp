#include "UndoShortcuts.h"

#include <QAbstractSpinBox>
#include <QAction>
#include <QApplication>
#include <QDialog>
#include <QKeyEvent>
#include <QLineEdit>
#include <QTextEdit>

namespace stylos::app {

UndoShortcuts::UndoShortcuts(QWidget& window, QAction& undo, QAction& redo)
    : QObject(&window), m_window(window), m_undo(undo), m_redo(redo)
{
    qApp->installEventFilter(this);
}

UndoShortcuts::~UndoShortcuts()
{
    qApp->removeEventFilter(this);
}

bool UndoShortcuts::isWindowField(const QWidget* widget) const
{
    if (!qobject_cast<const QLineEdit*>(widget) && !qobject_cast<const QAbstractSpinBox*>(widget) &&
        !qobject_cast<const QTextEdit*>(widget) && !(widget && qobject_cast<const QAbstractSpinBox*>(widget->parentWidget())))
        return false;
    // Up the parents, through floating docks (windows of their own) but not through a dialog.
    for (const QWidget* w = widget; w; w = w->parentWidget()) {
        if (w == &m_window) return true;
        if (qobject_cast<const QDialog*>(w)) return false;
    }
    return false;
}

bool UndoShortcuts::eventFilter(QObject* watched, QEvent* event)
{
    // A field claims the keys it edits with by accepting ShortcutOverride: Undo and Redo are not its to
    // claim here. Ignored, they reach the shortcut map and trigger the window's actions.
    if (event->type() != QEvent::ShortcutOverride && event->type() != QEvent::KeyPress) return false;
    auto* key = static_cast<QKeyEvent*>(event);
    const bool undo = key->matches(QKeySequence::Undo), redo = key->matches(QKeySequence::Redo);
    if (!undo && !redo) return false;
    auto* widget = qobject_cast<QWidget*>(watched);
    if (!isWindowField(widget)) return false;
    if (event->type() == QEvent::ShortcutOverride) {
        event->ignore();
        return true;
    }
    // A key press that came here all the same (no shortcut took it): act on it, never the field's undo.
    QAction& action = undo ? m_undo : m_redo;
    if (action.isEnabled()) action.trigger();
    return true;
}

} // namespace stylos::app
