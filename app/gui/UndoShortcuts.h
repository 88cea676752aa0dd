#pragma once
/** @file
 * @brief Undo and redo from anywhere in the main window: Ctrl+Z / Ctrl+Shift+Z (the platform's Undo and Redo
 *        keys) reach the document's undo and redo actions even while a text field or a number field (spin box)
 *        of the window or of its docks has the focus. Those fields would otherwise take the keys for their own
 *        text undo, and the document's step would not be undone. Dialogs keep their own. GUI thread only.
 */
#include <QObject>

class QAction;
class QWidget;

namespace stylos::app {

class UndoShortcuts : public QObject {
    Q_OBJECT

public:
    /** Watches the key presses sent to the fields of @p window (and its floating docks); @p undo and
     *  @p redo (not owned) are triggered by their keys. Installs itself on the application. */
    UndoShortcuts(QWidget& window, QAction& undo, QAction& redo);
    ~UndoShortcuts() override;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    /** @brief Whether @p widget is a text or number field of the window (not of a dialog over it). */
    bool isWindowField(const QWidget* widget) const;

    QWidget& m_window;
    QAction& m_undo;
    QAction& m_redo;
};

} // namespace stylos::app
