#include "stylos/widgets/docking/AxisGuideEditor.h"

#include "stylos/core/scene/SceneEigen.h"
#include "stylos/widgets/docking/AxisPickTool.h"
#include "stylos/widgets/docking/EditAxisDialog.h"
#include "stylos/widgets/view3d/ViewportWidget.h"

#include <QLocale>
#include <QTimer>

#include <algorithm>
#include <cmath>

namespace stylos::widgets {

AxisGuideEditor::AxisGuideEditor(SceneDocument& document, ViewportWidget* view, QObject* parent)
    : QObject(parent), m_document(document), m_view(view)
{
    connect(&document, &SceneDocument::fragmentRemoved, this, [this](quint64 id) {
        if (m_tool && isPicking() && m_tool->fragment() == id) cancelPicking();
    });
    connect(&document, &SceneDocument::sceneReset, this, [this] {
        if (isPicking()) cancelPicking();
    });
}

std::vector<core::scene::Guide> AxisGuideEditor::withAxis(std::vector<core::scene::Guide> guides,
                                                          const Eigen::Vector3d& origin, const Eigen::Vector3d& direction)
{
    const auto axis = std::find_if(guides.begin(), guides.end(),
                                   [](const core::scene::Guide& g) { return g.kind == core::scene::GuideKind::Axis; });
    core::scene::Guide guide{"Axis", core::scene::GuideKind::Axis, core::scene::toArray(origin), core::scene::toArray(direction)};
    if (axis != guides.end()) {
        guide.name = axis->name;
        *axis = guide;
    } else {
        guides.insert(guides.begin(), guide);
    }
    return guides;
}

bool AxisGuideEditor::setAxis(FragmentId id, const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                              const QString& commandText)
{
    const core::scene::Fragment* f = m_document.fragment(id);
    const double length = direction.norm();
    if (!f || !(std::isfinite(length) && length > 1e-9) || !origin.allFinite()) return false;
    return m_document.setFragmentGuides(id, withAxis(f->guides, origin, direction / length), commandText);
}

bool AxisGuideEditor::startPicking(FragmentId id)
{
    const core::scene::Fragment* f = m_document.fragment(id);
    if (!m_view || !f) return false;
    auto tool = std::make_unique<AxisPickTool>(
        id, [this](quint64 fragment, const Eigen::Vector3d& a, const Eigen::Vector3d& b) { picked(fragment, a, b); },
        [this] {
            Q_EMIT reported(tr("Set axis cancelled"), false);
            endPickingLater();
        });
    m_tool = tool.get();
    m_view->setTool(std::move(tool));
    Q_EMIT reported(tr("Click two points on %1 for its axis (Escape cancels)").arg(QString::fromStdString(f->name)), false);
    Q_EMIT pickingChanged(true);
    return true;
}

bool AxisGuideEditor::isPicking() const { return m_view && m_tool && m_view->tool() == m_tool; }

void AxisGuideEditor::cancelPicking()
{
    if (!isPicking()) return;
    m_view->resetTool();
    m_tool = nullptr;
    Q_EMIT pickingChanged(false);
}

void AxisGuideEditor::endPickingLater()
{
    QTimer::singleShot(0, this, &AxisGuideEditor::cancelPicking);
}

void AxisGuideEditor::picked(FragmentId id, const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
    endPickingLater();
    const core::scene::Fragment* f = m_document.fragment(id);
    if (!f) return;
    const core::scene::Pose toLocal = m_document.worldPose(id).rigidInverse();
    const Eigen::Vector3d p = core::scene::apply(toLocal, a), q = core::scene::apply(toLocal, b);
    const QString name = QString::fromStdString(f->name);
    if (!((q - p).norm() > 1e-6)) {
        Q_EMIT reported(tr("The two points picked on %1 are the same: pick two points apart along its axis").arg(name), true);
        return;
    }
    if (setAxis(id, p, q - p, tr("Set the axis of %1 from two points").arg(name)))
        Q_EMIT reported(tr("Axis of %1 set through the two points picked, %2 mm apart").arg(name).arg(QLocale().toString((q - p).norm() * 1e3, 'f', 1)),
                        false);
}

bool AxisGuideEditor::reverseAxis(FragmentId id)
{
    const core::scene::Fragment* f = m_document.fragment(id);
    const auto line = f ? core::scene::firstGuide(*f, core::scene::GuideKind::Axis) : std::nullopt;
    if (!line) return false;
    const QString name = QString::fromStdString(f->name);
    if (!setAxis(id, line->origin, -line->direction, tr("Reverse the axis of %1").arg(name))) return false;
    Q_EMIT reported(tr("The axis of %1 now points the other way: its développée turns upside down").arg(name), false);
    return true;
}

EditAxisDialog* AxisGuideEditor::editAxis(FragmentId id, QWidget* parent)
{
    const core::scene::Fragment* f = m_document.fragment(id);
    if (!f) return nullptr;
    Eigen::Vector3d origin = Eigen::Vector3d::Zero(), direction = Eigen::Vector3d::UnitZ();
    if (const auto line = core::scene::firstGuide(*f, core::scene::GuideKind::Axis)) {
        origin = line->origin;
        direction = line->direction;
    }
    auto* dialog = new EditAxisDialog(origin, direction, parent);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    const QString name = QString::fromStdString(f->name);
    dialog->setWindowTitle(tr("Edit the axis of %1").arg(name));
    connect(dialog, &QDialog::accepted, this, [this, id, dialog, name] {
        setAxis(id, dialog->point(), dialog->direction(), tr("Edit the axis of %1").arg(name));
    });
    dialog->open();
    return dialog;
}

} // namespace stylos::widgets
