#include "ToolBarText.h"

#include <QAction>

namespace stylos::app {

QString toolBarToolTip(const QAction& action)
{
    QString text = action.text();
    text.replace(QStringLiteral("&&"), QStringLiteral("\x01"));
    text.remove(QLatin1Char('&'));
    text.replace(QStringLiteral("\x01"), QStringLiteral("&"));
    for (const QString& dots : {QStringLiteral("…"), QStringLiteral("...")})
        if (text.endsWith(dots)) text.chop(dots.size());
    const QString keys = action.shortcut().toString(QKeySequence::NativeText);
    return keys.isEmpty() ? text : QStringLiteral("%1 (%2)").arg(text, keys);
}

void setToolBarText(QAction& action, const QString& shortText)
{
    action.setIconText(shortText);
    action.setToolTip(toolBarToolTip(action));
}

} // namespace stylos::app
