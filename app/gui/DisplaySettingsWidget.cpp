#include "DisplaySettingsWidget.h"

#include "stylos/widgets/util/WheelGuard.h"
#include "stylos/widgets/util/NumberSpinBox.h"
#include "stylos/widgets/view3d/ViewportWidget.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QSettings>
#include <QSlider>

#include <array>
#include <cmath>

namespace stylos::app {

namespace {
using Shading = widgets::PointRenderer::Shading;
using Mode = widgets::LodScheduler::Mode;

const auto ShadingKey = QStringLiteral("view/shading");
const auto SplatKey = QStringLiteral("view/splatFactor");
const auto BudgetKey = QStringLiteral("view/pointBudgetMillions");
const auto GapFillKey = QStringLiteral("view/gapFill");
const auto DetailKey = QStringLiteral("view/globalLevel");  ///< −1: view-dependent
constexpr int MaxLevel = 21;                                 ///< the octree's depth limit
} // namespace

DisplaySettingsWidget::DisplaySettingsWidget(widgets::ViewportWidget& viewport, QWidget* parent)
    : QWidget(parent), m_viewport(viewport), m_form(new QFormLayout(this)), m_shading(new QComboBox(this)),
      m_layer(new QComboBox(this)),
      m_splat(new widgets::NumberSpinBox(this)), m_budget(new widgets::NumberSpinBox(this)), m_detail(new QComboBox(this)),
      m_level(new QSlider(Qt::Horizontal, this)), m_levelValue(new QLabel(this)), m_gapFill(new QCheckBox(this))
{
    setObjectName(QStringLiteral("displaySettings"));
    for (QWidget* field : std::initializer_list<QWidget*>{m_shading, m_layer, m_splat, m_budget, m_detail, m_level})
        widgets::guardWheel(field); // the wheel scrolls the Properties dock
    m_shading->addItems({QString(), QString(), QString(), QString(), QString()});
    m_layer->setObjectName(QStringLiteral("annotationLayerBox"));
    m_layer->addItems({QString(), QString()});
    m_splat->setRange(0.25, 4.0);
    m_splat->setSingleStep(0.25);
    m_splat->setDecimals(2);
    m_budget->setRange(0.1, 100.0);
    m_budget->setSingleStep(0.5);
    m_budget->setDecimals(1);
    m_detail->addItems({QString(), QString()});
    m_level->setRange(0, MaxLevel);
    // Wide enough for the largest level, whatever the font.
    m_levelValue->setMinimumWidth(m_levelValue->fontMetrics().horizontalAdvance(QString::number(MaxLevel)));
    m_levelValue->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    auto* levelRow = new QHBoxLayout;
    levelRow->addWidget(m_level, 1);
    levelRow->addWidget(m_levelValue);
    // Labels beside their fields while the dock is wide enough, above them when it is not (long French
    // and Greek labels): the fields keep their full width either way.
    m_form->setRowWrapPolicy(QFormLayout::WrapLongRows);
    m_form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    const std::array<QWidget*, 7> fields = {m_shading, m_layer, m_splat, m_budget, m_detail, m_level, m_gapFill};
    for (std::size_t row = 0; row < fields.size(); ++row) {
        auto* label = new QLabel(this);
        label->setBuddy(fields[row]);
        m_labels[row] = label;
        if (fields[row] == m_level)
            m_form->addRow(label, levelRow);
        else
            m_form->addRow(label, fields[row]);
    }
    m_shading->setObjectName(QStringLiteral("displayShading"));
    m_splat->setObjectName(QStringLiteral("displaySplat"));
    m_budget->setObjectName(QStringLiteral("displayBudget"));
    m_detail->setObjectName(QStringLiteral("displayDetail"));
    m_level->setObjectName(QStringLiteral("displayLevel"));
    m_gapFill->setObjectName(QStringLiteral("displayGapFill"));

    const QSettings settings;
    m_updating = true;
    m_shading->setCurrentIndex(std::clamp(settings.value(ShadingKey, 1).toInt(), 0, 4));
    m_splat->setValue(settings.value(SplatKey, m_viewport.splatFactor()).toDouble()); // the renderer's default
    m_budget->setValue(settings.value(BudgetKey, 1.0).toDouble());
    const int level = settings.value(DetailKey, -1).toInt();
    m_detail->setCurrentIndex(level < 0 ? 0 : 1);
    m_level->setValue(level < 0 ? 8 : std::min(level, MaxLevel));
    m_gapFill->setChecked(settings.value(GapFillKey, true).toBool());
    m_updating = false;

    for (QComboBox* box : {m_shading, m_detail})
        connect(box, &QComboBox::currentIndexChanged, this, &DisplaySettingsWidget::apply);
    for (QDoubleSpinBox* spin : {m_splat, m_budget})
        connect(spin, &QDoubleSpinBox::valueChanged, this, &DisplaySettingsWidget::apply);
    connect(m_level, &QSlider::valueChanged, this, &DisplaySettingsWidget::apply);
    connect(m_gapFill, &QCheckBox::toggled, this, &DisplaySettingsWidget::apply);
    connect(m_layer, &QComboBox::currentIndexChanged, this, [this](int index) {
        if (!m_updating) Q_EMIT annotationLayerChanged(index);
    });
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

void DisplaySettingsWidget::setAnnotationLayer(int layer)
{
    m_updating = true;
    m_layer->setCurrentIndex(layer);
    m_updating = false;
}

void DisplaySettingsWidget::apply()
{
    m_levelValue->setText(QString::number(m_level->value()));
    m_level->setEnabled(m_detail->currentIndex() == 1);
    if (m_updating) return;
    m_viewport.setShading(static_cast<Shading>(m_shading->currentIndex()));
    m_viewport.setSplatFactor(m_splat->value());
    m_viewport.setGapFilling(m_gapFill->isChecked());
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
    settings.setValue(GapFillKey, m_gapFill->isChecked());
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
    m_shading->setItemText(4, tr("Annotation"));
    m_shading->setToolTip(tr("How the points are lit: by a light at the eye (headlight), by the sky each cell sees "
                             "(skydome; needs Tools › Compute skydome, else the headlight), in the scan's "
                             "colours, by eye-dome lighting (the relief from the depth alone), or tinted by each "
                             "cell's class in the annotation layer below"));
    m_layer->setItemText(0, tr("Material / condition"));
    m_layer->setItemText(1, tr("Tool marks"));
    m_layer->setToolTip(tr("The layer the Annotation shading shows and the 3D lasso labels"));
    m_splat->setSuffix(tr(" ×"));
    m_splat->setToolTip(tr("Size of the drawn points, as a multiple of the size of their octree cell"));
    m_budget->setSuffix(tr(" M points"));
    m_budget->setToolTip(tr("Points drawn at most; the view refines up to it when the camera stops"));
    m_detail->setItemText(0, tr("View-dependent"));
    m_detail->setItemText(1, tr("Global level"));
    m_detail->setToolTip(tr("View-dependent: finer cells near the camera, within the point budget; global level: "
                            "every fragment drawn at the one octree level below"));
    m_level->setToolTip(tr("The octree level drawn when the level of detail is global (0: the root cell)"));
    m_gapFill->setToolTip(tr("Close the small gaps between the drawn points on screen, and hide a far surface "
                             "seen through a narrow gap in a nearer one, when the view stops; openings of the scan "
                             "wider than the points stay open"));
    const QStringList labels = {tr("Shading"), tr("Annotation layer"), tr("Splat size"), tr("Point budget"),
                                tr("Level of detail"), tr("Octree level"), tr("Fill gaps")};
    for (std::size_t row = 0; row < m_labels.size(); ++row) {
        m_labels[row]->setText(labels.value(static_cast<int>(row)));
        m_labels[row]->setToolTip(m_form->itemAt(static_cast<int>(row), QFormLayout::FieldRole)->widget()
                                      ? m_form->itemAt(static_cast<int>(row), QFormLayout::FieldRole)->widget()->toolTip()
                                      : m_level->toolTip());
    }
    // The combo boxes as wide as their longest item in this language, as a hard minimum, which the form
    // layout honours when it decides to put a label above its field.
    for (QComboBox* box : {m_shading, m_layer, m_detail}) {
        box->setMinimumWidth(0);
        box->setMinimumWidth(box->minimumSizeHint().width());
    }
}

} // namespace stylos::app
