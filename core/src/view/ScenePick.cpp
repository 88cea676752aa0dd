#include "stylos/core/view/ScenePick.h"

#include "stylos/core/scene/SceneEigen.h"

#include "stylos/core/octree/CellPick.h"

#include <algorithm>

namespace stylos::core::view {

namespace {

constexpr int BoundsLevel = 5; ///< cells of this level bound a fragment (at most 32 Ki of them)

Eigen::AlignedBox3d fragmentBounds(const ViewFragment& f)
{
    Eigen::AlignedBox3d box;
    if (!f.octree) return box;
    const Eigen::Matrix3d r = f.pose.topLeftCorner<3, 3>();
    const Eigen::Vector3d t = f.pose.topRightCorner<3, 1>();
    f.octree->forEachCell(std::min(BoundsLevel, f.octree->depth()), [&](const octree::CellView& cell) {
        const Eigen::Vector3d c = r * scene::toEigen(cell.centre) + t;
        const Eigen::Vector3d half = Eigen::Vector3d::Constant(0.8660254037844386 * cell.size); // any rotation
        box.extend(c - half);
        box.extend(c + half);
        return true;
    });
    return box;
}

} // namespace

Eigen::AlignedBox3d sceneBounds(const std::vector<ViewFragment>& fragments, bool selectedOnly)
{
    Eigen::AlignedBox3d box;
    for (const ViewFragment& f : fragments)
        if (f.visible && (!selectedOnly || f.selected)) box.extend(fragmentBounds(f));
    return box;
}

std::vector<Eigen::Vector3d> sceneCorners(const std::vector<ViewFragment>& fragments, bool selectedOnly)
{
    std::vector<Eigen::Vector3d> corners;
    for (const ViewFragment& f : fragments) {
        if (!f.visible || !f.octree || (selectedOnly && !f.selected)) continue;
        const Eigen::Matrix3d r = f.pose.topLeftCorner<3, 3>();
        const Eigen::Vector3d t = f.pose.topRightCorner<3, 1>();
        f.octree->forEachCell(std::min(BoundsLevel, f.octree->depth()), [&](const octree::CellView& cell) {
            const Eigen::AlignedBox3d box(scene::toEigen(cell.centre) - Eigen::Vector3d::Constant(cell.size / 2),
                                          scene::toEigen(cell.centre) + Eigen::Vector3d::Constant(cell.size / 2));
            for (int k = 0; k < 8; ++k) corners.push_back(r * box.corner(Eigen::AlignedBox3d::CornerType(k)) + t);
            return true;
        });
    }
    return corners;
}

std::optional<ScenePick> pickScene(const std::vector<ViewFragment>& fragments, const Camera& camera, double x,
                                   double y, double radiusPixels)
{
    const Ray ray = camera.rayAt(x, y);
    double radiusAtOrigin = 0, radiusPerMetre = 0;
    if (camera.isOrthographic()) radiusAtOrigin = radiusPixels / camera.pixelsPerMetre();
    else radiusPerMetre = radiusPixels / (camera.pixelsPerMetre() * camera.distance()); // per metre of depth
    std::optional<ScenePick> best;
    for (const ViewFragment& f : fragments) {
        if (!f.visible || !f.octree) continue;
        const Eigen::Matrix3d r = f.pose.topLeftCorner<3, 3>();
        const Eigen::Vector3d t = f.pose.topRightCorner<3, 1>();
        const Eigen::Vector3d o = r.transpose() * (ray.origin - t), d = r.transpose() * ray.direction;
        const auto hit = octree::pickRay(*f.octree, {o.x(), o.y(), o.z()}, {d.x(), d.y(), d.z()},
                                               radiusAtOrigin, radiusPerMetre);
        if (!hit) continue;
        const Eigen::Vector3d point = r * scene::toEigen(hit->cell.centre) + t;
        const double along = (point - ray.origin).dot(ray.direction);
        if (!best || along < best->along) best = ScenePick{point, f.id, hit->cell.size, along};
    }
    return best;
}

} // namespace stylos::core::view
