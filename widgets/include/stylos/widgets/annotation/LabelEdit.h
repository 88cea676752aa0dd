#pragma once
/** @file
 * @brief One change of a fragment's annotation labels: the leaves it touches (sorted, unique) with the class id
 *        each had before and has after. An undo step stores only this, never the whole layer, so a stroke
 *        on a 30 M-leaf drum costs what it touched. Plain data, no Qt.
 */
#include "stylos/core/annotation/Legend.h"
#include "stylos/core/scene/Fragment.h"

#include <cstdint>
#include <vector>

namespace stylos::widgets {

struct LabelEdit {
    core::scene::FragmentId fragment = core::scene::NoFragment;
    core::annotation::AnnotationLayer layer = core::annotation::AnnotationLayer::Material;
    std::vector<std::uint32_t> leaves; ///< ascending, unique
    std::vector<std::uint8_t> before;  ///< per leaf, the id before the change
    std::vector<std::uint8_t> after;   ///< per leaf, the id after it (≠ before)

    bool empty() const { return leaves.empty(); }
    std::size_t size() const { return leaves.size(); }
    /**
     * @brief Folds @p later (made after this one, on the same fragment and layer) into this edit: a leaf
     *        keeps this edit's "before" and takes @p later's "after"; leaves that end where they started
     *        are dropped. Cost: O(size() + later.size()).
     */
    void merge(const LabelEdit& later);
};

} // namespace stylos::widgets
