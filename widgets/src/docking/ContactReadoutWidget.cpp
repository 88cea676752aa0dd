#include "stylos/widgets/docking/ContactReadoutWidget.h"

#include "stylos/widgets/docking/ContactMonitor.h"

#include <QEvent>
#include <QFormLayout>
#include <QLabel>
#include <QLocale>
#include <QStringList>

namespace stylos::widgets {

ContactReadoutWidget::ContactReadoutWidget(ContactMonitor& monitor, QWidget* parent)
    : QWidget(parent), m_monitor(monitor), m_form(new QFormLayout(this)), m_status(new QLabel(this)),
      m_members(new QLabel(this))
{
    setObjectName(QStringLiteral("contactReadout"));
    m_form->setContentsMargins(0, 0, 0, 0);
    m_status->setWordWrap(true);
    m_status->setObjectName(QStringLiteral("contactStatus"));
    m_form->addRow(m_status);
    for (std::size_t i = 0; i < Rows; ++i) {
        m_labels[i] = new QLabel(this);
        m_values[i] = new QLabel(this);
        m_values[i]->setTextInteractionFlags(Qt::TextSelectableByMouse);
        m_form->addRow(m_labels[i], m_values[i]);
    }
    m_members->setObjectName(QStringLiteral("contactMembers"));
    m_members->setWordWrap(true);
    m_members->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_form->addRow(m_members);
    connect(&m_monitor, &ContactMonitor::changed, this, &ContactReadoutWidget::refresh);
    retranslateUi();
}

void ContactReadoutWidget::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) retranslateUi();
    QWidget::changeEvent(event);
}

void ContactReadoutWidget::retranslateUi()
{
    m_labels[0]->setText(tr("Largest interpenetration:"));
    m_labels[1]->setText(tr("Median gap:"));
    m_labels[2]->setText(tr("Gap, 90 % of points:"));
    m_labels[3]->setText(tr("Gap, 99 % of points:"));
    m_labels[4]->setText(tr("Within 0.5 mm:"));
    m_labels[5]->setText(tr("Points measured:"));
    for (QLabel* label : m_labels) label->setToolTip(tr("Signed distance of the fragment's outer face to the drum's "
                                                        "flute profile, along its normal; negative: inside the drum"));
    refresh();
}

void ContactReadoutWidget::refresh()
{
    const auto& r = m_monitor.readout();
    const bool ready = m_monitor.state() == ContactMonitor::State::Ready && r.points > 0;
    switch (m_monitor.state()) {
    case ContactMonitor::State::Off:
        m_status->setText(tr("Set a docking drum with guides (Tools › Dock against this drum) and select another fragment."));
        break;
    case ContactMonitor::State::Computing: m_status->setText(tr("Measuring…")); break;
    case ContactMonitor::State::Failed: m_status->setText(m_monitor.message()); break;
    case ContactMonitor::State::Ready:
        m_status->setText(r.points > 0 ? tr("Against the docking drum's flute profile:")
                                       : tr("The fragment does not touch the drum (no point of it within 5 mm of the profile)."));
        break;
    }
    const QLocale locale;
    const auto mm = [&locale](double metres) { return tr("%1 mm").arg(locale.toString(metres * 1e3, 'f', 2)); };
    const QString none = QStringLiteral("—");
    m_values[0]->setText(ready ? mm(r.largestInterpenetration) : none);
    m_values[1]->setText(ready ? mm(r.medianGap) : none);
    m_values[2]->setText(ready ? mm(r.gap90) : none);
    m_values[3]->setText(ready ? mm(r.gap99) : none);
    m_values[4]->setText(ready ? tr("%1 %").arg(locale.toString(r.withinHalfMillimetre * 100.0, 'f', 1)) : none);
    m_values[5]->setText(ready ? locale.toString(qulonglong(r.points)) : none);
    QStringList lines;
    if (m_monitor.state() == ContactMonitor::State::Ready) {
        for (const MemberContact& m : m_monitor.members()) {
            if (!m.error.isEmpty()) lines << tr("Against %1: %2").arg(m.name, m.error);
            else if (m.readout.points == 0) lines << tr("Against %1: no contact (no point within 5 mm)").arg(m.name);
            else
                lines << tr("Against %1: largest interpenetration %2, median gap %3, 90 % gap %4 (%5 points)")
                             .arg(m.name, mm(m.readout.largestInterpenetration), mm(m.readout.medianGap),
                                  mm(m.readout.gap90), locale.toString(qulonglong(m.readout.points)));
        }
    }
    m_members->setText(lines.join(QLatin1Char('\n')));
    m_members->setVisible(!lines.isEmpty());
}

} // namespace stylos::widgets
