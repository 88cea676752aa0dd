#include "stylos/core/scene/ImportPlacement.h"

#include "stylos/core/scene/SceneEigen.h"

#include <algorithm>
#include <cmath>

namespace stylos::core::scene {

namespace {

bool inSiteFrame(const Eigen::AlignedBox3d& box) { return box.center().norm() >= SiteDistance; }

/** The gap between two boxes (0 when they touch or overlap). */
double gapBetween(const Eigen::AlignedBox3d& a, const Eigen::AlignedBox3d& b)
{
    const Eigen::Vector3d apart = (a.min() - b.max()).cwiseMax(b.min() - a.max()).cwiseMax(0.0);
    return apart.norm();
}

} // namespace

Eigen::AlignedBox3d worldBounds(const PlacedExtent& extent)
{
    Eigen::AlignedBox3d box;
    if (extent.local.isEmpty()) return box;
    const Eigen::Matrix4d m = toEigen(extent.world);
    for (int k = 0; k < 8; ++k) {
        const Eigen::Vector3d c = extent.local.corner(Eigen::AlignedBox3d::CornerType(k));
        box.extend((m * c.homogeneous()).head<3>());
    }
    return box;
}

Pose placeImport(const std::vector<PlacedExtent>& placed, const Eigen::AlignedBox3d& incoming)
{
    if (incoming.isEmpty()) return {};
    Eigen::AlignedBox3d scene;
    for (const PlacedExtent& p : placed) scene.extend(worldBounds(p));

    // The same site frame: beside a fragment within the larger of the two diagonals, in file coordinates.
    if (inSiteFrame(incoming))
        for (const PlacedExtent& p : placed)
            if (!p.local.isEmpty() && inSiteFrame(p.local) &&
                gapBetween(p.local, incoming) <= std::max(p.local.diagonal().norm(), incoming.diagonal().norm()))
                return p.world;

    if (scene.isEmpty()) {
        if (!inSiteFrame(incoming)) return {};
        const Eigen::Vector3d c = incoming.center();
        return Pose::translation({-std::round(c.x()), -std::round(c.y()), -std::round(c.z())});
    }

    const double gap = 0.25 * std::max(scene.sizes().maxCoeff(), incoming.sizes().maxCoeff());
    const Eigen::Vector3d to(scene.max().x() + gap + 0.5 * incoming.sizes().x(), scene.center().y(),
                             scene.min().z() + 0.5 * incoming.sizes().z());
    const Eigen::Vector3d shift = to - incoming.center();
    return Pose::translation({shift.x(), shift.y(), shift.z()});
}

} // namespace stylos::core::scene
