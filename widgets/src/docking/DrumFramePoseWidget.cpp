#include "stylos/widgets/docking/DrumFramePoseWidget.h"

#include "docking/FragmentBounds.h"
#include "stylos/widgets/util/NumberSpinBox.h"
#include "stylos/core/dock/DrumFramePose.h"
#include "stylos/core/scene/SceneEigen.h"

#include <QDoubleSpinBox>
#include <QEvent>
#include <QFormLayout>
#include <QLabel>

#include <numbers>

namespace stylos::widgets {

namespace {

constexpr double DegreesPerRadian = 180.0 / std::numbers::pi;

/** The value of @p field in @p pose (metres, radians): the docking unknowns and the spin, which with them fixes
 *  the fragment's orientation. */
double valueOf(const core::dock::DrumFramePose& pose, DrumFramePoseWidget::Field field)
{
    using core::dock::DockUnknown;
    switch (field) {
    case DrumFramePoseWidget::Theta: return pose.theta;
    case DrumFramePoseWidget::Z: return pose.z;
    case DrumFramePoseWidget::R: return pose.r;
    case DrumFramePoseWidget::TiltLean: return pose.tiltLean;
    case DrumFramePoseWidget::TiltRoll: return pose.tiltRoll;
    case DrumFramePoseWidget::Spin: return pose.spin;
    }
    return 0.0;
}

void setValue(core::dock::DrumFramePose& pose, DrumFramePoseWidget::Field field, double value)
{
    switch (field) {
    case DrumFramePoseWidget::Theta: pose.theta = value; break;
    case DrumFramePoseWidget::Z: pose.z = value; break;
    case DrumFramePoseWidget::R: pose.r = value; break;
    case DrumFramePoseWidget::TiltLean: pose.tiltLean = value; break;
    case DrumFramePoseWidget::TiltRoll: pose.tiltRoll = value; break;
    case DrumFramePoseWidget::Spin: pose.spin = value; break;
    }
}

bool isAngle(DrumFramePoseWidget::Field field) { return field != DrumFramePoseWidget::Z && field != DrumFramePoseWidget::R; }

/** Shown value per model value: degrees for angles, millimetres for lengths. */
double displayScale(DrumFramePoseWidget::Field field) { return isAngle(field) ? DegreesPerRadian : 1e3; }

} // namespace

struct DrumFramePoseWidget::Placement {
    core::dock::DrumFrame frame;
    Eigen::Isometry3d drumWorld = Eigen::Isometry3d::Identity();
    Eigen::Isometry3d relative = Eigen::Isometry3d::Identity(); ///< fragment frame → drum file frame
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();           ///< the fragment's, its own frame
};

DrumFramePoseWidget::DrumFramePoseWidget(SceneDocument& document, QWidget* parent)
    : QWidget(parent), m_document(document), m_bounds(std::make_unique<FragmentBounds>()), m_form(new QFormLayout(this)),
      m_status(new QLabel(this))
{
    setObjectName(QStringLiteral("drumFramePose"));
    m_form->setContentsMargins(0, 0, 0, 0);
    m_status->setWordWrap(true);
    m_status->setObjectName(QStringLiteral("drumFrameStatus"));
    m_form->addRow(m_status);
    for (int i = 0; i < FieldCount; ++i) {
        const auto field = Field(i);
        auto* spin = new NumberSpinBox(this);
        spin->setObjectName(QStringLiteral("drumFrame%1").arg(i));
        spin->setKeyboardTracking(false); // one edit per Enter, arrow step or focus change
        if (isAngle(field)) {
            spin->setRange(-180.0, 180.0);
            spin->setDecimals(3);
            spin->setWrapping(field == Theta || field == Spin);
            spin->setSuffix(QStringLiteral("°"));
        } else {
            spin->setRange(field == R ? 0.0 : -1e7, 1e7);
            spin->setDecimals(2);
            spin->setSuffix(QStringLiteral(" mm"));
        }
        connect(spin, &QDoubleSpinBox::valueChanged, this, [this, field] { apply(field); });
        m_fields[std::size_t(i)] = spin;
        m_labels[std::size_t(i)] = new QLabel(this);
        m_form->addRow(m_labels[std::size_t(i)], spin);
    }
    for (auto signal : {&SceneDocument::fragmentChanged, &SceneDocument::octreeChanged, &SceneDocument::fragmentRemoved,
                        &SceneDocument::dockingDrumChanged, &SceneDocument::assemblyChanged})
        connect(&document, signal, this, &DrumFramePoseWidget::refresh);
    connect(&document, &SceneDocument::structureChanged, this, &DrumFramePoseWidget::refresh);
    connect(&document, &SceneDocument::sceneReset, this, &DrumFramePoseWidget::refresh);
    retranslateUi();
}

DrumFramePoseWidget::~DrumFramePoseWidget() = default;

void DrumFramePoseWidget::setFragment(FragmentId id)
{
    m_id = id;
    refresh();
}

void DrumFramePoseWidget::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) retranslateUi();
    QWidget::changeEvent(event);
}

void DrumFramePoseWidget::retranslateUi()
{
    m_labels[Theta]->setText(tr("θ about the axis:"));
    m_labels[Z]->setText(tr("z along the axis:"));
    m_labels[R]->setText(tr("r from the axis:"));
    m_labels[TiltLean]->setText(tr("Lean:"));
    m_labels[TiltRoll]->setText(tr("Roll:"));
    m_labels[Spin]->setText(tr("Spin:"));
    m_fields[Theta]->setToolTip(tr("Azimuth of the fragment's centre about the drum axis, from the drum's reference "
                                   "direction (as in its développée); typing turns the fragment about the axis"));
    m_fields[Z]->setToolTip(tr("Height of the fragment's centre along the drum axis, from the axis guide's point"));
    m_fields[R]->setToolTip(tr("Distance of the fragment's centre from the drum axis"));
    m_fields[TiltLean]->setToolTip(tr("Turn about the tangent through the fragment's centre (leans it in or out)"));
    m_fields[TiltRoll]->setToolTip(tr("Turn about the radial direction through the fragment's centre (turns its "
                                      "flutes sideways)"));
    m_fields[Spin]->setToolTip(tr("Turn about the line through the fragment's centre parallel to the axis; with θ "
                                  "and the tilts it fixes the orientation. The tilts and the spin are measured from "
                                  "the fragment's frame as scanned"));
    refresh();
}

bool DrumFramePoseWidget::placement(Placement& out)
{
    const core::scene::Fragment* f = m_document.fragment(m_id);
    if (!f) return false;
    const FragmentId drumId = m_document.drumFor(m_id);
    const core::scene::Fragment* drum = drumId != m_id ? m_document.fragment(drumId) : nullptr;
    const auto axis = drum ? core::scene::firstGuide(*drum, core::scene::GuideKind::Axis) : std::nullopt;
    if (!axis || !(axis->direction.norm() > 0.0)) return false;
    const Eigen::AlignedBox3d bounds = m_bounds->of(m_document, m_id);
    if (bounds.isEmpty()) return false;
    out.frame = core::dock::DrumFrame(core::unroll::Axis{axis->origin, axis->direction.normalized()});
    out.drumWorld = Eigen::Isometry3d(core::scene::toEigen(m_document.worldPose(drumId)));
    out.relative = out.drumWorld.inverse() * Eigen::Isometry3d(core::scene::toEigen(m_document.worldPose(m_id)));
    out.centre = bounds.center();
    return true;
}

void DrumFramePoseWidget::refresh()
{
    Placement p;
    m_available = placement(p);
    m_updating = true;
    for (QDoubleSpinBox* spin : m_fields) spin->setEnabled(m_available);
    if (!m_available) {
        const bool isDrum = m_id != core::scene::NoFragment && m_document.drumFor(m_id) == m_id;
        m_status->setText(!m_document.fragment(m_id) ? tr("No fragment selected.")
                          : isDrum ? tr("This is the drum the others are placed against: select one of them.")
                                   : tr("This fragment has no drum with an axis guide (put it in an assembly with a drum, "
                                        "or Tools › Dock against this drum), or its octree is not open yet."));
        for (QDoubleSpinBox* spin : m_fields) spin->setValue(0.0);
        m_updating = false;
        return;
    }
    const FragmentId drumId = m_document.drumFor(m_id);
    m_status->setText(tr("In the frame of %1:").arg(QString::fromStdString(m_document.fragment(drumId)->name)));
    const core::dock::DrumFramePose value = core::dock::drumFramePose(p.frame, p.relative, p.centre);
    for (int i = 0; i < FieldCount; ++i)
        m_fields[std::size_t(i)]->setValue(valueOf(value, Field(i)) * displayScale(Field(i)));
    m_updating = false;
}

void DrumFramePoseWidget::apply(Field field)
{
    if (m_updating) return;
    Placement p;
    if (!placement(p)) return;
    // Only the edited value changes; the others keep their exact values, not the spin boxes' rounding.
    core::dock::DrumFramePose value = core::dock::drumFramePose(p.frame, p.relative, p.centre);
    setValue(value, field, m_fields[std::size_t(field)]->value() / displayScale(field));
    const Eigen::Isometry3d world = p.drumWorld * core::dock::placeInDrumFrame(p.frame, value, p.centre);
    m_document.setFragmentWorldPose(m_id, core::scene::poseFromEigen(world.matrix()));
}

} // namespace stylos::widgets
