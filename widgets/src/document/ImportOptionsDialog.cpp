#include "stylos/widgets/document/ImportOptionsDialog.h"

#include "stylos/widgets/util/NumberSpinBox.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QSettings>

#include <cmath>

namespace stylos::widgets {

namespace {

using core::io::LengthUnit;
using core::io::UpAxis;

constexpr UpAxis Axes[] = {UpAxis::PosZ, UpAxis::NegZ, UpAxis::PosY, UpAxis::NegY, UpAxis::PosX, UpAxis::NegX};
constexpr LengthUnit Units[] = {LengthUnit::Metre, LengthUnit::Centimetre, LengthUnit::Millimetre};

const auto UpKey = QStringLiteral("import/up");
const auto UnitKey = QStringLiteral("import/unit");
const auto OffsetKey = QStringLiteral("import/offset");

} // namespace

ImportOptionsDialog::ImportOptionsDialog(const core::io::ImportFrame& frame, QWidget* parent)
    : QDialog(parent), m_frame(frame), m_note(new QLabel(this)), m_upLabel(new QLabel(this)),
      m_unitLabel(new QLabel(this)), m_offsetLabel(new QLabel(this)), m_up(new QComboBox(this)),
      m_unit(new QComboBox(this)),
      m_buttons(new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this))
{
    setObjectName(QStringLiteral("importOptionsDialog"));
    m_up->setObjectName(QStringLiteral("importUpAxis"));
    m_unit->setObjectName(QStringLiteral("importUnit"));
    for (const UpAxis axis : Axes) m_up->addItem(QString(), QString::fromLatin1(core::io::upAxisName(axis)));
    for (const LengthUnit unit : Units) m_unit->addItem(QString(), QString::fromLatin1(core::io::lengthUnitName(unit)));
    m_note->setWordWrap(true);
    m_upLabel->setBuddy(m_up);
    m_unitLabel->setBuddy(m_unit);
    auto* form = new QFormLayout(this);
    form->addRow(m_note);
    form->addRow(m_upLabel, m_up);
    form->addRow(m_unitLabel, m_unit);
    // Site coordinates (e.g. UTM, hundreds of kilometres): subtracted before anything else, in the scans' unit.
    auto* offsetRow = new QHBoxLayout;
    const char* offsetNames[] = {"importOffsetX", "importOffsetY", "importOffsetZ"};
    for (int axis = 0; axis < 3; ++axis) {
        m_offset[axis] = new NumberSpinBox(this);
        m_offset[axis]->setObjectName(QString::fromLatin1(offsetNames[axis]));
        m_offset[axis]->setRange(-1e9, 1e9);
        m_offset[axis]->setDecimals(3);
        m_offset[axis]->setMinimumWidth(m_offset[axis]->fontMetrics().horizontalAdvance(QStringLiteral("-0000000.000")) + 30);
        offsetRow->addWidget(m_offset[axis]);
    }
    m_offsetLabel->setBuddy(m_offset[0]);
    form->addRow(m_offsetLabel, offsetRow);
    form->addRow(m_buttons);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    retranslateUi();
    setFrame(frame);
}

core::io::ImportFrame ImportOptionsDialog::frame() const
{
    core::io::ImportFrame frame = m_frame;
    frame.up = Axes[std::size_t(std::max(0, m_up->currentIndex()))];
    frame.unit = Units[std::size_t(std::max(0, m_unit->currentIndex()))];
    for (int axis = 0; axis < 3; ++axis) frame.offset[std::size_t(axis)] = m_offset[axis]->value();
    return frame;
}

void ImportOptionsDialog::setFrame(const core::io::ImportFrame& frame)
{
    m_frame = frame;
    m_up->setCurrentIndex(m_up->findData(QString::fromLatin1(core::io::upAxisName(frame.up))));
    m_unit->setCurrentIndex(m_unit->findData(QString::fromLatin1(core::io::lengthUnitName(frame.unit))));
    for (int axis = 0; axis < 3; ++axis) m_offset[axis]->setValue(frame.offset[std::size_t(axis)]);
}

void ImportOptionsDialog::save(QSettings& settings, const core::io::ImportFrame& frame)
{
    settings.setValue(UpKey, QString::fromLatin1(core::io::upAxisName(frame.up)));
    settings.setValue(UnitKey, QString::fromLatin1(core::io::lengthUnitName(frame.unit)));
    settings.setValue(OffsetKey, QVariantList{frame.offset[0], frame.offset[1], frame.offset[2]});
}

core::io::ImportFrame ImportOptionsDialog::load(QSettings& settings)
{
    core::io::ImportFrame frame;
    if (const auto up = core::io::upAxisFromName(settings.value(UpKey).toString().toStdString())) frame.up = *up;
    if (const auto unit = core::io::lengthUnitFromName(settings.value(UnitKey).toString().toStdString()))
        frame.unit = *unit;
    const QVariantList offset = settings.value(OffsetKey).toList();
    if (offset.size() == 3) {
        bool ok[3] = {};
        const double values[3] = {offset[0].toDouble(&ok[0]), offset[1].toDouble(&ok[1]), offset[2].toDouble(&ok[2])};
        if (ok[0] && ok[1] && ok[2] && std::isfinite(values[0]) && std::isfinite(values[1]) && std::isfinite(values[2]))
            frame.offset = {values[0], values[1], values[2]};
    }
    return frame;
}

void ImportOptionsDialog::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) retranslateUi();
    QDialog::changeEvent(event);
}

void ImportOptionsDialog::retranslateUi()
{
    setWindowTitle(tr("Import options"));
    m_note->setText(tr("Stylos works with Z up and in metres. Say how the scans are stored: their points are "
                       "turned and scaled once, as their octrees are built, and the project remembers it."));
    m_upLabel->setText(tr("&Up axis of the scans:"));
    m_unitLabel->setText(tr("&Unit of the scans:"));
    m_offsetLabel->setText(tr("&Offset (site coordinates, in that unit):"));
    const QString offsetTips[] = {tr("Subtracted from every x, before the turn and the scaling"),
                                  tr("Subtracted from every y, before the turn and the scaling"),
                                  tr("Subtracted from every z, before the turn and the scaling")};
    for (int axis = 0; axis < 3; ++axis) m_offset[axis]->setToolTip(offsetTips[axis]);
    const QString upTexts[] = {tr("+Z (already upright)"), tr("−Z (upside down)"), tr("+Y (Y up)"),
                               tr("−Y (Y down)"),          tr("+X (X up)"),        tr("−X (X down)")};
    for (int i = 0; i < m_up->count(); ++i) m_up->setItemText(i, upTexts[i]);
    const QString unitTexts[] = {tr("metres (m)"), tr("centimetres (cm)"), tr("millimetres (mm)")};
    for (int i = 0; i < m_unit->count(); ++i) m_unit->setItemText(i, unitTexts[i]);
}

} // namespace stylos::widgets
