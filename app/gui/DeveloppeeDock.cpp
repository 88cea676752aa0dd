#include "DeveloppeeDock.h"

#include "stylos/widgets/developpee/DeveloppeePanel.h"
#include "stylos/widgets/developpee/DeveloppeeView.h"

#include <QEvent>
#include <QSettings>

namespace stylos::app {

namespace {
constexpr const char* BrushSizeKey = "paint/brushSize"; ///< metres
} // namespace

DeveloppeeDock::DeveloppeeDock(QWidget* parent) : QDockWidget(parent), m_panel(new widgets::DeveloppeePanel)
{
    setObjectName(QStringLiteral("developpeeDock"));
    m_panel->setObjectName(QStringLiteral("developpee"));
    QSettings settings;
    m_panel->setSettings(widgets::DeveloppeeSettings::load(settings));
    // The brush as the user left it (before the paint bar is made: it reads the view's size).
    bool ok = false;
    const double brush = settings.value(QLatin1String(BrushSizeKey)).toDouble(&ok);
    if (ok && brush > 0.0 && brush <= 1.0) m_panel->view()->setBrushSize(brush);
    setWidget(m_panel);
    retranslateUi();
}

void DeveloppeeDock::saveSettings() const
{
    QSettings settings;
    m_panel->settings().save(settings);
    settings.setValue(QLatin1String(BrushSizeKey), m_panel->view()->brushSize());
}

void DeveloppeeDock::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) retranslateUi();
    QDockWidget::changeEvent(event);
}

void DeveloppeeDock::retranslateUi() { setWindowTitle(tr("Développée")); }

} // namespace stylos::app
