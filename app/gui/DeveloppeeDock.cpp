#include "DeveloppeeDock.h"

#include "stylos/widgets/developpee/DeveloppeePanel.h"

#include <QEvent>
#include <QSettings>

namespace stylos::app {

DeveloppeeDock::DeveloppeeDock(QWidget* parent) : QDockWidget(parent), m_panel(new widgets::DeveloppeePanel)
{
    setObjectName(QStringLiteral("developpeeDock"));
    m_panel->setObjectName(QStringLiteral("developpee"));
    QSettings settings;
    m_panel->setSettings(widgets::DeveloppeeSettings::load(settings));
    setWidget(m_panel);
    retranslateUi();
}

void DeveloppeeDock::saveSettings() const
{
    QSettings settings;
    m_panel->settings().save(settings);
}

void DeveloppeeDock::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) retranslateUi();
    QDockWidget::changeEvent(event);
}

void DeveloppeeDock::retranslateUi() { setWindowTitle(tr("Développée")); }

} // namespace stylos::app
