// The Legend dock's contents: classes of both layers with their measures, and the legend's edits.
#include "stylos/widgets/annotation/LegendWidget.h"
#include "annotation/HatchBox.h"

#include "stylos/widgets/annotation/ClassMeasures.h"
#include "stylos/widgets/annotation/LabelStore.h"
#include "stylos/widgets/annotation/LegendText.h"
#include "stylos/widgets/document/SceneDocument.h"
#include "stylos/widgets/util/WheelGuard.h"

#include <QColorDialog>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPainter>
#include <QPixmap>
#include <QPushButton>
#include <QRadioButton>
#include <QScrollBar>
#include <QTimer>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace stylos::widgets {

namespace {

using core::annotation::AnnotationLayer;
using core::annotation::Hatch;
using core::annotation::Legend;
using core::annotation::LegendClass;

enum Column { NameColumn, HatchColumn, CellsColumn, AreaColumn, ColumnCount };
constexpr int LayerRole = Qt::UserRole + 1;
constexpr int IdRole = Qt::UserRole + 2;

constexpr Hatch Hatches[] = {Hatch::None, Hatch::Diagonal, Hatch::BackDiagonal, Hatch::Cross, Hatch::DiagonalCross,
                             Hatch::Dots, Hatch::Horizontal, Hatch::Vertical, Hatch::Solid};

QIcon swatch(const core::scene::Rgb& c)
{
    QPixmap pixmap(14, 14);
    pixmap.fill(QColor(c.r, c.g, c.b));
    return QIcon(pixmap);
}

/** A small black-on-white sample of @p hatch, as plates draw it. */
QIcon hatchIcon(Hatch hatch)
{
    static const std::pair<Hatch, Qt::BrushStyle> styles[] = {
        {Hatch::None, Qt::NoBrush},          {Hatch::Diagonal, Qt::BDiagPattern},   {Hatch::BackDiagonal, Qt::FDiagPattern},
        {Hatch::Cross, Qt::CrossPattern},    {Hatch::DiagonalCross, Qt::DiagCrossPattern}, {Hatch::Dots, Qt::Dense6Pattern},
        {Hatch::Horizontal, Qt::HorPattern}, {Hatch::Vertical, Qt::VerPattern},     {Hatch::Solid, Qt::SolidPattern}};
    QPixmap pixmap(28, 14); // the HatchBox shows it alone: wide enough to read the pattern
    pixmap.fill(Qt::white);
    QPainter painter(&pixmap);
    for (const auto& [h, style] : styles)
        if (h == hatch) painter.fillRect(pixmap.rect(), QBrush(Qt::black, style));
    painter.setPen(Qt::gray);
    painter.drawRect(pixmap.rect().adjusted(0, 0, -1, -1));
    return QIcon(pixmap);
}

} // namespace

LegendWidget::LegendWidget(SceneDocument& document, ClassMeasures* measures, QWidget* parent)
    : QWidget(parent), m_document(document), m_measures(measures), m_tree(new QTreeWidget(this)),
      m_add(new QPushButton(this)), m_colour(new QPushButton(this)), m_remove(new QPushButton(this))
{
    setObjectName(QStringLiteral("LegendWidget"));
    m_tree->setObjectName(QStringLiteral("legendTree"));
    m_add->setObjectName(QStringLiteral("legendAdd"));
    m_colour->setObjectName(QStringLiteral("legendColour"));
    m_remove->setObjectName(QStringLiteral("legendRemove"));
    m_tree->setColumnCount(ColumnCount);
    m_tree->setRootIsDecorated(false);
    m_tree->setUniformRowHeights(true);
    m_tree->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed);
    // Every column as wide as its contents (the hatch boxes included: their longest name in Greek is cut
    // otherwise), and the tree as wide as the columns (fitColumns): the dock widens rather than cut a column.
    for (int column : {NameColumn, HatchColumn, CellsColumn, AreaColumn})
        m_tree->header()->setSectionResizeMode(column, QHeaderView::ResizeToContents);
    m_tree->header()->setStretchLastSection(false);
    m_tree->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_tree->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOn); // its width counted once, whether it shows or not

    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_add);
    buttons->addWidget(m_colour);
    buttons->addWidget(m_remove);
    buttons->addStretch(1);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(m_tree, 1);
    layout->addLayout(buttons);

    connect(&document, &SceneDocument::legendChanged, this, &LegendWidget::rebuild);
    if (measures) connect(measures, &ClassMeasures::changed, this, &LegendWidget::refreshMeasures);
    connect(m_tree, &QTreeWidget::currentItemChanged, this, [this] {
        updateButtons();
        if (m_updating) return;
        if (const auto current = currentClass()) {
            m_active = current;
            Q_EMIT classChosen(current->first, current->second);
        }
    });
    connect(m_tree, &QTreeWidget::itemChanged, this, [this](QTreeWidgetItem* item, int column) {
        if (m_updating || column != NameColumn || !item->parent()) return;
        const auto layer = AnnotationLayer(item->data(NameColumn, LayerRole).toInt());
        const auto id = std::uint8_t(item->data(NameColumn, IdRole).toInt());
        ++m_editing;
        if (!renameClass(layer, id, item->text(NameColumn))) rebuild(); // refused (empty, taken): shown as it is
        --m_editing;
    });
    connect(m_add, &QPushButton::clicked, this, [this] {
        const auto current = currentClass();
        const QTreeWidgetItem* item = m_tree->currentItem();
        const AnnotationLayer layer = current ? current->first
                                      : item ? AnnotationLayer(item->data(NameColumn, LayerRole).toInt())
                                             : AnnotationLayer::Material;
        if (const std::uint8_t id = addClass(layer)) {
            if (QTreeWidgetItem* added = itemOf(layer, id)) {
                m_tree->setCurrentItem(added);
                m_tree->editItem(added, NameColumn);
            }
        }
    });
    connect(m_colour, &QPushButton::clicked, this, [this] {
        const auto current = currentClass();
        if (!current) return;
        const LegendClass* c = m_document.legend().find(current->first, current->second);
        const QColor chosen = QColorDialog::getColor(QColor(c->colour.r, c->colour.g, c->colour.b), this,
                                                     tr("Colour of “%1”").arg(LegendText::className(current->first, *c)));
        if (chosen.isValid()) setClassColour(current->first, current->second, chosen);
    });
    connect(m_remove, &QPushButton::clicked, this, [this] {
        if (const auto current = currentClass()) removeClass(current->first, current->second);
    });
    retranslateUi();
}

QTreeWidgetItem* LegendWidget::itemOf(AnnotationLayer layer, std::uint8_t classId) const
{
    for (int i = 0; i < m_tree->topLevelItemCount(); ++i) {
        QTreeWidgetItem* top = m_tree->topLevelItem(i);
        if (AnnotationLayer(top->data(NameColumn, LayerRole).toInt()) != layer) continue;
        for (int j = 0; j < top->childCount(); ++j)
            if (top->child(j)->data(NameColumn, IdRole).toInt() == classId) return top->child(j);
    }
    return nullptr;
}

std::optional<std::pair<AnnotationLayer, std::uint8_t>> LegendWidget::currentClass() const
{
    const QTreeWidgetItem* item = m_tree->currentItem();
    if (!item || !item->parent()) return std::nullopt;
    return std::pair{AnnotationLayer(item->data(NameColumn, LayerRole).toInt()),
                     std::uint8_t(item->data(NameColumn, IdRole).toInt())};
}

LegendClass* LegendWidget::editable(Legend& legend, AnnotationLayer layer, std::uint8_t id) const
{
    auto& classes = legend.classes(layer);
    const auto it = std::find_if(classes.begin(), classes.end(), [id](const LegendClass& c) { return c.id == id; });
    return it == classes.end() ? nullptr : &*it;
}

bool LegendWidget::renameClass(AnnotationLayer layer, std::uint8_t classId, const QString& name)
{
    Legend legend = m_document.legend();
    LegendClass* c = editable(legend, layer, classId);
    const QString trimmed = name.trimmed();
    if (!c || trimmed.isEmpty() || LegendText::showsAs(layer, c->name, trimmed)) return false;
    const std::string stored = trimmed.toStdString();
    for (const LegendClass& other : legend.classes(layer))
        if (other.id != classId && other.name == stored) return false; // names are unique within a layer
    const QString before = LegendText::className(layer, *c);
    c->name = stored;
    return m_document.setLegend(std::move(legend), tr("Rename class “%1” to “%2”").arg(before, trimmed));
}

bool LegendWidget::setClassColour(AnnotationLayer layer, std::uint8_t classId, const QColor& colour)
{
    Legend legend = m_document.legend();
    LegendClass* c = editable(legend, layer, classId);
    if (!c || !colour.isValid()) return false;
    c->colour = {std::uint8_t(colour.red()), std::uint8_t(colour.green()), std::uint8_t(colour.blue())};
    return m_document.setLegend(legend, tr("Recolour class “%1”").arg(LegendText::className(layer, *c)));
}

bool LegendWidget::setClassHatch(AnnotationLayer layer, std::uint8_t classId, Hatch hatch)
{
    Legend legend = m_document.legend();
    LegendClass* c = editable(legend, layer, classId);
    if (!c) return false;
    c->hatch = hatch;
    return m_document.setLegend(legend, tr("Change the hatch of “%1”").arg(LegendText::className(layer, *c)));
}

std::uint8_t LegendWidget::addClass(AnnotationLayer layer)
{
    Legend legend = m_document.legend();
    auto& classes = legend.classes(layer);
    int id = 1;
    while (id <= 255 && legend.find(layer, id)) ++id;
    if (id > 255) return 0;
    LegendClass c;
    c.id = std::uint8_t(id);
    for (int n = id;; ++n) { // a name not yet taken
        c.name = tr("class %1").arg(n).toStdString();
        if (std::none_of(classes.begin(), classes.end(), [&](const LegendClass& o) { return o.name == c.name; })) break;
    }
    // A hue away from the others: the golden angle from the id.
    const QColor colour = QColor::fromHsv(int(id * 137.508) % 360, 170, 220);
    c.colour = {std::uint8_t(colour.red()), std::uint8_t(colour.green()), std::uint8_t(colour.blue())};
    c.hatch = Hatch::None;
    classes.push_back(c);
    const QString name = QString::fromStdString(c.name);
    return m_document.setLegend(std::move(legend), tr("Add class “%1”").arg(name)) ? std::uint8_t(id) : 0;
}

bool LegendWidget::removeClass(AnnotationLayer layer, std::uint8_t classId)
{
    if (!m_document.legend().find(layer, classId)) return false;
    const std::uint64_t cells = m_document.labels().count(layer, classId);
    std::uint8_t replacement = 0;
    if (cells > 0) {
        const auto chosen = m_chooser ? m_chooser(layer, classId, cells) : askReplacement(layer, classId, cells);
        if (!chosen) return false;
        replacement = *chosen;
    }
    return m_document.removeLegendClass(layer, classId, replacement);
}

std::optional<std::uint8_t> LegendWidget::askReplacement(AnnotationLayer layer, std::uint8_t classId, std::uint64_t cells)
{
    const LegendClass* c = m_document.legend().find(layer, classId);
    QDialog dialog(this);
    dialog.setWindowTitle(tr("Delete class “%1”").arg(LegendText::className(layer, *c)));
    auto* text = new QLabel(tr("%n cell(s) hold this class. What becomes of them?", nullptr, int(std::min<std::uint64_t>(cells, INT_MAX))), &dialog);
    auto* unlabel = new QRadioButton(tr("Unlabel them"), &dialog);
    auto* move = new QRadioButton(tr("Move them to"), &dialog);
    auto* target = new QComboBox(&dialog);
    for (const LegendClass& other : m_document.legend().classes(layer))
        if (other.id != classId) target->addItem(swatch(other.colour), LegendText::className(layer, other), int(other.id));
    unlabel->setChecked(true);
    move->setEnabled(target->count() > 0);
    target->setEnabled(false);
    connect(move, &QRadioButton::toggled, target, &QComboBox::setEnabled);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("Delete"));
    connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
    auto* moveRow = new QHBoxLayout;
    moveRow->addWidget(move);
    moveRow->addWidget(target, 1);
    auto* layout = new QVBoxLayout(&dialog);
    layout->addWidget(text);
    layout->addWidget(unlabel);
    layout->addLayout(moveRow);
    layout->addWidget(buttons);
    if (dialog.exec() != QDialog::Accepted) return std::nullopt;
    return move->isChecked() ? std::uint8_t(target->currentData().toInt()) : std::uint8_t(0);
}

void LegendWidget::showActive(AnnotationLayer layer, std::uint8_t classId)
{
    m_active = std::pair{layer, classId};
    m_updating = true;
    if (QTreeWidgetItem* item = itemOf(layer, classId)) m_tree->setCurrentItem(item);
    m_updating = false;
    updateButtons();
}

void LegendWidget::rebuild()
{
    if (m_editing > 0) { // the edited row or list must outlive its own signal: rebuild once it returned
        QTimer::singleShot(0, this, &LegendWidget::rebuild);
        return;
    }
    m_updating = true;
    m_tree->clear();
    const Legend& legend = m_document.legend();
    for (AnnotationLayer layer : core::annotation::AllAnnotationLayers) {
        auto* top = new QTreeWidgetItem(m_tree);
        top->setText(NameColumn, LegendText::layerTitle(layer));
        top->setData(NameColumn, LayerRole, int(layer));
        top->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
        QFont bold = top->font(NameColumn);
        bold.setBold(true);
        top->setFont(NameColumn, bold);
        top->setFirstColumnSpanned(false);
        for (const LegendClass& c : legend.classes(layer)) {
            auto* item = new QTreeWidgetItem(top);
            item->setIcon(NameColumn, swatch(c.colour));
            item->setText(NameColumn, LegendText::className(layer, c));
            item->setData(NameColumn, LayerRole, int(layer));
            item->setData(NameColumn, IdRole, int(c.id));
            item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsEditable);
            item->setTextAlignment(CellsColumn, Qt::AlignRight | Qt::AlignVCenter);
            item->setTextAlignment(AreaColumn, Qt::AlignRight | Qt::AlignVCenter);
            auto* hatch = new HatchBox(m_tree);
            hatch->setObjectName(QStringLiteral("legendHatch_%1_%2").arg(core::annotation::layerName(layer)).arg(c.id));
            for (Hatch h : Hatches) hatch->addItem(hatchIcon(h), LegendText::hatchTitle(h), int(h));
            hatch->setCurrentIndex(hatch->findData(int(c.hatch)));
            hatch->setDescription(tr("The black-and-white pattern of this class on plates"));
            m_tree->setItemWidget(item, HatchColumn, hatch);
            guardWheel(hatch); // the wheel scrolls the legend
            const std::uint8_t id = c.id;
            connect(hatch, &QComboBox::currentIndexChanged, this, [this, layer, id, hatch] {
                if (m_updating) return;
                ++m_editing;
                setClassHatch(layer, id, Hatch(hatch->currentData().toInt()));
                --m_editing;
            });
        }
    }
    m_tree->expandAll();
    if (m_active)
        if (QTreeWidgetItem* item = itemOf(m_active->first, m_active->second)) m_tree->setCurrentItem(item);
    m_updating = false;
    refreshMeasures();
    updateButtons();
}

void LegendWidget::fitColumns()
{
    const QAbstractItemView* view = m_tree; // sizeHintForColumn() is public there (the tree's own override is not)
    int width = 2 * m_tree->frameWidth() + m_tree->verticalScrollBar()->sizeHint().width();
    for (int column = 0; column < ColumnCount; ++column)
        width += std::max(view->sizeHintForColumn(column), m_tree->header()->sectionSizeHint(column));
    m_tree->setMinimumWidth(width);
}

void LegendWidget::refreshMeasures()
{
    const QLocale locale;
    const bool busy = m_measures && m_measures->isBusy();
    m_updating = true;
    for (int i = 0; i < m_tree->topLevelItemCount(); ++i) {
        QTreeWidgetItem* top = m_tree->topLevelItem(i);
        const auto layer = AnnotationLayer(top->data(NameColumn, LayerRole).toInt());
        for (int j = 0; j < top->childCount(); ++j) {
            QTreeWidgetItem* item = top->child(j);
            if (!m_measures) continue;
            const auto m = m_measures->total(layer, std::uint8_t(item->data(NameColumn, IdRole).toInt()));
            item->setText(CellsColumn, locale.toString(qulonglong(m.cells)));
            item->setText(AreaColumn, locale.toString(m.areaM2, 'f', 4));
            item->setToolTip(AreaColumn, busy ? tr("Being measured…") : tr("Surface area on the object, m²"));
        }
    }
    m_updating = false;
    fitColumns();
}

void LegendWidget::updateButtons()
{
    const bool selected = currentClass().has_value();
    m_colour->setEnabled(selected);
    m_remove->setEnabled(selected);
}

void LegendWidget::retranslateUi()
{
    m_tree->setHeaderLabels({tr("Class"), tr("Hatch"), tr("Cells"), tr("Area (m²)")});
    m_add->setText(tr("Add"));
    m_add->setToolTip(tr("Add a class to the layer of the selected row"));
    m_colour->setText(tr("Colour…"));
    m_colour->setToolTip(tr("Change the colour of the selected class"));
    m_remove->setText(tr("Delete…"));
    m_remove->setToolTip(tr("Delete the selected class (its cells are unlabelled or moved to another class)"));
    m_tree->setToolTip(tr("Click a class to paint it; double-click its name to rename it"));
    rebuild();
}

void LegendWidget::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) retranslateUi();
    QWidget::changeEvent(event);
}

} // namespace stylos::widgets
