// The développée's painting bar: tool, layer, class, brush size, wand tolerance, overlay opacity.
#include "stylos/widgets/annotation/PaintToolBar.h"
#include "stylos/widgets/util/NumberSpinBox.h"

#include "stylos/widgets/annotation/DeveloppeeAnnotator.h"
#include "stylos/widgets/annotation/LegendText.h"
#include "stylos/widgets/developpee/DeveloppeeView.h"
#include "stylos/widgets/document/SceneDocument.h"

#include <QButtonGroup>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QPixmap>
#include <QSlider>
#include <QToolButton>
#include <QVBoxLayout>

namespace stylos::widgets {

namespace {

using core::annotation::AnnotationLayer;

constexpr PaintTool Tools[] = {PaintTool::Navigate, PaintTool::Brush, PaintTool::Eraser,
                               PaintTool::Lasso,    PaintTool::Wand,  PaintTool::Holes};

QIcon swatch(const core::scene::Rgb& c)
{
    QPixmap pixmap(12, 12);
    pixmap.fill(QColor(c.r, c.g, c.b));
    return QIcon(pixmap);
}

} // namespace

PaintToolBar::PaintToolBar(const SceneDocument& document, DeveloppeeAnnotator& annotator, DeveloppeeView& view,
                           QWidget* parent)
    : QWidget(parent), m_document(document), m_annotator(annotator), m_view(view), m_tools(new QButtonGroup(this)),
      m_layer(new QComboBox(this)), m_class(new QComboBox(this)), m_sizeLabel(new QLabel(this)),
      m_size(new NumberSpinBox(this)), m_criterion(new QComboBox(this)), m_tolerance(new NumberSpinBox(this)),
      m_opacityLabel(new QLabel(this)), m_opacity(new QSlider(Qt::Horizontal, this))
{
    setObjectName(QStringLiteral("PaintToolBar"));
    m_layer->setObjectName(QStringLiteral("paintLayer"));
    // As wide as its longest name in the language shown (set after the first show; Greek was cut).
    m_layer->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    m_class->setObjectName(QStringLiteral("paintClass"));
    m_size->setObjectName(QStringLiteral("paintBrushSize"));
    m_criterion->setObjectName(QStringLiteral("paintWandCriterion"));
    m_tolerance->setObjectName(QStringLiteral("paintWandTolerance"));
    m_opacity->setObjectName(QStringLiteral("paintOverlayOpacity"));

    auto* tools = new QHBoxLayout;
    tools->setSpacing(2);
    for (PaintTool tool : Tools) {
        auto* button = new QToolButton(this);
        button->setCheckable(true);
        button->setAutoRaise(true);
        button->setObjectName(QStringLiteral("paintTool%1").arg(int(tool)));
        m_tools->addButton(button, int(tool));
        tools->addWidget(button);
    }
    m_tools->button(int(view.tool()))->setChecked(true);
    tools->addSpacing(8);
    tools->addWidget(m_layer);
    tools->addWidget(m_class, 1);

    for (AnnotationLayer layer : core::annotation::AllAnnotationLayers) m_layer->addItem(QString(), int(layer));
    m_size->setRange(0.1, 500.0);
    m_size->setDecimals(1);
    m_size->setValue(view.brushSize() * 1e3);
    m_criterion->addItem(QString(), int(WandCriterion::Height));
    m_criterion->addItem(QString(), int(WandCriterion::Shading));
    m_tolerance->setDecimals(2);
    m_tolerance->setRange(0.0, 1000.0);
    m_opacity->setRange(0, 100);
    m_opacity->setValue(int(std::lround(view.overlayOpacity() * 100.0)));
    m_opacity->setMaximumWidth(120);

    auto* settings = new QHBoxLayout;
    settings->addWidget(m_sizeLabel);
    settings->addWidget(m_size);
    settings->addSpacing(8);
    settings->addWidget(m_criterion);
    settings->addWidget(m_tolerance);
    settings->addSpacing(8);
    settings->addWidget(m_opacityLabel);
    settings->addWidget(m_opacity);
    settings->addStretch(1);

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addLayout(tools);
    layout->addLayout(settings);

    connect(m_tools, &QButtonGroup::idClicked, this, [this](int id) { m_view.setTool(PaintTool(id)); });
    connect(&view, &DeveloppeeView::toolChanged, this, [this](PaintTool tool) {
        if (auto* b = m_tools->button(int(tool))) b->setChecked(true);
        updateEnabled();
    });
    connect(m_layer, &QComboBox::currentIndexChanged, this, [this] {
        if (!m_updating) m_annotator.setActive(AnnotationLayer(m_layer->currentData().toInt()), 0);
    });
    connect(m_class, &QComboBox::currentIndexChanged, this, [this] {
        if (!m_updating && m_class->currentIndex() >= 0)
            m_annotator.setActive(m_annotator.layer(), std::uint8_t(m_class->currentData().toInt()));
    });
    connect(m_size, &QDoubleSpinBox::valueChanged, this, [this](double mm) { m_view.setBrushSize(mm * 1e-3); });
    connect(m_criterion, &QComboBox::currentIndexChanged, this, [this] {
        m_view.setWandCriterion(WandCriterion(m_criterion->currentData().toInt()));
        m_updating = true;
        const bool height = m_view.wandCriterion() == WandCriterion::Height;
        m_tolerance->setSuffix(height ? tr(" mm") : tr(" %"));
        m_tolerance->setRange(0.0, height ? 1000.0 : 100.0);
        m_tolerance->setValue(height ? m_heightTolerance : m_shadeTolerance);
        m_updating = false;
        applyTolerance();
    });
    connect(m_tolerance, &QDoubleSpinBox::valueChanged, this, [this](double value) {
        if (m_updating) return;
        (m_view.wandCriterion() == WandCriterion::Height ? m_heightTolerance : m_shadeTolerance) = value;
        applyTolerance();
    });
    connect(m_opacity, &QSlider::valueChanged, this, [this](int value) { m_view.setOverlayOpacity(value / 100.0); });
    connect(&annotator, &DeveloppeeAnnotator::activeChanged, this, &PaintToolBar::showActive);
    connect(&document, &SceneDocument::legendChanged, this, &PaintToolBar::fillClasses);
    connect(&view, &DeveloppeeView::developpeeChanged, this, &PaintToolBar::updateEnabled);

    m_tolerance->setValue(m_heightTolerance);
    applyTolerance();
    retranslateUi();
    fillClasses();
    updateEnabled();
}

void PaintToolBar::applyTolerance()
{
    const bool height = m_view.wandCriterion() == WandCriterion::Height;
    m_view.setWandTolerance(height ? m_heightTolerance * 1e-3 : m_shadeTolerance / 100.0);
}

void PaintToolBar::fillClasses()
{
    m_updating = true;
    m_listedLayer = m_annotator.layer();
    m_class->clear();
    for (const auto& c : m_document.legend().classes(m_annotator.layer()))
        m_class->addItem(swatch(c.colour), LegendText::className(m_annotator.layer(), c), int(c.id));
    m_updating = false;
    showActive();
}

void PaintToolBar::showActive()
{
    if (m_listedLayer != m_annotator.layer()) { // the classes listed are another layer's
        fillClasses();
        return;
    }
    m_updating = true;
    m_layer->setCurrentIndex(m_layer->findData(int(m_annotator.layer())));
    m_class->setCurrentIndex(m_class->findData(int(m_annotator.activeClass())));
    m_updating = false;
}

void PaintToolBar::updateEnabled()
{
    const bool paintable = m_view.canPaint();
    for (QAbstractButton* b : m_tools->buttons())
        if (m_tools->id(b) != int(PaintTool::Navigate)) b->setEnabled(paintable);
    const PaintTool tool = m_view.tool();
    m_size->setEnabled(tool == PaintTool::Brush || tool == PaintTool::Eraser);
    m_criterion->setEnabled(tool == PaintTool::Wand);
    m_tolerance->setEnabled(tool == PaintTool::Wand);
}

void PaintToolBar::retranslateUi()
{
    const auto set = [this](PaintTool tool, const QString& text, const QString& tip) {
        QAbstractButton* b = m_tools->button(int(tool));
        b->setText(text);
        b->setToolTip(tip);
    };
    set(PaintTool::Navigate, tr("Pan"), tr("Navigate: drag to pan, click to mark the point in 3D (N)"));
    set(PaintTool::Brush, tr("Brush"), tr("Paint the active class with a round brush (B)"));
    set(PaintTool::Eraser, tr("Eraser"), tr("Unlabel the cells under a round brush (E)"));
    set(PaintTool::Lasso, tr("Polygon"),
        tr("Fill a polygon with the active class: click its corners and double-click, or drag a lasso (L); Escape cancels"));
    set(PaintTool::Wand, tr("Wand"),
        tr("Fill the connected pixels of similar height or shading with the active class (W)"));
    set(PaintTool::Holes, tr("Holes"), tr("Fill the holes enclosed by the clicked region with its class (H)"));
    m_layer->setToolTip(tr("The annotation layer shown and painted"));
    for (int i = 0; i < m_layer->count(); ++i)
        m_layer->setItemText(i, LegendText::layerTitle(AnnotationLayer(m_layer->itemData(i).toInt())));
    m_class->setToolTip(tr("The class the brush, polygon and wand paint"));
    m_sizeLabel->setText(tr("Size"));
    m_size->setSuffix(tr(" mm"));
    m_size->setToolTip(tr("Brush and eraser diameter on the object"));
    m_criterion->setItemText(0, tr("Height"));
    m_criterion->setItemText(1, tr("Shading"));
    m_criterion->setToolTip(tr("What the magic wand compares"));
    m_tolerance->setSuffix(m_view.wandCriterion() == WandCriterion::Height ? tr(" mm") : tr(" %"));
    m_tolerance->setToolTip(tr("The magic wand takes pixels within this of the clicked one"));
    m_opacityLabel->setText(tr("Overlay"));
    m_opacity->setToolTip(tr("Opacity of the annotation over the développée"));
    fillClasses();
}

void PaintToolBar::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) retranslateUi();
    QWidget::changeEvent(event);
}

} // namespace stylos::widgets
