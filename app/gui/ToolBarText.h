#pragma once
/** @file
 * @brief The short label a toolbar button shows for an action, with the action's full text and shortcut as its
 *        tooltip: the menus keep "Compute &skydome" or "Undo Move Fragment A", the toolbar "Skydome" or "Undo",
 *        so the main toolbar fits the window in every language. Call again after each change of text.
 */
#include <QString>

class QAction;

namespace stylos::app {

/** @brief Sets @p action's icon text to @p shortText and its tooltip to its text (mnemonics and "…" removed)
 *         followed by its shortcut in the native format, e.g. "Open project (Ctrl+O)". */
void setToolBarText(QAction& action, const QString& shortText);

/** @brief The tooltip setToolBarText() gives: @p text without '&' and a trailing "…" or "...", then " (shortcut)". */
QString toolBarToolTip(const QAction& action);

} // namespace stylos::app
