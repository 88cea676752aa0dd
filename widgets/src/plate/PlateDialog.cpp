// File › Export plate…: the plate's statement and a live preview of the page.
#include "stylos/widgets/plate/PlateDialog.h"

#include "stylos/widgets/util/NumberSpinBox.h"

#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/plate/PlateLayout.h"
#include "stylos/core/view/GuideGeometry.h"
#include "stylos/plate/PlateComposer.h"
#include "stylos/plate/PlatePainter.h"
#include "stylos/widgets/plate/PlateTexts.h"
#include "stylos/widgets/util/WheelGuard.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QFutureWatcher>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>

#include <optional>
#include <QPainter>
#include <QScreen>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>

namespace stylos::widgets {

namespace {

namespace cp = core::plate;

constexpr int kPreviewDpi = 72; // the lowest a plate takes
constexpr int kPreviewHeight = 520;
enum Column { ViewColumn, ScaleColumn, ShadingColumn, LayerColumn, HatchColumn, FragmentColumn, ColumnCount };
const char* const kPages[] = {"A4", "A3", "letter", "170x105", "205x135"};

/** The journals' print areas (the last two pages above): drawn without margins. */
bool isPrintArea(const QString& page)
{
    return page.compare(QLatin1String("170x105"), Qt::CaseInsensitive) == 0 ||
           page.compare(QLatin1String("205x135"), Qt::CaseInsensitive) == 0;
}

struct Preview {
    QImage image;
    QString error;                  ///< the plate's error (English detail), when it is not a layout's
    cp::LayoutFailure failure;      ///< Kind::None unless the plate does not fit its page: worded on the GUI thread
};

QString viewText(cp::PanelView v)
{
    switch (v) {
    case cp::PanelView::Developpee: return PlateDialog::tr("Développée");
    case cp::PanelView::Front: return PlateDialog::tr("Front");
    case cp::PanelView::Back: return PlateDialog::tr("Back");
    case cp::PanelView::Left: return PlateDialog::tr("Left");
    case cp::PanelView::Right: return PlateDialog::tr("Right");
    case cp::PanelView::Top: return PlateDialog::tr("Top");
    case cp::PanelView::Bottom: return PlateDialog::tr("Bottom");
    case cp::PanelView::Camera: return PlateDialog::tr("Current view");
    }
    return {};
}

QString shadingText(cp::PanelShading s)
{
    switch (s) {
    case cp::PanelShading::Skydome: return PlateDialog::tr("Skydome");
    case cp::PanelShading::Light: return PlateDialog::tr("Light");
    case cp::PanelShading::Height: return PlateDialog::tr("Height");
    case cp::PanelShading::Headlight: return PlateDialog::tr("Headlight");
    }
    return {};
}

/** "1:10", "1:2,5" in the user's number format. */
QString scaleLabel(double scale)
{
    return QStringLiteral("1:") + QLocale().toString(scale, 'g', 10);
}

QString millimetres(double mm)
{
    return QLocale().toString(mm, 'f', 1);
}

Preview computePreview(const std::shared_ptr<const cp::PlateSources>& sources, cp::PlateSpec spec,
                       const plate::PlateTexts& texts)
{
    Preview out;
    spec.dpi = kPreviewDpi;
    auto plate = plate::composePlate(*sources, spec, {}, nullptr, texts, &out.failure);
    if (!plate) {
        // A layout that does not fit is said in the user's language, on the GUI thread (QLocale's default may change
        // there); other errors (a missing octree, nothing visible) name their file.
        out.error = QString::fromStdString(plate.error().message);
        return out;
    }
    const auto& page = plate->layout.page;
    const double pxPerMm = kPreviewHeight / std::max(page.widthMm, page.heightMm); // the longer side fits
    out.image = QImage(int(std::lround(page.widthMm * pxPerMm)), int(std::lround(page.heightMm * pxPerMm)), QImage::Format_RGB32);
    out.image.fill(Qt::white);
    QPainter painter(&out.image);
    painter.scale(pxPerMm, pxPerMm);
    plate::paintPlate(painter, *plate);
    return out;
}

} // namespace

PlateDialog::PlateDialog(std::shared_ptr<const cp::PlateSources> sources, const cp::PlateSpec& spec, QWidget* parent)
    : QDialog(parent), m_sources(std::move(sources)), m_page(new QComboBox(this)), m_landscape(new QCheckBox(this)),
      m_margin(new NumberSpinBox(this)), m_dpi(new QSpinBox(this)), m_bits(new QComboBox(this)),
      m_legend(new QCheckBox(this)), m_caption(new QPlainTextEdit(this)), m_template(new QComboBox(this)),
      m_panels(new QTableWidget(0, ColumnCount, this)), m_preview(new QLabel(this)), m_message(new QLabel(this)),
      m_buttons(new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this)), m_timer(new QTimer(this))
{
    for (const char* p : kPages) m_page->addItem(QString::fromLatin1(p), QString::fromLatin1(p));
    m_page->setObjectName(QStringLiteral("platePage"));
    m_landscape->setObjectName(QStringLiteral("plateTurned"));
    m_margin->setObjectName(QStringLiteral("plateMargin"));
    m_margin->setRange(0, 60);
    m_margin->setDecimals(1);
    m_margin->setSuffix(QStringLiteral(" mm"));
    m_dpi->setRange(72, 2400);
    m_dpi->setSingleStep(100);
    m_bits->addItem(QStringLiteral("8"), 8);
    m_bits->addItem(QStringLiteral("16"), 16);
    m_caption->setMaximumHeight(70);
    m_panels->verticalHeader()->setVisible(false);
    m_panels->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    // The fragment takes the width the others leave (its long "(all visible; …)" item made the table scroll sideways,
    // the View column out of sight, at 1280 pixels); its box shows what fits, the whole item in its list and tooltip.
    m_panels->horizontalHeader()->setSectionResizeMode(FragmentColumn, QHeaderView::Stretch);
    m_panels->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_preview->setAlignment(Qt::AlignCenter);
    m_preview->setMinimumSize(kPreviewHeight + 20, kPreviewHeight + 20);
    m_message->setWordWrap(true);

    auto* pageForm = new QFormLayout;
    pageForm->addRow(tr("Page"), m_page);
    pageForm->addRow(QString(), m_landscape);
    pageForm->addRow(tr("Margins"), m_margin);
    pageForm->addRow(tr("Resolution (dpi)"), m_dpi);
    pageForm->addRow(tr("Bits per sample (TIFF, PNG)"), m_bits);
    pageForm->addRow(QString(), m_legend);
    pageForm->addRow(tr("Template"), m_template);
    pageForm->addRow(tr("Caption"), m_caption);

    auto* add = new QPushButton(tr("Add panel"), this);
    auto* remove = new QPushButton(tr("Remove panel"), this);
    auto* rowButtons = new QHBoxLayout;
    rowButtons->addWidget(add);
    rowButtons->addWidget(remove);
    rowButtons->addStretch();

    auto* left = new QVBoxLayout;
    left->addLayout(pageForm);
    left->addWidget(new QLabel(tr("Panels"), this));
    left->addWidget(m_panels, 1);
    left->addLayout(rowButtons);
    left->addWidget(m_message);
    auto* columns = new QHBoxLayout;
    columns->addLayout(left, 1);
    columns->addWidget(m_preview);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(columns, 1);
    layout->addWidget(m_buttons);

    m_timer->setSingleShot(true);
    m_timer->setInterval(350);
    connect(m_timer, &QTimer::timeout, this, &PlateDialog::startPreview);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(add, &QPushButton::clicked, this, [this] {
        cp::PanelSpec panel;
        panel.view = cp::PanelView::Front;
        panel.scale = m_panels->rowCount() > 0 ? qobject_cast<QDoubleSpinBox*>(m_panels->cellWidget(0, ScaleColumn))->value() : 10;
        panel.shading = cp::PanelShading::Headlight;
        addPanelRow(panel);
        schedulePreview();
    });
    connect(remove, &QPushButton::clicked, this, [this] {
        const int row = m_panels->currentRow();
        if (row >= 0 && m_panels->rowCount() > 1) m_panels->removeRow(row);
        schedulePreview();
    });
    connect(m_template, &QComboBox::activated, this, &PlateDialog::applyTemplate);
    connect(m_page, &QComboBox::currentIndexChanged, this, [this] {
        // The journal print areas are the printed area itself: no margin (docs/plates.md); leaving one for a
        // paper page gives back the margin it had before.
        const bool area = isPrintArea(m_page->currentData().toString());
        if (area && !m_onPrintArea) m_marginBeforePrintArea = m_margin->value();
        if (area) m_margin->setValue(0);
        else if (m_onPrintArea && m_margin->value() == 0) m_margin->setValue(m_marginBeforePrintArea);
        m_onPrintArea = area;
        updateTurnText();
        schedulePreview();
    });
    connect(m_landscape, &QCheckBox::toggled, this, &PlateDialog::schedulePreview);
    connect(m_margin, &QDoubleSpinBox::valueChanged, this, &PlateDialog::schedulePreview);
    connect(m_legend, &QCheckBox::toggled, this, &PlateDialog::schedulePreview);
    connect(m_caption, &QPlainTextEdit::textChanged, this, &PlateDialog::schedulePreview);

    retranslateUi();
    setSpec(spec);
    // Wide enough for the table and the preview, but never beyond the screen (a 1280-pixel laptop cut off the
    // Export and Cancel buttons).
    QSize size(1400, 720);
    if (const QScreen* shown = parent ? parent->screen() : screen())
        size = size.boundedTo(shown->availableGeometry().size() * 0.96).expandedTo(minimumSizeHint());
    resize(size);
}

PlateDialog::~PlateDialog() = default;

void PlateDialog::retranslateUi()
{
    setWindowTitle(tr("Export plate"));
    // The pages with their sizes (the data stays the layout file's name).
    const QString pageTexts[] = {tr("A4 (210 × 297 mm)"), tr("A3 (297 × 420 mm)"), tr("US letter (215.9 × 279.4 mm)"),
                                 tr("Journal print area, 170 × 105 mm"), tr("Journal print area, 205 × 135 mm")};
    static_assert(std::size(kPages) == 5);
    for (int i = 0; i < int(std::size(kPages)); ++i) {
        const int at = m_page->findData(QString::fromLatin1(kPages[i]));
        if (at >= 0) m_page->setItemText(at, pageTexts[i]);
    }
    updateTurnText();
    m_legend->setText(tr("Legend of the annotation classes"));
    m_buttons->button(QDialogButtonBox::Ok)->setText(tr("Export…"));
    m_panels->setHorizontalHeaderLabels({tr("View"), tr("Scale 1:"), tr("Shading"), tr("Annotation"), tr("Hatches"), tr("Fragment")});
    m_template->clear();
    m_template->addItem(tr("Choose a template…"));
    m_template->addItem(tr("Développée"));
    m_template->addItem(tr("Développée and front view"));
    m_template->addItem(tr("Front, right and top views"));
}

void PlateDialog::updateTurnText()
{
    // A named page is portrait and turns to landscape; a W×H page is as stated and the box turns it.
    const QString page = m_page->currentData().toString();
    const auto size = cp::pageFromName(page.toStdString());
    m_landscape->setText(page.contains(QLatin1Char('x'), Qt::CaseInsensitive) && size
                             ? tr("Turned (%1 × %2 mm)").arg(QLocale().toString(size->heightMm), QLocale().toString(size->widthMm))
                             : tr("Landscape"));
}

void PlateDialog::addPanelRow(const cp::PanelSpec& panel)
{
    const int row = m_panels->rowCount();
    m_panels->insertRow(row);
    auto* view = new QComboBox;
    for (int v = 0; v <= int(cp::PanelView::Bottom); ++v) view->addItem(viewText(cp::PanelView(v)), v);
    // The camera view: the row's own orientation when it has one, else the 3D view's current camera.
    const auto camera = panel.view == cp::PanelView::Camera && panel.camera ? panel.camera : m_camera;
    if (camera) {
        view->addItem(viewText(cp::PanelView::Camera), int(cp::PanelView::Camera));
        view->setProperty("camera", QVariantList{(*camera)[0], (*camera)[1], (*camera)[2], (*camera)[3]});
    }
    view->setCurrentIndex(std::max(0, view->findData(int(panel.view))));
    auto* scale = new NumberSpinBox; // 1e3 typed is 1:1000 (it read 13)
    scale->setRange(1, 1e6);
    scale->setDecimals(1);
    scale->setValue(panel.scale);
    auto* shading = new QComboBox;
    auto fillShading = [shading](cp::PanelView v, cp::PanelShading current) {
        const QSignalBlocker block(shading);
        shading->clear();
        const bool dev = v == cp::PanelView::Developpee;
        for (const auto s : dev ? std::vector{cp::PanelShading::Skydome, cp::PanelShading::Light, cp::PanelShading::Height}
                                : std::vector{cp::PanelShading::Skydome, cp::PanelShading::Headlight})
            shading->addItem(shadingText(s), int(s));
        const int at = shading->findData(int(current));
        shading->setCurrentIndex(at >= 0 ? at : 0);
    };
    fillShading(panel.view, panel.shading);
    auto* layer = new QComboBox;
    layer->addItem(tr("None"), -1);
    layer->addItem(tr("Material / condition"), int(core::annotation::AnnotationLayer::Material));
    layer->addItem(tr("Tool marks"), int(core::annotation::AnnotationLayer::Toolmark));
    layer->setCurrentIndex(panel.layer ? (*panel.layer == core::annotation::AnnotationLayer::Material ? 1 : 2) : 0);
    auto* hatches = new QCheckBox;
    hatches->setChecked(panel.hatches);
    auto* fragment = new QComboBox;
    fragment->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    fragment->setMinimumContentsLength(10);
    fragment->addItem(tr("(all visible; the first for a développée)"), QString());
    for (const cp::PlateFragment& f : m_sources->fragments)
        fragment->addItem(QString::fromStdString(f.name), QString::fromStdString(f.name));
    const int at = fragment->findData(QString::fromStdString(panel.fragment));
    fragment->setCurrentIndex(at >= 0 ? at : 0);
    const auto tip = [fragment] { fragment->setToolTip(fragment->currentText()); };
    tip();
    connect(fragment, &QComboBox::currentIndexChanged, fragment, tip);
    m_panels->setCellWidget(row, ViewColumn, view);
    m_panels->setCellWidget(row, ScaleColumn, scale);
    m_panels->setCellWidget(row, ShadingColumn, shading);
    m_panels->setCellWidget(row, LayerColumn, layer);
    m_panels->setCellWidget(row, HatchColumn, hatches);
    m_panels->setCellWidget(row, FragmentColumn, fragment);
    for (QWidget* field : {static_cast<QWidget*>(view), static_cast<QWidget*>(scale), static_cast<QWidget*>(shading),
                           static_cast<QWidget*>(layer), static_cast<QWidget*>(hatches), static_cast<QWidget*>(fragment)})
        guardWheel(field); // the wheel scrolls the table
    connect(view, &QComboBox::currentIndexChanged, this, [this, view, shading, fillShading] {
        fillShading(cp::PanelView(view->currentData().toInt()), cp::PanelShading(shading->currentData().toInt()));
        schedulePreview();
    });
    connect(scale, &QDoubleSpinBox::valueChanged, this, &PlateDialog::schedulePreview);
    connect(shading, &QComboBox::currentIndexChanged, this, &PlateDialog::schedulePreview);
    connect(layer, &QComboBox::currentIndexChanged, this, &PlateDialog::schedulePreview);
    connect(hatches, &QCheckBox::toggled, this, &PlateDialog::schedulePreview);
    connect(fragment, &QComboBox::currentIndexChanged, this, &PlateDialog::schedulePreview);
}

cp::PlateSpec PlateDialog::spec() const
{
    cp::PlateSpec s;
    s.pageName = m_page->currentData().toString().toStdString();
    s.page = cp::pageFromName(s.pageName).value_or(cp::PageSize{});
    s.landscape = m_landscape->isChecked();
    s.marginMm = m_margin->value();
    s.dpi = m_dpi->value();
    s.bits = m_bits->currentData().toInt();
    s.legend = m_legend->isChecked();
    s.caption = m_caption->toPlainText().toStdString();
    for (int row = 0; row < m_panels->rowCount(); ++row) {
        cp::PanelSpec p;
        auto* view = qobject_cast<QComboBox*>(m_panels->cellWidget(row, ViewColumn));
        p.view = cp::PanelView(view->currentData().toInt());
        if (p.view == cp::PanelView::Camera) {
            const QVariantList q = view->property("camera").toList();
            if (q.size() == 4) p.camera = std::array<double, 4>{q[0].toDouble(), q[1].toDouble(), q[2].toDouble(), q[3].toDouble()};
        }
        p.scale = qobject_cast<QDoubleSpinBox*>(m_panels->cellWidget(row, ScaleColumn))->value();
        p.shading = cp::PanelShading(qobject_cast<QComboBox*>(m_panels->cellWidget(row, ShadingColumn))->currentData().toInt());
        const int layer = qobject_cast<QComboBox*>(m_panels->cellWidget(row, LayerColumn))->currentData().toInt();
        if (layer >= 0) p.layer = core::annotation::AnnotationLayer(layer);
        p.hatches = qobject_cast<QCheckBox*>(m_panels->cellWidget(row, HatchColumn))->isChecked();
        p.fragment = qobject_cast<QComboBox*>(m_panels->cellWidget(row, FragmentColumn))->currentData().toString().toStdString();
        s.panels.push_back(p);
    }
    return s;
}

void PlateDialog::setSpec(const cp::PlateSpec& spec)
{
    {
        const QSignalBlocker a(m_page), b(m_landscape), c(m_margin), d(m_legend), e(m_caption);
        int page = -1; // the names are case-insensitive ("a4" is A4)
        for (int i = 0; i < m_page->count() && page < 0; ++i)
            if (m_page->itemData(i).toString().compare(QString::fromStdString(spec.pageName), Qt::CaseInsensitive) == 0) page = i;
        if (page < 0) {
            m_page->addItem(QString::fromStdString(spec.pageName), QString::fromStdString(spec.pageName));
            page = m_page->count() - 1;
        }
        m_page->setCurrentIndex(page);
        m_onPrintArea = isPrintArea(m_page->currentData().toString());
        updateTurnText();
        m_landscape->setChecked(spec.landscape);
        m_margin->setValue(spec.marginMm);
        m_dpi->setValue(spec.dpi);
        m_bits->setCurrentIndex(spec.bits == 16 ? 1 : 0);
        m_legend->setChecked(spec.legend);
        m_caption->setPlainText(QString::fromStdString(spec.caption));
        m_panels->setRowCount(0);
        for (const cp::PanelSpec& p : spec.panels) addPanelRow(p);
    }
    schedulePreview();
}

cp::PlateSpec PlateDialog::defaultSpec(
    const cp::PlateSources& sources,
    const std::function<std::shared_ptr<const core::octree::PackedOctree>(const cp::PlateFragment&)>& opened,
    std::optional<std::size_t> preferred)
{
    cp::PlateSpec spec;
    spec.landscape = true;
    cp::PanelSpec panel;
    panel.scale = 10;
    // The fragment's développée at the most detailed usual scale that fits the print area, judged from its octree's
    // occupied box: π × its wider horizontal side (a whole drum's turn; a fragment's arc is less) by its height, laid
    // out as the plate would be (the preview then checks the page as drawn). The fragment is the preferred one, named
    // in the panel (the composer draws a named fragment, hidden or not), else the one the composer unrolls for a panel
    // that names none: the first visible one. @p opened gives its octree when the caller holds it open.
    const auto usable = [](const cp::PlateFragment& f) { return !f.missing && f.isOctree; };
    auto chosen = sources.fragments.end();
    if (preferred && *preferred < sources.fragments.size()) {
        const auto named = [&](const cp::PlateFragment& f) { return f.name == sources.fragments[*preferred].name; };
        if (usable(sources.fragments[*preferred]) &&
            std::count_if(sources.fragments.begin(), sources.fragments.end(), named) == 1)
            chosen = sources.fragments.begin() + std::ptrdiff_t(*preferred);
    }
    if (chosen != sources.fragments.end()) panel.fragment = chosen->name;
    else
        chosen = std::find_if(sources.fragments.begin(), sources.fragments.end(),
                              [&](const cp::PlateFragment& f) { return f.visible && usable(f); });
    std::shared_ptr<const core::octree::PackedOctree> octree;
    if (chosen != sources.fragments.end()) {
        // What the user painted shows: the first layer that holds a class (0 is "unlabelled").
        for (const auto layer : core::annotation::AllAnnotationLayers) {
            const auto& labels = chosen->labels[static_cast<std::size_t>(layer)];
            if (labels && std::any_of(labels->begin(), labels->end(), [](std::uint8_t c) { return c != 0; })) {
                panel.layer = layer;
                break;
            }
        }
        if (opened) octree = opened(*chosen);
        if (!octree)
            if (auto read = core::octree::PackedOctree::open(chosen->path))
                octree = std::make_shared<const core::octree::PackedOctree>(std::move(read).value());
    }
    if (octree) {
        const Eigen::Vector3d size = core::view::occupiedBounds(*octree).sizes();
        const double widthMm = std::numbers::pi * std::max(size.x(), size.y()) * 1000.0, heightMm = size.z() * 1000.0;
        for (const double scale : {1.0, 2.0, 5.0, 10.0, 20.0, 25.0, 50.0, 100.0, 200.0, 250.0, 500.0, 1000.0}) {
            panel.scale = scale;
            spec.panels = {panel};
            const std::array<double, 2> imageMm{widthMm / scale, heightMm / scale};
            if (cp::layoutPlate(spec, std::span(&imageMm, 1), 0, 0.0)) break;
        }
    }
    spec.panels = {panel};
    return spec;
}

void PlateDialog::applyTemplate(int index)
{
    if (index <= 0) return;
    const double scale = m_panels->rowCount() > 0 ? qobject_cast<QDoubleSpinBox*>(m_panels->cellWidget(0, ScaleColumn))->value() : 10;
    cp::PlateSpec s = spec();
    cp::PanelSpec dev;
    dev.scale = scale;
    cp::PanelSpec front;
    front.view = cp::PanelView::Front;
    front.scale = scale;
    front.shading = cp::PanelShading::Headlight;
    if (index == 1) s.panels = {dev};
    else if (index == 2) s.panels = {dev, front};
    else {
        cp::PanelSpec right = front, top = front;
        right.view = cp::PanelView::Right;
        top.view = cp::PanelView::Top;
        s.panels = {front, right, top};
    }
    m_template->setCurrentIndex(0);
    setSpec(s);
}

void PlateDialog::setCurrentCamera(const std::optional<std::array<double, 4>>& camera)
{
    m_camera = camera;
}

bool PlateDialog::previewPending() const { return m_running || m_again || m_timer->isActive(); }

void PlateDialog::schedulePreview()
{
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(false);
    m_message->setText(tr("Drawing the preview…"));
    m_timer->start();
}

void PlateDialog::startPreview()
{
    if (m_running) {
        m_again = true;
        return;
    }
    m_running = true;
    auto* watcher = new QFutureWatcher<Preview>(this);
    const cp::PlateSpec stated = spec();
    connect(watcher, &QFutureWatcher<Preview>::finished, this, [this, watcher, stated] {
        const Preview p = watcher->result();
        watcher->deleteLater();
        m_running = false;
        if (m_again) {
            m_again = false;
            startPreview();
            return;
        }
        if (p.error.isEmpty()) {
            m_image = p.image;
            m_preview->setPixmap(QPixmap::fromImage(p.image));
            m_message->clear();
        } else {
            m_image = QImage(); // not the last page that fitted: nothing is shown that would not be exported
            m_preview->clear();
            m_message->setText(p.failure.kind != cp::LayoutFailure::Kind::None ? layoutFailureText(p.failure, stated) : p.error);
        }
        m_buttons->button(QDialogButtonBox::Ok)->setEnabled(p.error.isEmpty());
        Q_EMIT previewUpdated();
    });
    watcher->setFuture(QtConcurrent::run([sources = m_sources, spec = stated, texts = PlateTexts::translated(m_sources->legend)] {
        return computePreview(sources, spec, texts);
    }));
}

QString PlateDialog::layoutFailureText(const cp::LayoutFailure& failure, const cp::PlateSpec& spec)
{
    const auto size = [](double w, double h) { return tr("%1 × %2 mm").arg(millimetres(w), millimetres(h)); };
    const QString area = size(failure.printArea.w, failure.printArea.h);
    const bool letters = spec.panels.size() > 1;
    const auto panelName = [&](std::size_t i) {
        const cp::PanelSpec& p = spec.panels[i];
        const QString what = QStringLiteral("%1, %2").arg(viewText(p.view), scaleLabel(p.scale));
        return letters ? tr("Panel %1 (%2)").arg(QChar(QLatin1Char(char('A' + i))), what) : tr("The panel (%1)").arg(what);
    };
    switch (failure.kind) {
    case cp::LayoutFailure::Kind::None: break;
    case cp::LayoutFailure::Kind::PanelTooLarge: {
        if (failure.panel >= spec.panels.size()) break;
        const QString panel = size(failure.sizeMm[0], failure.sizeMm[1]);
        if (failure.smallerScale)
            return tr("%1 is %2; the print area is %3: use %4 or smaller, or a larger page.")
                .arg(panelName(failure.panel), panel, area, scaleLabel(*failure.smallerScale));
        return tr("%1 is %2; the print area is %3: no scale fits this page, use a larger page.")
            .arg(panelName(failure.panel), panel, area);
    }
    case cp::LayoutFailure::Kind::PanelOutside:
        if (failure.panel >= spec.panels.size()) break;
        return tr("%1, placed at (%2, %3) mm, is %4 with its texts and leaves the %5 page.")
            .arg(panelName(failure.panel), millimetres(failure.atMm[0]), millimetres(failure.atMm[1]),
                 size(failure.sizeMm[0], failure.sizeMm[1]), size(failure.page.widthMm, failure.page.heightMm));
    case cp::LayoutFailure::Kind::CaptionTooTall:
        return tr("The caption needs %1 mm of height on its own; the print area is %2: shorten the caption or use a "
                  "larger page.").arg(millimetres(failure.sizeMm[1]), area);
    case cp::LayoutFailure::Kind::TooTall: {
        QStringList scales;
        for (std::size_t i = 0; i < failure.fittingScales.size() && i < spec.panels.size(); ++i) {
            if (spec.panels[i].atMm) continue;
            scales << (letters ? QStringLiteral("%1 %2").arg(QChar(QLatin1Char(char('A' + i))), scaleLabel(failure.fittingScales[i]))
                               : scaleLabel(failure.fittingScales[i]));
        }
        const QString height = millimetres(failure.sizeMm[1]);
        if (scales.isEmpty())
            return tr("The plate needs %1 mm of height; the print area is %2: use smaller scales, a larger page or the "
                      "other orientation.").arg(height, area);
        return tr("The plate needs %1 mm of height; the print area is %2: use smaller scales (%3), a larger page or the "
                  "other orientation.").arg(height, area, scales.join(QStringLiteral(", ")));
    }
    }
    return {};
}

} // namespace stylos::widgets
