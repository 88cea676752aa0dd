#include "PropertiesDock.h"

#include "DisplaySettingsWidget.h"
#include "stylos/widgets/docking/ContactReadoutWidget.h"
#include "stylos/widgets/docking/DrumFramePoseWidget.h"
#include "stylos/widgets/document/FragmentPropertiesWidget.h"

#include <QEvent>
#include <QGroupBox>
#include <QScrollArea>
#include <QStyle>
#include <QVBoxLayout>

namespace stylos::app {

PropertiesDock::PropertiesDock(widgets::SceneDocument& document, widgets::ViewportWidget* viewport, QWidget* parent)
    : QDockWidget(parent), m_fragmentBox(new QGroupBox), m_drumFrameBox(new QGroupBox),
      m_drumFrame(new widgets::DrumFramePoseWidget(document)), m_fragment(new widgets::FragmentPropertiesWidget(document))
{
    setObjectName(QStringLiteral("propertiesDock"));
    auto* contents = new QWidget;
    auto* layout = new QVBoxLayout(contents);
    auto* fragmentLayout = new QVBoxLayout(m_fragmentBox);
    fragmentLayout->setContentsMargins(4, 4, 4, 4);
    fragmentLayout->addWidget(m_fragment);
    layout->addWidget(m_fragmentBox);
    m_drumFrameBox->setObjectName(QStringLiteral("drumFrameBox"));
    (new QVBoxLayout(m_drumFrameBox))->addWidget(m_drumFrame);
    layout->addWidget(m_drumFrameBox);
    if (viewport) {
        m_displayBox = new QGroupBox;
        m_display = new DisplaySettingsWidget(*viewport);
        auto* displayLayout = new QVBoxLayout(m_displayBox);
        displayLayout->setContentsMargins(4, 4, 4, 4);
        displayLayout->addWidget(m_display);
        layout->addWidget(m_displayBox);
    }
    layout->addStretch(1);
    m_scroll = new QScrollArea(this);
    m_scroll->setWidgetResizable(true);
    m_scroll->setFrameShape(QFrame::NoFrame);
    m_scroll->setWidget(contents);
    // Never cut sideways: the dock is at least as wide as its contents need (labels wrap above their fields
    // first), in every language; it scrolls only up and down.
    m_scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    contents->installEventFilter(this);
    setWidget(m_scroll);
    retranslateUi();
}

void PropertiesDock::setFragment(core::scene::FragmentId id)
{
    m_fragment->setFragment(id);
    m_drumFrame->setFragment(id);
}

void PropertiesDock::addContactReadout(widgets::ContactMonitor& monitor)
{
    if (m_contact) return;
    m_contactBox = new QGroupBox;
    m_contactBox->setObjectName(QStringLiteral("contactBox"));
    m_contact = new widgets::ContactReadoutWidget(monitor);
    auto* layout = new QVBoxLayout(m_contactBox);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(m_contact);
    auto* contents = static_cast<QVBoxLayout*>(m_fragmentBox->parentWidget()->layout());
    contents->insertWidget(contents->indexOf(m_drumFrameBox) + 1, m_contactBox);
    retranslateUi();
}

void PropertiesDock::showContactReadout()
{
    if (m_contactBox) m_scroll->ensureWidgetVisible(m_contactBox, 0, 0);
}

bool PropertiesDock::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == m_scroll->widget() && event->type() == QEvent::LayoutRequest) {
        const int scrollBar = m_scroll->style()->pixelMetric(QStyle::PM_ScrollBarExtent, nullptr, m_scroll);
        m_scroll->setMinimumWidth(m_scroll->widget()->minimumSizeHint().width() + scrollBar);
    }
    return QDockWidget::eventFilter(watched, event);
}

void PropertiesDock::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) retranslateUi();
    QDockWidget::changeEvent(event);
}

void PropertiesDock::retranslateUi()
{
    setWindowTitle(tr("Properties"));
    m_fragmentBox->setTitle(tr("Fragment"));
    m_drumFrameBox->setTitle(tr("Placement in the drum frame"));
    if (m_displayBox) m_displayBox->setTitle(tr("Display"));
    if (m_contactBox) m_contactBox->setTitle(tr("Contact with the drum"));
}

} // namespace stylos::app
