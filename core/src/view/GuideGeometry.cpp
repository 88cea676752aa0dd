#include "stylos/core/view/GuideGeometry.h"

#include "stylos/core/scene/SceneEigen.h"

#include <algorithm>
#include <limits>
#include <numbers>

namespace stylos::core::view {

std::optional<DrumAxis> drumAxisOf(const scene::Fragment& drum, const scene::Pose* world)
{
    const auto axis = scene::firstGuide(drum, scene::GuideKind::Axis);
    if (!axis) return std::nullopt;
    const Eigen::Matrix4d pose = scene::toEigen(world ? *world : drum.pose);
    DrumAxis result;
    result.point = pose.topLeftCorner<3, 3>() * axis->origin + pose.topRightCorner<3, 1>();
    result.direction = (pose.topLeftCorner<3, 3>() * axis->direction).normalized();
    const auto grooves = std::count_if(drum.guides.begin(), drum.guides.end(),
                                       [](const scene::Guide& g) { return g.kind == scene::GuideKind::Groove; });
    result.pitch = grooves > 0 ? 2 * std::numbers::pi / double(grooves) : 0.0;
    return result;
}

std::vector<GuideSegment> guideSegments(const scene::Fragment& fragment, const Eigen::AlignedBox3d& localBounds,
                                        const scene::Pose* world)
{
    std::vector<GuideSegment> segments;
    if (localBounds.isEmpty()) return segments;
    const Eigen::Matrix4d pose = scene::toEigen(world ? *world : fragment.pose);
    const auto toScene = [&pose](const Eigen::Vector3d& p) -> Eigen::Vector3d {
        return pose.topLeftCorner<3, 3>() * p + pose.topRightCorner<3, 1>();
    };
    segments.reserve(fragment.guides.size());
    for (const scene::Guide& guide : fragment.guides) {
        const scene::GuideLine line = scene::guideLine(guide);
        const Eigen::Vector3d d = line.direction.normalized();
        double low = std::numeric_limits<double>::infinity(), high = -low;
        for (int corner = 0; corner < 8; ++corner) {
            const double s = (localBounds.corner(Eigen::AlignedBox3d::CornerType(corner)) - line.origin).dot(d);
            low = std::min(low, s);
            high = std::max(high, s);
        }
        segments.push_back({toScene(line.origin + low * d), toScene(line.origin + high * d), guide.kind});
    }
    return segments;
}

Eigen::AlignedBox3d occupiedBounds(const octree::PackedOctree& octree, int level)
{
    Eigen::AlignedBox3d box;
    octree.forEachCell(std::clamp(level, 0, octree.depth()), [&box](const octree::CellView& cell) {
        const Eigen::Vector3d c = scene::toEigen(cell.centre);
        const Eigen::Vector3d half = Eigen::Vector3d::Constant(cell.size / 2);
        box.extend(c - half);
        box.extend(c + half);
        return true;
    });
    return box;
}

} // namespace stylos::core::view
