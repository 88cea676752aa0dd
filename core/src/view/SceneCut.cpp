#include "stylos/core/view/SceneCut.h"

#include "stylos/core/view/BudgetShare.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>

namespace stylos::core::view {

namespace oct = octree;

namespace {

/** True when the octree's root box lies entirely outside one clip plane of @p camera. */
bool boxOutsideView(const oct::RootBox& box, const oct::CutCamera& camera)
{
    Eigen::Map<const Eigen::Matrix4d> vp(camera.viewProjection.data());
    std::array<int, 6> outside{};
    for (int corner = 0; corner < 8; ++corner) {
        const Eigen::Vector4d p(box.origin[0] + ((corner & 1) ? box.size : 0.0),
                                box.origin[1] + ((corner & 2) ? box.size : 0.0),
                                box.origin[2] + ((corner & 4) ? box.size : 0.0), 1.0);
        const Eigen::Vector4d c = vp * p;
        for (int axis = 0; axis < 3; ++axis) {
            outside[2 * axis] += c[axis] < -c.w() ? 1 : 0;
            outside[2 * axis + 1] += c[axis] > c.w() ? 1 : 0;
        }
    }
    return std::any_of(outside.begin(), outside.end(), [](int n) { return n == 8; });
}

/** Cells the octree needs at the threshold: the count of the level whose cells project to ~threshold. */
double estimateDemand(const oct::PackedOctree& octree, const oct::CutCamera& camera, double threshold)
{
    const oct::RootBox& box = octree.box();
    if (camera.cullToFrustum && boxOutsideView(box, camera)) return 0;
    double projected = 0;
    if (camera.orthographic) {
        projected = box.size * camera.pixelsPerMetre;
    } else {
        const Eigen::Vector3d centre(box.origin[0] + 0.5 * box.size, box.origin[1] + 0.5 * box.size,
                                     box.origin[2] + 0.5 * box.size);
        const double distance = (centre - Eigen::Vector3d(camera.eye[0], camera.eye[1], camera.eye[2])).norm();
        projected = box.size * camera.pixelsPerRadian / std::max(distance, 0.5 * box.size);
    }
    int level = octree.depth();
    if (threshold > 0) level = std::clamp(int(std::ceil(std::log2(std::max(projected / threshold, 1.0)))), 0, octree.depth());
    return double(std::max<std::uint64_t>(octree.cellCount(level), 1));
}

} // namespace

oct::CutCamera cutCameraFor(const Camera& camera, const Eigen::Matrix4d& pose)
{
    oct::CutCamera c;
    const Eigen::Matrix4d vp = camera.viewProjection() * pose;
    std::copy(vp.data(), vp.data() + 16, c.viewProjection.begin()); // both column-major
    const Eigen::Matrix3d r = pose.topLeftCorner<3, 3>();
    const Eigen::Vector3d eye = r.transpose() * (camera.eye() - pose.topRightCorner<3, 1>());
    c.eye = {eye.x(), eye.y(), eye.z()};
    c.orthographic = camera.isOrthographic();
    c.pixelsPerRadian = camera.pixelsPerRadian();
    c.pixelsPerMetre = camera.pixelsPerMetre();
    return c;
}

SceneCut computeSceneCut(const std::vector<ViewFragment>& fragments, const Camera& camera,
                         const CutSettings& settings, std::uint64_t budget)
{
    const auto start = std::chrono::steady_clock::now();
    struct Item {
        std::size_t slot = 0;                 ///< index in fragments (and result.fragments)
        const ViewFragment* fragment = nullptr;
        oct::CutCamera camera;
        oct::CutOptions options;
        oct::CutResult cut;
    };
    std::vector<Item> items;
    std::vector<double> demands;
    std::vector<std::uint64_t> caps;
    SceneCut result;
    result.budget = budget;
    result.fragments.resize(fragments.size());
    for (std::size_t slot = 0; slot < fragments.size(); ++slot) {
        const ViewFragment& f = fragments[slot];
        result.fragments[slot].id = f.id;
        if (!f.visible || !f.octree) continue;
        const oct::PackedOctree& octree = *f.octree;
        Item item{slot, &f, cutCameraFor(camera, f.pose), {}, {}};
        if (settings.mode == CutMode::GlobalLevel) {
            const int level = std::clamp(settings.globalLevel, 0, octree.depth());
            item.camera.cullToFrustum = false;
            item.options.pixelThreshold = 0;
            item.options.maxLevel = level;
            demands.push_back(double(octree.cellCount(level)));
            caps.push_back(octree.cellCount(level));
        } else {
            item.options.pixelThreshold = settings.pixelThreshold;
            demands.push_back(estimateDemand(octree, item.camera, settings.pixelThreshold));
            caps.push_back(octree.cellCount(octree.depth()));
        }
        items.push_back(item);
    }

    std::vector<std::uint64_t> shares = shareBudget(demands, caps, budget);
    auto run = [&](std::size_t i) {
        items[i].cut = {};
        if (shares[i] == 0) return;
        items[i].options.pointBudget = shares[i];
        items[i].cut = oct::computeViewCut(*items[i].fragment->octree, items[i].camera, items[i].options);
    };
    std::uint64_t used = 0;
    for (std::size_t i = 0; i < items.size(); ++i) {
        run(i);
        used += items[i].cut.cells.size();
    }
    // One more round: what fragments satisfied below their share did not use goes to those that hit theirs.
    if (items.size() > 1 && budget - std::min(used, budget) > budget / 20) {
        std::vector<double> moreDemand(items.size(), 0);
        std::vector<std::uint64_t> room(items.size(), 0);
        for (std::size_t i = 0; i < items.size(); ++i)
            if (items[i].cut.budgetReached) {
                moreDemand[i] = demands[i];
                room[i] = caps[i] - std::min(caps[i], shares[i]);
            }
        const std::vector<std::uint64_t> extra = shareBudget(moreDemand, room, budget - used);
        for (std::size_t i = 0; i < items.size(); ++i)
            if (extra[i] > 0) {
                shares[i] += extra[i];
                run(i);
            }
    }
    bool anyReached = false;
    for (Item& item : items) {
        anyReached = anyReached || item.cut.budgetReached;
        result.cells += item.cut.cells.size();
        result.fragments[item.slot].splats = makeSplatBuffer(*item.fragment->octree, item.cut, item.fragment->id + 1);
        item.cut = {};
    }
    result.budgetReached = anyReached;
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

} // namespace stylos::core::view
