// LodScheduler: the budget is respected, a still view refines (in stages, in the background) to the
// whole leaf level of a small octree, fragments share the budget, the global level mode, and the
// frame-time controller of the motion budget.
#include "DrumOctreeFixture.h"
#include "WidgetTestSupport.h"

#include "stylos/core/ao/AoExport.h"
#include "stylos/widgets/LodScheduler.h"
#include "stylos/widgets/SplatBuffer.h"

#include <QSignalSpy>
#include <QTemporaryDir>

#include <algorithm>
#include <set>
#include <tuple>

using stylos::widgets::Camera;
using stylos::widgets::LodScheduler;
using stylos::widgets::RenderFragment;
using stylos::widgets::StandardView;

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
    void budgetIsRespected();
    void refinesToTheLeafLevelWhenStill();
    void fragmentsShareTheBudget();
    void shareBudgetExactly();
    void hiddenAndGlobalLevel();
    void motionBudgetFollowsFrameTimes();
    void splatsCarryTheAmbientLayer();

private:
    Camera fittedCamera(const Eigen::Matrix4d& pose = Eigen::Matrix4d::Identity()) const;
    RenderFragment fragment(std::uint64_t id, const Eigen::Matrix4d& pose = Eigen::Matrix4d::Identity()) const;

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

RenderFragment LodSchedulerTest::fragment(std::uint64_t id, const Eigen::Matrix4d& pose) const
{
    RenderFragment f;
    f.id = id;
    f.octree = m_drum.octree;
    f.pose = pose;
    return f;
}

void LodSchedulerTest::budgetIsRespected()
{
    const Camera camera = fittedCamera();
    for (std::uint64_t budget : {1ull, 37ull, 500ull, 5000ull}) {
        const auto batch = LodScheduler::computeCuts({fragment(1)}, camera, {}, budget);
        QCOMPARE(batch.fragments.size(), 1u);
        QVERIFY(batch.cells <= budget);
        QCOMPARE(batch.fragments[0].splats.vertices.size(), batch.cells);
        QVERIFY(batch.budgetReached);
        QVERIFY(batch.cells >= budget * 8 / 10); // the budget is used, not wasted
    }
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
        const auto batch = args.at(0).value<std::shared_ptr<const LodScheduler::CutBatch>>();
        QVERIFY(batch->cells > previous);
        previous = batch->cells;
    }
    const auto last = cuts.last().at(0).value<std::shared_ptr<const LodScheduler::CutBatch>>();
    QVERIFY(last->final);
    QVERIFY(!last->budgetReached);

    // The final cut is exactly the leaf level: the same cells, each once.
    const auto& octree = *m_drum.octree;
    const double leaf = octree.box().cellSize(octree.depth());
    const auto& vertices = last->fragments.at(0).splats.vertices;
    QCOMPARE(std::uint64_t(vertices.size()), octree.cellCount(octree.depth()));
    std::set<Key> cut, leaves;
    for (const auto& v : vertices) {
        QVERIFY(std::abs(v.size - leaf) < 1e-6 * leaf);
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

void LodSchedulerTest::fragmentsShareTheBudget()
{
    // Two copies side by side, symmetric about the view axis, and a third far behind them.
    const double size = m_drum.octree->box().size;
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
    LodScheduler::Settings coarse;
    coarse.pixelThreshold = 8;
    const std::uint64_t budget = 3000;
    const auto batch = LodScheduler::computeCuts({fragment(1, left), fragment(2, right), fragment(3, far)}, camera,
                                                 coarse, budget);
    QCOMPARE(batch.fragments.size(), 3u);
    const auto n = [&](int i) { return double(batch.fragments[std::size_t(i)].splats.vertices.size()); };
    QVERIFY(batch.cells <= budget);
    QVERIFY(batch.cells >= budget * 9 / 10);
    QVERIFY2(std::abs(n(0) - n(1)) <= 0.1 * n(0), qPrintable(QString("%1 vs %2").arg(n(0)).arg(n(1))));
    QVERIFY2(n(2) > 0 && n(2) < 0.5 * n(0), qPrintable(QString("far %1 near %2").arg(n(2)).arg(n(0))));

    // With a budget above what the view needs each gets all it asks for: the same as alone.
    Camera alone = camera;
    const auto big = LodScheduler::computeCuts({fragment(1, left), fragment(2, right)}, alone, {}, 10'000'000);
    const auto single = LodScheduler::computeCuts({fragment(1, left)}, alone, {}, 10'000'000);
    QVERIFY(!big.budgetReached);
    QCOMPARE(big.fragments[0].splats.vertices.size(), single.fragments[0].splats.vertices.size());
}

void LodSchedulerTest::shareBudgetExactly()
{
    using V = std::vector<std::uint64_t>;
    QCOMPARE(LodScheduler::shareBudget({1, 1, 2}, {100, 100, 100}, 100), (V{25, 25, 50}));
    QCOMPARE(LodScheduler::shareBudget({1, 1, 2}, {10, 100, 100}, 100), (V{10, 30, 60}));
    QCOMPARE(LodScheduler::shareBudget({1, 0, 2}, {100, 100, 100}, 90), (V{30, 0, 60}));
    QCOMPARE(LodScheduler::shareBudget({1, 1}, {5, 7}, 100), (V{5, 7}));
    QCOMPARE(LodScheduler::shareBudget({1, 1, 1}, {100, 100, 100}, 10), (V{4, 3, 3})); // rounding goes somewhere
    QCOMPARE(LodScheduler::shareBudget({1000, 1}, {100, 100}, 100), (V{99, 1}));       // nobody visible gets 0
    QCOMPARE(LodScheduler::shareBudget({}, {}, 100), V{});
}

void LodSchedulerTest::hiddenAndGlobalLevel()
{
    RenderFragment hidden = fragment(2);
    hidden.visible = false;
    LodScheduler::Settings settings;
    settings.mode = LodScheduler::Mode::GlobalLevel;
    settings.globalLevel = 4;
    const auto batch = LodScheduler::computeCuts({fragment(1), hidden}, fittedCamera(), settings, 1'000'000);
    QCOMPARE(batch.fragments.size(), 2u);
    QCOMPARE(std::uint64_t(batch.fragments[0].splats.vertices.size()), m_drum.octree->cellCount(4));
    QCOMPARE(batch.fragments[1].id, 2u);
    QVERIFY(batch.fragments[1].splats.vertices.empty());
    // A level beyond the depth is the leaf level; the budget still caps it.
    settings.globalLevel = 40;
    const auto capped = LodScheduler::computeCuts({fragment(1)}, fittedCamera(), settings, 100);
    QVERIFY(capped.cells <= 100);
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

void LodSchedulerTest::splatsCarryTheAmbientLayer()
{
    // Every leaf gets its own value; an inner cell of a cut takes its first leaf's.
    const auto& octree = *m_drum.octree;
    const std::uint64_t leaves = octree.cellCount(octree.depth());
    std::vector<float> ambient(leaves);
    for (std::uint64_t i = 0; i < leaves; ++i) ambient[i] = float(i % 256) / 255.0f;
    const std::filesystem::path path = m_dir.filePath("ambient.poct").toStdString();
    QVERIFY(stylos::core::ao::writeAmbientPoct(octree, ambient, path).ok());
    auto opened = stylos::core::octree::PackedOctree::open(path);
    QVERIFY(opened.ok());
    const auto& withAmbient = *opened;

    stylos::core::octree::CutCamera camera;
    camera.cullToFrustum = false;
    stylos::core::octree::CutOptions options;
    options.pixelThreshold = 0;
    options.maxLevel = 3;
    const auto cut = stylos::core::octree::computeViewCut(withAmbient, camera, options);
    QCOMPARE(std::uint64_t(cut.cells.size()), withAmbient.cellCount(3));
    const auto splats = stylos::widgets::makeSplatBuffer(withAmbient, cut, 0);
    QVERIFY(splats.hasAmbient);
    QVERIFY(!splats.hasColour);
    QCOMPARE(splats.vertices.size(), cut.cells.size());
    for (std::size_t i = 0; i < cut.cells.size(); ++i) {
        const auto& c = cut.cells[i];
        const std::uint64_t first = stylos::widgets::firstLeafOf(withAmbient, c.level, c.index);
        QCOMPARE(int(splats.vertices[i].colour[3]), int(first % 256));
        QCOMPARE(splats.vertices[i].position, c.centre);
        QCOMPARE(splats.vertices[i].colour[0], std::uint8_t(255)); // no scan colour
        // The first leaf lies inside the cell.
        bool inside = false;
        withAmbient.forEachCell(withAmbient.depth(), [&](const stylos::core::octree::CellView& l) {
            if (l.index != first) return true;
            for (int a = 0; a < 3; ++a) {
                const double rel = l.centre[std::size_t(a)] - withAmbient.box().origin[std::size_t(a)];
                if (std::abs(rel - c.centre[std::size_t(a)]) > 0.5 * c.size) return false;
            }
            inside = true;
            return false;
        });
        QVERIFY(inside);
        if (i > 40) break; // the leaf walk is linear: a sample is enough
    }
    QCOMPARE(stylos::widgets::firstLeafOf(withAmbient, withAmbient.depth(), 5), 5u);
    QCOMPARE(stylos::widgets::firstLeafOf(withAmbient, 0, 0), 0u);
}

STYLOS_WIDGET_TEST_MAIN(LodSchedulerTest)
#include "LodSchedulerTest.moc"
