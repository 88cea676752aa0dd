#include "PropertiesDock.h"

#include "DisplaySettingsWidget.h"
#include "stylos/widgets/document/FragmentPropertiesWidget.h"

#include <QEvent>
#include <QGroupBox>
#include <QScrollArea>
#include <QVBoxLayout>

namespace stylos::app {

PropertiesDock::PropertiesDock(widgets::SceneDocument& document, widgets::ViewportWidget* viewport, QWidget* parent)
    : QDockWidget(parent), m_fragmentBox(new QGroupBox), m_fragment(new widgets::FragmentPropertiesWidget(document))
{
    setObjectName(QStringLiteral("propertiesDock"));
    auto* contents = new QWidget;
    auto* layout = new QVBoxLayout(contents);
    auto* fragmentLayout = new QVBoxLayout(m_fragmentBox);
    fragmentLayout->setContentsMargins(4, 4, 4, 4);
    fragmentLayout->addWidget(m_fragment);
    layout->addWidget(m_fragmentBox);
    if (viewport) {
        m_displayBox = new QGroupBox;
        m_display = new DisplaySettingsWidget(*viewport);
        auto* displayLayout = new QVBoxLayout(m_displayBox);
        displayLayout->setContentsMargins(4, 4, 4, 4);
        displayLayout->addWidget(m_display);
        layout->addWidget(m_displayBox);
    }
    layout->addStretch(1);
    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(contents);
    setWidget(scroll);
    retranslateUi();
}

void PropertiesDock::setFragment(core::scene::FragmentId id)
{
    m_fragment->setFragment(id);
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
    if (m_displayBox) m_displayBox->setTitle(tr("Display"));
}

} // namespace stylos::app
