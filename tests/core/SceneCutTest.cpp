// computeSceneCut: the budget is respected and used, one fragment's cut is exactly core's view cut under the
// budget, fragments share the budget (by what they need; more to the near ones), hidden fragments and the
// global level mode, and cutCameraFor for a posed fragment — on a small generated drum (depth 6).
#include "ViewTestSupport.h"

#include "stylos/core/view/SceneCut.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>

using namespace stylos::core;
using stylos::core::view::Camera;
using stylos::core::view::CutMode;
using stylos::core::view::CutSettings;
using stylos::core::view::SceneCut;
using stylos::core::view::StandardView;
using stylos::core::view::ViewFragment;

namespace {

std::vector<std::array<float, 3>> sortedPositions(const view::SplatBuffer& splats)
{
    std::vector<std::array<float, 3>> out;
    for (const auto& v : splats.vertices) out.push_back(v.position);
    std::sort(out.begin(), out.end());
    return out;
}

std::vector<std::array<float, 3>> sortedCentres(const octree::CutResult& cut)
{
    std::vector<std::array<float, 3>> out;
    for (const auto& c : cut.cells) out.push_back(c.centre);
    std::sort(out.begin(), out.end());
    return out;
}

} // namespace

class SceneCutTest : public ::testing::Test {
protected:
    static void SetUpTestSuite()
    {
        s_dir = std::make_unique<stylos::test::TempDir>();
        s_drum = stylos::test::makeDrumOctree(s_dir->path(), 0.01, 6);
    }
    static void TearDownTestSuite()
    {
        s_drum = {};
        s_dir.reset();
    }
    void SetUp() override
    {
        ASSERT_NE(s_drum.octree, nullptr);
        ASSERT_GT(s_drum.octree->cellCount(6), 1000u);
    }

    static Camera fittedCamera(const Eigen::Matrix4d& pose = Eigen::Matrix4d::Identity())
    {
        const auto& b = s_drum.octree->box();
        const Eigen::Vector3d lo(b.origin[0], b.origin[1], b.origin[2]);
        Eigen::AlignedBox3d box((pose * lo.homogeneous()).head<3>());
        box.extend((pose * (lo + Eigen::Vector3d::Constant(b.size)).homogeneous()).head<3>());
        Camera camera;
        camera.setViewport(800, 600);
        camera.setStandardView(StandardView::Iso);
        camera.setSceneBounds(box);
        camera.fit(box);
        return camera;
    }
    static ViewFragment fragment(std::uint64_t id, const Eigen::Matrix4d& pose = Eigen::Matrix4d::Identity())
    {
        return stylos::test::viewFragment(id, s_drum.octree, pose);
    }

    static inline std::unique_ptr<stylos::test::TempDir> s_dir;
    static inline stylos::test::DrumOctree s_drum;
};

TEST_F(SceneCutTest, BudgetIsRespectedAndOneFragmentGetsCoresCut)
{
    const Camera camera = fittedCamera();
    for (std::uint64_t budget : {1ull, 37ull, 500ull, 5000ull}) {
        SCOPED_TRACE(budget);
        const SceneCut cut = view::computeSceneCut({fragment(1)}, camera, {}, budget);
        ASSERT_EQ(cut.fragments.size(), 1u);
        EXPECT_EQ(cut.fragments[0].id, 1u);
        EXPECT_EQ(cut.budget, budget);
        EXPECT_LE(cut.cells, budget);
        EXPECT_EQ(cut.fragments[0].splats.vertices.size(), cut.cells);
        EXPECT_TRUE(cut.budgetReached);
        EXPECT_GE(cut.cells, budget * 8 / 10); // the budget is used, not wasted
        // Alone, a fragment gets the whole budget: exactly core's view cut for its camera.
        octree::CutOptions options;
        options.pointBudget = budget;
        const octree::CutResult expected =
            octree::computeViewCut(*s_drum.octree, view::cutCameraFor(camera, Eigen::Matrix4d::Identity()), options);
        EXPECT_EQ(cut.cells, expected.cells.size());
        EXPECT_EQ(sortedPositions(cut.fragments[0].splats), sortedCentres(expected));
        EXPECT_EQ(cut.fragments[0].splats.deepestLevel, expected.deepestLevel);
    }
}

TEST_F(SceneCutTest, FragmentsShareTheBudget)
{
    // Two copies side by side, symmetric about the view axis, and a third far behind them.
    const double size = s_drum.octree->box().size;
    Eigen::Matrix4d left = Eigen::Matrix4d::Identity(), right = left, far = left;
    left(0, 3) = -0.6 * size;
    right(0, 3) = 0.6 * size;
    far(1, 3) = 6 * size;
    Camera camera = fittedCamera();
    camera.setStandardView(StandardView::Front);
    camera.setDistance(camera.distance() * 2);
    Eigen::AlignedBox3d all = camera.sceneBounds();
    all.extend(all.min() + Eigen::Vector3d(0, 6 * size, 0));
    all.extend(all.min() - Eigen::Vector3d(0.6 * size, 0, 0));
    all.extend(all.max() + Eigen::Vector3d(0.6 * size, 6 * size, 0));
    camera.setSceneBounds(all);

    // A coarse threshold, so that the needs differ within this shallow octree (depth 6).
    CutSettings coarse;
    coarse.pixelThreshold = 8;
    const std::uint64_t budget = 3000;
    const SceneCut cut = view::computeSceneCut({fragment(1, left), fragment(2, right), fragment(3, far)}, camera,
                                               coarse, budget);
    ASSERT_EQ(cut.fragments.size(), 3u);
    const auto n = [&](int i) { return double(cut.fragments[std::size_t(i)].splats.vertices.size()); };
    EXPECT_LE(cut.cells, budget);
    EXPECT_GE(cut.cells, budget * 9 / 10);
    EXPECT_EQ(cut.cells, std::uint64_t(n(0) + n(1) + n(2)));
    EXPECT_LE(std::abs(n(0) - n(1)), 0.1 * n(0)) << n(0) << " vs " << n(1);
    EXPECT_TRUE(n(2) > 0 && n(2) < 0.5 * n(0)) << "far " << n(2) << " near " << n(0);

    // With a budget above what the view needs each gets all it asks for: exactly the same as alone.
    const SceneCut big = view::computeSceneCut({fragment(1, left), fragment(2, right)}, camera, {}, 10'000'000);
    const SceneCut single = view::computeSceneCut({fragment(1, left)}, camera, {}, 10'000'000);
    EXPECT_FALSE(big.budgetReached);
    EXPECT_EQ(big.fragments[0].splats.vertices.size(), single.fragments[0].splats.vertices.size());
    EXPECT_EQ(sortedPositions(big.fragments[0].splats), sortedPositions(single.fragments[0].splats));
}

TEST_F(SceneCutTest, HiddenAndGlobalLevel)
{
    ViewFragment hidden = fragment(2);
    hidden.visible = false;
    ViewFragment empty = fragment(3);
    empty.octree = nullptr;
    CutSettings settings;
    settings.mode = CutMode::GlobalLevel;
    settings.globalLevel = 4;
    const SceneCut cut = view::computeSceneCut({fragment(1), hidden, empty}, fittedCamera(), settings, 1'000'000);
    ASSERT_EQ(cut.fragments.size(), 3u);
    EXPECT_EQ(std::uint64_t(cut.fragments[0].splats.vertices.size()), s_drum.octree->cellCount(4));
    EXPECT_EQ(cut.cells, s_drum.octree->cellCount(4));
    EXPECT_FALSE(cut.budgetReached);
    EXPECT_EQ(cut.fragments[1].id, 2u);
    EXPECT_TRUE(cut.fragments[1].splats.vertices.empty());
    EXPECT_EQ(cut.fragments[2].id, 3u);
    EXPECT_TRUE(cut.fragments[2].splats.vertices.empty());
    // A level beyond the depth is the leaf level; the budget still caps it.
    settings.globalLevel = 40;
    const SceneCut capped = view::computeSceneCut({fragment(1)}, fittedCamera(), settings, 100);
    EXPECT_LE(capped.cells, 100u);
    EXPECT_TRUE(capped.budgetReached);
    settings.globalLevel = 40;
    const SceneCut leaves = view::computeSceneCut({fragment(1)}, fittedCamera(), settings, 1'000'000);
    EXPECT_EQ(leaves.cells, s_drum.octree->cellCount(6));
}

TEST_F(SceneCutTest, GlobalLevelSharesEquallyBetweenEqualFragments)
{
    // Two copies of the same octree need the same: each gets half the budget, and its cut is core's cut of
    // the level under that half, for its camera (no culling in this mode).
    CutSettings settings;
    settings.mode = CutMode::GlobalLevel;
    settings.globalLevel = 5;
    const std::uint64_t level5 = s_drum.octree->cellCount(5);
    const std::uint64_t budget = 2 * (level5 / 3);
    Eigen::Matrix4d moved = Eigen::Matrix4d::Identity();
    moved(2, 3) = 3.0;
    const std::array<Eigen::Matrix4d, 2> poses{Eigen::Matrix4d::Identity(), moved};
    const Camera camera = fittedCamera();
    const SceneCut cut = view::computeSceneCut({fragment(1, poses[0]), fragment(2, poses[1])}, camera, settings, budget);
    ASSERT_EQ(cut.fragments.size(), 2u);
    EXPECT_TRUE(cut.budgetReached);
    for (std::size_t i = 0; i < 2; ++i) {
        octree::CutCamera unculled = view::cutCameraFor(camera, poses[i]);
        unculled.cullToFrustum = false;
        octree::CutOptions options;
        options.pixelThreshold = 0;
        options.maxLevel = 5;
        options.pointBudget = budget / 2;
        const octree::CutResult expected = octree::computeViewCut(*s_drum.octree, unculled, options);
        EXPECT_EQ(cut.fragments[i].splats.vertices.size(), expected.cells.size());
        EXPECT_EQ(sortedPositions(cut.fragments[i].splats), sortedCentres(expected));
    }
}

TEST_F(SceneCutTest, CutCameraForAPosedFragment)
{
    Camera camera = fittedCamera();
    camera.orbit(0.4, 0.1);
    // A quarter turn about z and a translation: the eye in the octree's frame is Rᵀ(eye − t).
    Eigen::Matrix4d pose = Eigen::Matrix4d::Identity();
    pose.topLeftCorner<3, 3>() << 0, -1, 0, 1, 0, 0, 0, 0, 1;
    pose.topRightCorner<3, 1>() << 2, -3, 0.5;
    const octree::CutCamera c = view::cutCameraFor(camera, pose);
    const Eigen::Vector3d e = camera.eye() - Eigen::Vector3d(2, -3, 0.5);
    EXPECT_NEAR(c.eye[0], e.y(), 1e-12);
    EXPECT_NEAR(c.eye[1], -e.x(), 1e-12);
    EXPECT_NEAR(c.eye[2], e.z(), 1e-12);
    const Eigen::Matrix4d vp = camera.viewProjection() * pose;
    for (int i = 0; i < 16; ++i) EXPECT_EQ(c.viewProjection[std::size_t(i)], vp.data()[i]) << i; // column-major
    EXPECT_FALSE(c.orthographic);
    EXPECT_TRUE(c.cullToFrustum);
    EXPECT_EQ(c.pixelsPerRadian, camera.pixelsPerRadian());
    EXPECT_EQ(c.pixelsPerMetre, camera.pixelsPerMetre());
    camera.setOrthographic(true);
    EXPECT_TRUE(view::cutCameraFor(camera, pose).orthographic);
}

TEST_F(SceneCutTest, AFragmentOutOfViewGetsNothing)
{
    // Far to the side of the view: culled, and its share goes to the fragment in view.
    Eigen::Matrix4d aside = Eigen::Matrix4d::Identity();
    aside(0, 3) = 1000;
    const Camera camera = fittedCamera();
    const SceneCut cut = view::computeSceneCut({fragment(1, aside), fragment(2)}, camera, {}, 500);
    ASSERT_EQ(cut.fragments.size(), 2u);
    EXPECT_TRUE(cut.fragments[0].splats.vertices.empty());
    const SceneCut alone = view::computeSceneCut({fragment(2)}, camera, {}, 500);
    EXPECT_EQ(sortedPositions(cut.fragments[1].splats), sortedPositions(alone.fragments[0].splats));
}
