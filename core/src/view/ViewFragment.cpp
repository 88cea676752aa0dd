#include "stylos/core/view/ViewFragment.h"

namespace stylos::core::view {

std::optional<std::vector<PoseChange>> poseChanges(const std::vector<ViewFragment>& current,
                                                   const std::vector<ViewFragment>& next)
{
    if (current.size() != next.size()) return std::nullopt;
    std::vector<PoseChange> changes;
    for (std::size_t i = 0; i < next.size(); ++i) {
        const ViewFragment& a = current[i];
        const ViewFragment& b = next[i];
        if (a.id != b.id || a.octree != b.octree || a.colour != b.colour || a.visible != b.visible ||
            a.selected != b.selected)
            return std::nullopt;
        if (a.pose != b.pose) changes.push_back({b.id, b.pose});
    }
    return changes;
}

} // namespace stylos::core::view
