// Merging two label changes of one layer into one undo step.
#include "stylos/widgets/annotation/LabelEdit.h"

#include <cassert>

namespace stylos::widgets {

void LabelEdit::merge(const LabelEdit& later)
{
    assert(later.fragment == fragment && later.layer == layer);
    LabelEdit out;
    out.fragment = fragment;
    out.layer = layer;
    const std::size_t capacity = leaves.size() + later.leaves.size();
    out.leaves.reserve(capacity);
    out.before.reserve(capacity);
    out.after.reserve(capacity);
    const auto keep = [&out](std::uint32_t leaf, std::uint8_t before, std::uint8_t after) {
        if (before == after) return;
        out.leaves.push_back(leaf);
        out.before.push_back(before);
        out.after.push_back(after);
    };
    std::size_t i = 0, j = 0;
    while (i < leaves.size() || j < later.leaves.size()) {
        if (j == later.leaves.size() || (i < leaves.size() && leaves[i] < later.leaves[j])) {
            keep(leaves[i], before[i], after[i]);
            ++i;
        } else if (i == leaves.size() || later.leaves[j] < leaves[i]) {
            keep(later.leaves[j], later.before[j], later.after[j]);
            ++j;
        } else {
            keep(leaves[i], before[i], later.after[j]);
            ++i;
            ++j;
        }
    }
    *this = std::move(out);
}

} // namespace stylos::widgets
