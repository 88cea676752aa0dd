#include "stylos/widgets/document/FragmentPropertiesWidget.h"

#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/scene/SceneEigen.h"
#include "stylos/core/view/GuideGeometry.h"
#include "stylos/widgets/document/SceneDocument.h"

#include "docking/FragmentBounds.h"
#include "stylos/widgets/util/NumberSpinBox.h"

#include <QCheckBox>
#include <QColorDialog>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>

#include <cmath>
#include <limits>
#include <numbers>

namespace stylos::widgets {

namespace {

using core::scene::Fragment;

constexpr double DegreesPerRadian = 180.0 / std::numbers::pi;

QDoubleSpinBox* makeSpin(QWidget* parent, bool angle)
{
    auto* spin = new NumberSpinBox(parent);
    spin->setKeyboardTracking(false); // one edit per Enter, arrow step or focus change
    if (angle) {
        spin->setRange(-180.0, 180.0);
        spin->setDecimals(3);
        spin->setWrapping(true);
        spin->setSuffix(QStringLiteral("°"));
    } else {
        spin->setRange(-1e7, 1e7);
        spin->setDecimals(4); // 0.1 mm
        spin->setSingleStep(0.001);
        spin->setSuffix(QStringLiteral(" m"));
    }
    return spin;
}

/** "x × y × z mm" (one decimal) for @p size in metres, "x × y × z m" (three decimals) from 10 m. */
QString sizeText(const Eigen::Vector3d& size, const QLocale& locale)
{
    if (!(size.minCoeff() >= 0.0)) return QStringLiteral("–"); // an octree without cells
    const bool metres = size.maxCoeff() >= 10.0;
    const double scale = metres ? 1.0 : 1000.0;
    const int decimals = metres ? 3 : 1;
    const auto number = [&](double v) { return locale.toString(v * scale, 'f', decimals); };
    return QStringLiteral("%1 × %2 × %3 %4")
        .arg(number(size.x()), number(size.y()), number(size.z()),
             metres ? QStringLiteral("m") : QStringLiteral("mm"));
}

} // namespace

FragmentPropertiesWidget::FragmentPropertiesWidget(SceneDocument& document, QWidget* parent)
    : QWidget(parent), m_document(document), m_form(new QFormLayout(this)), m_name(new QLineEdit(this)),
      m_visible(new QCheckBox(this)), m_colour(new QPushButton(this)), m_size(new QLabel(this)),
      m_points(new QLabel(this)), m_leafCells(new QLabel(this)), m_totalCells(new QLabel(this)),
      m_depth(new QLabel(this)), m_imported(new QLabel(this)), m_file(new QLabel(this)),
      m_centres(std::make_unique<FragmentBounds>()),
      m_leaves(std::make_unique<FragmentBounds>(std::numeric_limits<int>::max()))
{
    setObjectName(QStringLiteral("FragmentPropertiesWidget"));
    m_name->setObjectName(QStringLiteral("fragmentName"));
    m_visible->setObjectName(QStringLiteral("fragmentVisible"));
    m_colour->setObjectName(QStringLiteral("fragmentColour"));
    m_imported->setObjectName(QStringLiteral("fragmentImported"));
    m_size->setObjectName(QStringLiteral("fragmentSize"));
    m_size->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_size->setWordWrap(true); // "460.5 × 482.7 × 387.7 mm" breaks at a space in a narrow dock rather than being cut
    m_imported->setWordWrap(true);
    m_file->setWordWrap(true);
    m_file->setTextInteractionFlags(Qt::TextSelectableByMouse);
    for (int i = 0; i < 6; ++i) {
        m_pose[static_cast<std::size_t>(i)] = makeSpin(this, i >= 3);
        m_pose[static_cast<std::size_t>(i)]->setObjectName(QStringLiteral("fragmentPose%1").arg(i));
        connect(m_pose[static_cast<std::size_t>(i)], &QDoubleSpinBox::valueChanged, this, [this, i] { applyPose(i); });
    }
    QWidget* fields[RowCount] = {m_name,     m_visible,  m_colour,    m_pose[0], m_pose[1], m_pose[2],
                                 m_pose[3],  m_pose[4],  m_pose[5],   m_size,    m_points,  m_leafCells,
                                 m_totalCells, m_depth, m_imported, m_file};
    // Labels beside their fields while the dock is wide enough, above them when it is not (the longer
    // French and Greek labels): each field keeps its full width.
    m_form->setRowWrapPolicy(QFormLayout::WrapLongRows);
    m_form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    for (std::size_t row = 0; row < RowCount; ++row) {
        m_labels[row] = new QLabel(this);
        m_labels[row]->setBuddy(fields[row]);
        m_form->addRow(m_labels[row], fields[row]);
    }

    connect(m_name, &QLineEdit::editingFinished, this, &FragmentPropertiesWidget::applyName);
    connect(m_visible, &QCheckBox::toggled, this, [this](bool on) {
        if (!m_updating) m_document.setFragmentVisible(m_id, on);
    });
    connect(m_colour, &QPushButton::clicked, this, &FragmentPropertiesWidget::chooseColour);
    connect(&m_document, &SceneDocument::fragmentChanged, this, [this](quint64 id) {
        if (id == m_id) refresh();
    });
    connect(&m_document, &SceneDocument::octreeChanged, this, [this](quint64 id) {
        if (id == m_id) refresh();
    });
    connect(&m_document, &SceneDocument::fragmentRemoved, this, [this](quint64 id) {
        m_centres->forget(id); // its octree is not held open here
        m_leaves->forget(id);
        if (id == m_id) setFragment(core::scene::NoFragment);
    });
    connect(&m_document, &SceneDocument::sceneReset, this, [this] {
        m_centres->clear();
        m_leaves->clear();
        setFragment(core::scene::NoFragment);
    });
    retranslateUi();
    refresh();
}

FragmentPropertiesWidget::~FragmentPropertiesWidget() = default;

void FragmentPropertiesWidget::setFragment(core::scene::FragmentId id)
{
    m_id = m_document.fragment(id) ? id : core::scene::NoFragment;
    refresh();
}

void FragmentPropertiesWidget::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) retranslateUi();
    QWidget::changeEvent(event);
}

void FragmentPropertiesWidget::retranslateUi()
{
    const QString labels[RowCount] = {tr("Name"),        tr("Visible"),    tr("Colour"),      tr("X"),
                              tr("Y"),           tr("Z"),          tr("Rotation X"),  tr("Rotation Y"),
                              tr("Rotation Z"),  tr("Size"),       tr("Points"),      tr("Leaf cells"),
                              tr("Total cells"), tr("Depth"),      tr("Imported as"), tr("File")};
    for (std::size_t row = 0; row < RowCount; ++row) m_labels[row]->setText(labels[row]);
    m_visible->setText(tr("Shown in the 3D view"));
    m_colour->setToolTip(tr("Choose the fragment's display colour"));
    m_pose[0]->setToolTip(tr("Translation along the scene's x axis, in metres"));
    m_pose[3]->setToolTip(tr("Rotation about the x axis, applied first, in degrees"));
    m_size->setToolTip(tr("Extent of the fragment's leaf cells along its own x, y and z axes (its scan's frame, "
                          "z up), whatever its pose"));
    refresh();
}

void FragmentPropertiesWidget::refresh()
{
    const Fragment* f = m_document.fragment(m_id);
    m_updating = true;
    for (QWidget* w : {static_cast<QWidget*>(m_name), static_cast<QWidget*>(m_visible), static_cast<QWidget*>(m_colour)})
        w->setEnabled(f != nullptr);
    // The rotations turn the fragment about its centre, which its octree gives: off until it is open.
    for (std::size_t i = 0; i < m_pose.size(); ++i) m_pose[i]->setEnabled(f && (i < 3 || m_document.octree(m_id)));
    const QLocale locale;
    const QString none = QStringLiteral("–");
    if (!f) {
        m_name->clear();
        m_visible->setChecked(false);
        m_colour->setText(QString());
        m_colour->setStyleSheet(QString());
        for (QDoubleSpinBox* spin : m_pose) spin->setValue(0.0);
        for (QLabel* label : {m_size, m_points, m_leafCells, m_totalCells, m_depth, m_imported, m_file})
            label->setText(none);
        m_updating = false;
        return;
    }
    if (!m_name->hasFocus() || m_name->text() != QString::fromStdString(f->name))
        m_name->setText(QString::fromStdString(f->name));
    m_visible->setChecked(f->visible);
    const QString hex = QString::fromStdString(f->colour.toHex());
    m_colour->setText(hex);
    m_colour->setStyleSheet(QStringLiteral("QPushButton { background-color: %1; }").arg(hex));
    const auto value = f->pose.toTranslationAngles();
    for (int i = 0; i < 3; ++i) {
        m_pose[static_cast<std::size_t>(i)]->setValue(value.translation[static_cast<std::size_t>(i)]);
        m_pose[static_cast<std::size_t>(3 + i)]->setValue(value.angles[static_cast<std::size_t>(i)] * DegreesPerRadian);
    }
    const auto octree = m_document.octree(m_id);
    if (octree) {
        m_points->setText(locale.toString(static_cast<qulonglong>(octree->description().points)));
        m_leafCells->setText(locale.toString(static_cast<qulonglong>(octree->cellCount(octree->depth()))));
        m_totalCells->setText(locale.toString(static_cast<qulonglong>(octree->totalCells())));
        m_depth->setText(locale.toString(octree->depth()));
        m_size->setText(sizeText(m_leaves->of(m_document, m_id).sizes(), locale));
    } else {
        const QString state = f->octreeMissing ? tr("missing") : tr("opening…");
        for (QLabel* label : {m_size, m_points, m_leafCells, m_totalCells, m_depth}) label->setText(state);
    }
    // The frame the scan was read in (Z up, metres from the file's up axis and unit), as the project keeps it.
    const core::io::ImportFrame& frame = f->importFrame;
    QString imported = tr("%1 up, in %2")
                           .arg(QString::fromLatin1(core::io::upAxisName(frame.up)),
                                QString::fromLatin1(core::io::lengthUnitName(frame.unit)));
    if (frame.offset != std::array<double, 3>{0.0, 0.0, 0.0})
        imported += QLatin1Char('\n') + tr("offset %1, %2, %3")
                                           .arg(locale.toString(frame.offset[0], 'g', 12),
                                                locale.toString(frame.offset[1], 'g', 12),
                                                locale.toString(frame.offset[2], 'g', 12));
    m_imported->setText(imported);
    m_file->setText(QString::fromStdString(f->octreePath.string()));
    m_updating = false;
}

void FragmentPropertiesWidget::applyName()
{
    if (m_updating) return;
    const QString name = m_name->text().trimmed();
    const Fragment* f = m_document.fragment(m_id);
    if (!f) return;
    if (name.isEmpty()) {
        m_name->setText(QString::fromStdString(f->name)); // a fragment keeps a name
        return;
    }
    m_document.renameFragment(m_id, name);
}

void FragmentPropertiesWidget::applyPose(int component)
{
    if (m_updating) return;
    const Fragment* f = m_document.fragment(m_id);
    if (!f) return;
    // Only the edited component changes; the others keep their exact values, not the spin boxes' rounding.
    core::scene::Pose pose = f->pose;
    const double value = m_pose[static_cast<std::size_t>(component)]->value();
    if (component < 3) {
        auto t = pose.translationPart();
        t[static_cast<std::size_t>(component)] = value;
        pose = pose.withTranslation(t);
    } else {
        auto angles = pose.toTranslationAngles().angles;
        angles[static_cast<std::size_t>(component - 3)] = value / DegreesPerRadian;
        const core::scene::Pose turned = pose.withAngles(angles);
        pose = turned;
        // About the fragment's centre, as the gizmo turns it, not about its file frame's origin: a scan in site
        // coordinates lies kilometres from that origin, and 1° swung it tens of metres away. The translation follows.
        if (!m_document.octree(m_id)) return; // not open yet: no centre to turn about (the fields are off then)
        const Eigen::AlignedBox3d box = m_centres->of(m_document, m_id);
        if (!box.isEmpty()) {
            using core::scene::apply;
            const Eigen::Vector3d centre = box.center();
            const Eigen::Vector3d shift = apply(f->pose, centre) - apply(turned, centre);
            pose = turned.withTranslation(core::scene::toArray(core::scene::toEigen(turned.translationPart()) + shift));
        }
    }
    m_document.setFragmentPose(m_id, pose);
}

void FragmentPropertiesWidget::chooseColour()
{
    const Fragment* f = m_document.fragment(m_id);
    if (!f) return;
    const QColor chosen = QColorDialog::getColor(QColor(f->colour.r, f->colour.g, f->colour.b), this, tr("Fragment colour"));
    if (!chosen.isValid()) return;
    m_document.setFragmentColour(m_id, core::scene::Rgb{static_cast<std::uint8_t>(chosen.red()),
                                                       static_cast<std::uint8_t>(chosen.green()),
                                                       static_cast<std::uint8_t>(chosen.blue())});
}

} // namespace stylos::widgets
