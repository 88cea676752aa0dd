#include "LegendDock.h"

#include "stylos/widgets/annotation/LegendWidget.h"

#include <QEvent>

namespace stylos::app {

LegendDock::LegendDock(widgets::SceneDocument& document, widgets::ClassMeasures* measures, QWidget* parent)
    : QDockWidget(parent), m_legend(new widgets::LegendWidget(document, measures))
{
    setObjectName(QStringLiteral("legendDock"));
    setWidget(m_legend);
    retranslateUi();
}

void LegendDock::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) retranslateUi();
    QDockWidget::changeEvent(event);
}

void LegendDock::retranslateUi() { setWindowTitle(tr("Legend")); }

} // namespace stylos::app
