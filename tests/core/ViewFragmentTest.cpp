// poseChanges: a change of poses alone is told from any other change of the view's fragments.
#include "ViewTestSupport.h"

#include "stylos/core/view/ViewFragment.h"

#include <gtest/gtest.h>

using stylos::core::view::poseChanges;
using stylos::core::view::ViewFragment;

namespace {

std::vector<ViewFragment> twoFragments(const std::shared_ptr<const stylos::core::octree::PackedOctree>& tree)
{
    return {stylos::test::viewFragment(1, tree), stylos::test::viewFragment(2, tree)};
}

} // namespace

TEST(ViewFragmentTest, PosesAloneAreTheChangedPoses)
{
    stylos::test::TempDir dir;
    const auto tree = stylos::test::fourLeafOctree(dir);
    ASSERT_NE(tree, nullptr);
    const std::vector<ViewFragment> before = twoFragments(tree);
    auto same = poseChanges(before, before);
    ASSERT_TRUE(same);
    EXPECT_TRUE(same->empty());

    std::vector<ViewFragment> after = before;
    after[1].pose(0, 3) = 0.25;
    after[1].pose(1, 1) = -1; // not rigid, still a pose change: the view draws what it is given
    const auto changes = poseChanges(before, after);
    ASSERT_TRUE(changes);
    ASSERT_EQ(changes->size(), 1u);
    EXPECT_EQ((*changes)[0].id, 2u);
    EXPECT_EQ((*changes)[0].pose, after[1].pose);

    after[0].pose(2, 3) = -4;
    const auto both = poseChanges(before, after);
    ASSERT_TRUE(both);
    ASSERT_EQ(both->size(), 2u);
    EXPECT_EQ((*both)[0].id, 1u);
    EXPECT_EQ((*both)[0].pose, after[0].pose);
    EXPECT_EQ((*both)[1].id, 2u);
}

TEST(ViewFragmentTest, AnyOtherChangeIsNotAPoseChange)
{
    stylos::test::TempDir dir;
    const auto tree = stylos::test::fourLeafOctree(dir);
    ASSERT_NE(tree, nullptr);
    const std::vector<ViewFragment> before = twoFragments(tree);
    const auto differs = [&](auto change) {
        std::vector<ViewFragment> after = before;
        change(after);
        after[0].pose(0, 3) = 1; // together with a pose change
        return !poseChanges(before, after).has_value();
    };
    EXPECT_TRUE(differs([](auto& f) { f.pop_back(); }));
    EXPECT_TRUE(differs([&](auto& f) { f.push_back(stylos::test::viewFragment(3, tree)); }));
    EXPECT_TRUE(differs([](auto& f) { std::swap(f[0], f[1]); }));
    EXPECT_TRUE(differs([](auto& f) { f[1].id = 9; }));
    EXPECT_TRUE(differs([](auto& f) { f[1].octree = nullptr; }));
    // The same file opened again is another octree (a replaced "ambient" layer): not a pose change.
    stylos::test::TempDir otherDir;
    const auto again = stylos::test::fourLeafOctree(otherDir);
    EXPECT_TRUE(differs([&](auto& f) { f[1].octree = again; }));
    EXPECT_TRUE(differs([](auto& f) { f[1].colour = {1, 2, 3}; }));
    EXPECT_TRUE(differs([](auto& f) { f[1].visible = false; }));
    EXPECT_TRUE(differs([](auto& f) { f[1].selected = true; }));
    EXPECT_FALSE(differs([](auto&) {}));
}
