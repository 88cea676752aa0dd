// LodScheduler: a still view refines (in stages, in the background) to the whole leaf level of a small
// octree, a change of poses alone starts no cut until the poses stop changing, and the frame-time
// controller of the motion budget. What a cut is (the budget, its sharing, the global level mode, the
// splats) is core::view's, tested without a display in tests/core (SceneCutTest, BudgetShareTest,
// SplatBufferTest).
#include "DrumOctreeFixture.h"
#include "WidgetTestSupport.h"

#include "stylos/core/view/SceneCut.h"
#include "stylos/widgets/view3d/LodScheduler.h"

#include <QSignalSpy>
#include <QTemporaryDir>

#include <algorithm>
#include <set>
#include <tuple>

using stylos::core::view::Camera;
using stylos::core::view::SceneCut;
using stylos::core::view::StandardView;
using stylos::core::view::ViewFragment;
using stylos::widgets::LodScheduler;

namespace {

using Key = std::tuple<long long, long long, long long>;

/** A cell centre (octree frame) quantised to 1/8 of @p cell, for set comparison. */
Key keyOf(double x, double y, double z, double cell)
{
    const double q = cell / 8;
    return {std::llround(x / q), std::llround(y / q), std::llround(z / q)};
}

} // namespace

class LodSchedulerTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void refinesToTheLeafLevelWhenStill();
    void aPoseChangeStartsNoCut();
    void motionBudgetFollowsFrameTimes();

private:
    Camera fittedCamera(const Eigen::Matrix4d& pose = Eigen::Matrix4d::Identity()) const;
    ViewFragment fragment(std::uint64_t id, const Eigen::Matrix4d& pose = Eigen::Matrix4d::Identity()) const;

    QTemporaryDir m_dir;
    stylos::test::DrumOctree m_drum;
};

void LodSchedulerTest::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_drum = stylos::test::makeDrumOctree(m_dir.path(), 0.01, 6);
    QVERIFY(m_drum.octree->cellCount(6) > 1000);
}

Camera LodSchedulerTest::fittedCamera(const Eigen::Matrix4d& pose) const
{
    const auto& b = m_drum.octree->box();
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

ViewFragment LodSchedulerTest::fragment(std::uint64_t id, const Eigen::Matrix4d& pose) const
{
    ViewFragment f;
    f.id = id;
    f.octree = m_drum.octree;
    f.pose = pose;
    return f;
}

void LodSchedulerTest::refinesToTheLeafLevelWhenStill()
{
    LodScheduler scheduler;
    scheduler.setMinimumDrawLimit(100);
    for (int i = 0; i < 20; ++i) scheduler.reportFrame(1000, 1000); // a slow renderer: the first stage is small
    QVERIFY(scheduler.drawLimit() < 1000);
    QSignalSpy cuts(&scheduler, &LodScheduler::cutReady);
    QSignalSpy refined(&scheduler, &LodScheduler::refined);
    scheduler.setIdleDelay(50);
    scheduler.setFragments({fragment(7)});
    scheduler.cameraChanged(fittedCamera()); // moving: nothing computed until it stops
    QVERIFY(scheduler.isMoving());
    QCOMPARE(scheduler.frameLimit(), scheduler.drawLimit());
    QVERIFY(refined.wait(20000));
    QVERIFY(!scheduler.isMoving());
    QCOMPARE(scheduler.frameLimit(), 0u);
    QVERIFY(scheduler.isRefined());
    QVERIFY2(cuts.size() >= 3, "progressive: several stages");
    std::uint64_t previous = 0;
    for (const auto& args : cuts) {
        const auto batch = args.at(0).value<std::shared_ptr<const SceneCut>>();
        QVERIFY(batch->cells > previous);
        previous = batch->cells;
    }
    const auto last = cuts.last().at(0).value<std::shared_ptr<const SceneCut>>();
    QVERIFY(last->final);
    QVERIFY(!last->budgetReached);

    // The final cut is exactly the leaf level: the same cells, each once.
    const auto& octree = *m_drum.octree;
    const double leaf = octree.box().cellSize(octree.depth());
    const auto& vertices = last->fragments.at(0).splats.vertices;
    QCOMPARE(std::uint64_t(vertices.size()), octree.cellCount(octree.depth()));
    std::set<Key> cut, leaves;
    for (const auto& v : vertices) {
        QVERIFY(v.size >= leaf * (1 - 1e-6)); // at least the cell; wider where the sampling is sparser (spacing)
        cut.insert(keyOf(v.position[0], v.position[1], v.position[2], leaf));
    }
    octree.forEachCell(octree.depth(), [&](const stylos::core::octree::CellView& c) {
        leaves.insert(keyOf(c.centre[0] - octree.box().origin[0], c.centre[1] - octree.box().origin[1],
                            c.centre[2] - octree.box().origin[2], leaf));
        return true;
    });
    QCOMPARE(cut.size(), vertices.size());
    QVERIFY(cut == leaves);
}

void LodSchedulerTest::aPoseChangeStartsNoCut()
{
    LodScheduler scheduler;
    scheduler.setIdleDelay(1000);
    QSignalSpy refined(&scheduler, &LodScheduler::refined);
    QSignalSpy stopped(&scheduler, &LodScheduler::motionStopped);
    QSignalSpy cuts(&scheduler, &LodScheduler::cutReady);
    const Camera camera = fittedCamera();
    scheduler.setFragments({fragment(1), fragment(2)}, camera);
    QVERIFY(refined.wait(20000));
    QTRY_VERIFY(!scheduler.isComputing());
    const std::uint64_t before = scheduler.cutsStarted();
    QVERIFY(before >= 1);
    QCOMPARE(std::uint64_t(cuts.size()), before); // each cut started was delivered

    // A drag: poses change, no cut starts; the view counts as moving (quick frames).
    Eigen::Matrix4d moved = Eigen::Matrix4d::Identity();
    for (int i = 1; i <= 5; ++i) {
        moved(0, 3) = 0.01 * i;
        QVERIFY(scheduler.setFragmentPose(2, moved, camera));
        QCOMPARE(scheduler.cutsStarted(), before);
        QVERIFY(scheduler.isMoving());
        QVERIFY(!scheduler.isRefined());
        QCOMPARE(scheduler.frameLimit(), scheduler.drawLimit());
        QTest::qWait(20); // well within the idle delay: still no cut
        QCOMPARE(scheduler.cutsStarted(), before);
    }
    QVERIFY(scheduler.fragments()[1].pose == moved);
    QVERIFY(scheduler.fragments()[0].pose == Eigen::Matrix4d::Identity());
    QVERIFY(!scheduler.setFragmentPose(99, moved, camera)); // no such fragment: nothing changes
    QVERIFY(scheduler.fragments()[1].pose == moved);
    QCOMPARE(stopped.size(), 0);

    // Once the poses have been still for the idle delay, the cut for the new poses follows, refined to the end:
    // exactly the core's cut of the moved fragments at the last stage's budget.
    QVERIFY(refined.wait(20000));
    QCOMPARE(stopped.size(), 1);
    QVERIFY(scheduler.cutsStarted() > before);
    QVERIFY(!scheduler.isMoving());
    const auto last = cuts.last().at(0).value<std::shared_ptr<const SceneCut>>();
    QVERIFY(last->final);
    const SceneCut expected = stylos::core::view::computeSceneCut(scheduler.fragments(), camera, {}, last->budget);
    QCOMPARE(last->cells, expected.cells);
    QCOMPARE(last->fragments.at(1).splats.vertices.size(), expected.fragments.at(1).splats.vertices.size());
}

void LodSchedulerTest::motionBudgetFollowsFrameTimes()
{
    LodScheduler scheduler;
    QCOMPARE(scheduler.pointBudget(), 1'000'000u);
    QCOMPARE(scheduler.targetFrameMs(), 50.0);
    QCOMPARE(scheduler.drawLimit(), 100'000u);
    // 100 ms for 200 000 points: aim at 85 % of 50 ms → 85 000; half-way there.
    scheduler.reportFrame(100, 200'000);
    QCOMPARE(scheduler.drawLimit(), 92'500u);
    scheduler.reportFrame(0, 200'000); // ignored
    scheduler.reportFrame(10, 0);      // ignored
    QCOMPARE(scheduler.drawLimit(), 92'500u);
    // Fast frames raise it, at most doubling per frame, never above the budget.
    scheduler.reportFrame(1, 92'500);
    QCOMPARE(scheduler.drawLimit(), 185'000u);
    // Slow frames lower it, never below the minimum (5 000).
    for (int i = 0; i < 30; ++i) scheduler.reportFrame(1000, scheduler.drawLimit());
    QCOMPARE(scheduler.drawLimit(), 5'000u);
    for (int i = 0; i < 20; ++i) scheduler.reportFrame(1, scheduler.drawLimit());
    QCOMPARE(scheduler.drawLimit(), 1'000'000u);
    scheduler.setPointBudget(50'000);
    QCOMPARE(scheduler.drawLimit(), 50'000u);
    // Converges where a frame takes 85 % of the target for a linear cost (1 µs per point + 5 ms).
    scheduler.setPointBudget(1'000'000);
    for (int i = 0; i < 60; ++i) scheduler.reportFrame(5 + 1e-3 * double(scheduler.drawLimit()), scheduler.drawLimit());
    QVERIFY(std::abs(5 + 1e-3 * double(scheduler.drawLimit()) - 42.5) < 0.5);
}

STYLOS_WIDGET_TEST_MAIN(LodSchedulerTest)
#include "LodSchedulerTest.moc"
