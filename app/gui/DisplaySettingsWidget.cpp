#include "DisplaySettingsWidget.h"

#include "stylos/widgets/view3d/ViewportWidget.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QSettings>
#include <QSlider>

#include <cmath>

namespace stylos::app {

namespace {
using Shading = widgets::PointRenderer::Shading;
using Mode = widgets::LodScheduler::Mode;

const auto ShadingKey = QStringLiteral("view/shading");
const auto SplatKey = QStringLiteral("view/splatFactor");
const auto BudgetKey = QStringLiteral("view/pointBudgetMillions");
const auto DetailKey = QStringLiteral("view/globalLevel");  ///< −1: view-dependent
constexpr int MaxLevel = 21;                                 ///< the octree's depth limit
} // namespace

DisplaySettingsWidget::DisplaySettingsWidget(widgets::ViewportWidget& viewport, QWidget* parent)
    : QWidget(parent), m_viewport(viewport), m_form(new QFormLayout(this)), m_shading(new QComboBox(this)),
      m_splat(new QDoubleSpinBox(this)), m_budget(new QDoubleSpinBox(this)), m_detail(new QComboBox(this)),
      m_level(new QSlider(Qt::Horizontal, this)), m_levelValue(new QLabel(this))
{
    setObjectName(QStringLiteral("displaySettings"));
    m_shading->addItems({QString(), QString(), QString(), QString()});
    m_splat->setRange(0.25, 4.0);
    m_splat->setSingleStep(0.25);
    m_splat->setDecimals(2);
    m_budget->setRange(0.1, 100.0);
    m_budget->setSingleStep(0.5);
    m_budget->setDecimals(1);
    m_detail->addItems({QString(), QString()});
    m_level->setRange(0, MaxLevel);
    m_levelValue->setMinimumWidth(24);
    auto* levelRow = new QHBoxLayout;
    levelRow->addWidget(m_level, 1);
    levelRow->addWidget(m_levelValue);
    m_form->addRow(QString(), m_shading);
    m_form->addRow(QString(), m_splat);
    m_form->addRow(QString(), m_budget);
    m_form->addRow(QString(), m_detail);
    m_form->addRow(QString(), levelRow);

    const QSettings settings;
    m_updating = true;
    m_shading->setCurrentIndex(std::clamp(settings.value(ShadingKey, 1).toInt(), 0, 3));
    m_splat->setValue(settings.value(SplatKey, 1.0).toDouble());
    m_budget->setValue(settings.value(BudgetKey, 1.0).toDouble());
    const int level = settings.value(DetailKey, -1).toInt();
    m_detail->setCurrentIndex(level < 0 ? 0 : 1);
    m_level->setValue(level < 0 ? 8 : std::min(level, MaxLevel));
    m_updating = false;

    for (QComboBox* box : {m_shading, m_detail})
        connect(box, &QComboBox::currentIndexChanged, this, &DisplaySettingsWidget::apply);
    for (QDoubleSpinBox* spin : {m_splat, m_budget})
        connect(spin, &QDoubleSpinBox::valueChanged, this, &DisplaySettingsWidget::apply);
    connect(m_level, &QSlider::valueChanged, this, &DisplaySettingsWidget::apply);
    apply();
    retranslateUi();
}

void DisplaySettingsWidget::syncFromViewport()
{
    m_updating = true;
    m_shading->setCurrentIndex(static_cast<int>(m_viewport.shading()));
    m_updating = false;
    save();
}

void DisplaySettingsWidget::apply()
{
    m_levelValue->setText(QString::number(m_level->value()));
    m_level->setEnabled(m_detail->currentIndex() == 1);
    if (m_updating) return;
    m_viewport.setShading(static_cast<Shading>(m_shading->currentIndex()));
    m_viewport.setSplatFactor(m_splat->value());
    widgets::LodScheduler& scheduler = m_viewport.scheduler();
    scheduler.setPointBudget(static_cast<std::uint64_t>(std::llround(m_budget->value() * 1e6)));
    widgets::LodScheduler::Settings lod = scheduler.settings();
    lod.mode = m_detail->currentIndex() == 1 ? Mode::GlobalLevel : Mode::Budget;
    lod.globalLevel = m_level->value();
    scheduler.setSettings(lod);
    m_viewport.update();
    save();
}

void DisplaySettingsWidget::save() const
{
    QSettings settings;
    settings.setValue(ShadingKey, m_shading->currentIndex());
    settings.setValue(SplatKey, m_splat->value());
    settings.setValue(BudgetKey, m_budget->value());
    settings.setValue(DetailKey, m_detail->currentIndex() == 1 ? m_level->value() : -1);
}

void DisplaySettingsWidget::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) retranslateUi();
    QWidget::changeEvent(event);
}

void DisplaySettingsWidget::retranslateUi()
{
    m_shading->setItemText(0, tr("Headlight"));
    m_shading->setItemText(1, tr("Skydome"));
    m_shading->setItemText(2, tr("Scan colour"));
    m_shading->setItemText(3, tr("Eye-dome lighting"));
    m_shading->setToolTip(tr("Skydome needs Tools › Compute skydome; without it a fragment is lit by the headlight"));
    m_splat->setSuffix(tr(" ×"));
    m_budget->setSuffix(tr(" M points"));
    m_budget->setToolTip(tr("Points drawn at most; the view refines up to it when the camera stops"));
    m_detail->setItemText(0, tr("View-dependent"));
    m_detail->setItemText(1, tr("Global level"));
    const QStringList labels = {tr("Shading"), tr("Splat size"), tr("Point budget"), tr("Level of detail"),
                                tr("Level")};
    for (int row = 0; row < m_form->rowCount(); ++row)
        if (auto* label = qobject_cast<QLabel*>(m_form->itemAt(row, QFormLayout::LabelRole)
                                                    ? m_form->itemAt(row, QFormLayout::LabelRole)->widget()
                                                    : nullptr))
            label->setText(labels.value(row));
}

} // namespace stylos::app
