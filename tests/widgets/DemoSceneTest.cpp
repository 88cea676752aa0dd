// DemoScene: the demo is a project generated once (coarse spacing here, to stay fast) into its folder: four
// fragments laid out side by side, each a .poct with its skydome; a second prepare() reuses it untouched;
// Cancel leaves nothing; an outdated or incomplete cache is regenerated; failures are reported.
#include "WidgetTestSupport.h"

#include "stylos/core/ao/AoExport.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/annotation/LeafLabels.h"
#include "stylos/core/scene/ProjectFile.h"
#include "stylos/widgets/document/DemoScene.h"
#include "stylos/widgets/tasks/TaskManager.h"

#include <cmath>
#include <QDateTime>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QSignalSpy>
#include <QTemporaryDir>

#include <cstring>
#include <limits>

using stylos::widgets::DemoScene;
using stylos::widgets::TaskManager;
namespace core = stylos::core;

namespace {

constexpr double kTestSpacing = 0.012; ///< metres: a few tens of thousands of points in all

/** Scene-frame bounds of a fragment's leaf centres. */
struct Bounds {
    std::array<double, 3> lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                             std::numeric_limits<double>::infinity()};
    std::array<double, 3> hi{-lo[0], -lo[1], -lo[2]};
};

Bounds sceneBounds(const core::octree::PackedOctree& octree, const core::scene::Pose& pose)
{
    Bounds b;
    octree.forEachCell(octree.depth(), [&](const core::octree::CellView& cell) {
        const auto p = pose.apply(cell.centre);
        for (int k = 0; k < 3; ++k) {
            b.lo[k] = std::min(b.lo[k], p[k]);
            b.hi[k] = std::max(b.hi[k], p[k]);
        }
        return true;
    });
    return b;
}

/** Runs prepare() to its end; returns the ready() path, or "" after failed()/cancelled(). */
QString prepareAndWait(DemoScene& demo, int timeoutMs = 120000)
{
    QSignalSpy ready(&demo, &DemoScene::ready);
    QSignalSpy failed(&demo, &DemoScene::failed);
    QSignalSpy cancelled(&demo, &DemoScene::cancelled);
    if (!demo.prepare()) return {};
    QElapsedTimer timer;
    timer.start();
    while (ready.isEmpty() && failed.isEmpty() && cancelled.isEmpty() && timer.elapsed() < timeoutMs)
        QTest::qWait(20);
    if (!failed.isEmpty()) qWarning("%s", qPrintable(failed.first().at(0).toString()));
    return ready.isEmpty() ? QString() : ready.first().at(0).toString();
}

QMap<QString, QDateTime> modificationTimes(const QString& directory)
{
    QMap<QString, QDateTime> times;
    for (const QFileInfo& info :
         QDir(directory).entryInfoList(QDir::Files | QDir::Hidden | QDir::AllDirs | QDir::NoDotAndDotDot))
        times.insert(info.fileName(), info.lastModified());
    return times;
}

} // namespace

class DemoSceneTest : public QObject {
    Q_OBJECT

  private Q_SLOTS:
    void defaultDirectoryAndItems();
    void generatesTheProject();
    void secondPrepareReusesTheCache();
    void incompleteOrOutdatedCacheIsRegenerated();
    void cancelLeavesNothing();
    void unwritableFolderFails();
    void firstRunAtTheDefaultSpacing();

  private:
    QString generatedDirectory();

    QTemporaryDir m_dir;
    TaskManager m_tasks;
};

QString DemoSceneTest::generatedDirectory()
{
    const QString dir = m_dir.filePath("demo");
    DemoScene demo(m_tasks, dir);
    demo.setSpacing(kTestSpacing);
    if (!demo.isGenerated()) prepareAndWait(demo);
    return dir;
}

void DemoSceneTest::defaultDirectoryAndItems()
{
    const QString cache = QStandardPaths::writableLocation(QStandardPaths::CacheLocation);
    QCOMPARE(DemoScene::defaultDirectory(), cache + "/demo");
    const auto items = DemoScene::items();
    QCOMPARE(items.size(), 4u);
    QCOMPARE(items[0].name, QString("Drum"));
    QCOMPARE(items[3].fileName, QString("omphalos.poct"));

    DemoScene demo(m_tasks, m_dir.filePath("nowhere"));
    QCOMPARE(demo.projectPath(), QDir(m_dir.filePath("nowhere")).absoluteFilePath("demo.stylos"));
    QCOMPARE(demo.paths().size(), 4);
    QVERIFY(demo.paths()[1].endsWith("/fragment-a.poct"));
    QCOMPARE(demo.spacing(), DemoScene::DefaultSpacing);
    QVERIFY(!demo.isGenerated());
}

void DemoSceneTest::generatesTheProject()
{
    const QString dir = m_dir.filePath("demo");
    DemoScene demo(m_tasks, dir);
    demo.setSpacing(kTestSpacing);
    QVERIFY(!demo.isGenerated());
    QSignalSpy added(&m_tasks, &TaskManager::taskAdded);
    QCOMPARE(prepareAndWait(demo), demo.projectPath());
    QCOMPARE(added.size(), 1); // one task for the whole demo
    QCOMPARE(added.first().at(1).toString(), QString("Preparing the demo scene"));
    QVERIFY(demo.isGenerated());
    QVERIFY(!demo.isPreparing());
    // Only the project, its stamp and the four octrees: the scans and the scratch folder are gone.
    QCOMPARE(QDir(dir).entryList(QDir::Files | QDir::Hidden | QDir::AllDirs | QDir::NoDotAndDotDot, QDir::Name),
             QStringList(
                 {"demo.stylos", "demo.version", "drum.poct", "fragment-a.poct", "fragment-b.poct", "omphalos.poct"}));

    auto project = core::scene::ProjectFile::load(demo.projectPath().toStdString());
    QVERIFY(project.ok());
    QVERIFY(project->problems.empty());
    const auto& fragments = project->scene.fragments();
    QCOMPARE(fragments.size(), 4u);
    const QStringList names{"Drum", "Fragment A", "Fragment B", "Omphalos"};
    std::vector<Bounds> bounds;
    for (std::size_t i = 0; i < 4; ++i) {
        const auto& f = fragments[i];
        QCOMPARE(QString::fromStdString(f.name), names[int(i)]);
        QCOMPARE(QString::fromStdString(f.octreePath.string()), demo.paths()[int(i)]);
        QVERIFY(f.pose.isRigid(1e-9));
        QVERIFY(f.visible);
        QCOMPARE(f.colour, core::scene::defaultFragmentColour(i));

        auto octree = core::octree::PackedOctree::open(f.octreePath);
        QVERIFY2(octree.ok(), octree.ok() ? "" : octree.error().message.c_str());
        const std::uint64_t leaves = octree->cellCount(octree->depth());
        QVERIFY(leaves > 1000);
        const auto ambient = octree->attribute(core::ao::AmbientLayerName);
        QVERIFY(ambient.has_value());
        QCOMPARE(ambient->type, core::octree::AttributeType::Float32);
        QCOMPARE(int(ambient->components), 1);
        QCOMPARE(ambient->bytes.size(), std::size_t(leaves * 4));
        double sum = 0, lowest = 1;
        for (std::uint64_t k = 0; k < leaves; ++k) {
            float v;
            std::memcpy(&v, ambient->bytes.data() + 4 * k, 4);
            QVERIFY(v >= 0.0f && v <= 1.0f);
            sum += v;
            lowest = std::min(lowest, double(v));
        }
        qInfo("%s: %llu leaves, ambient mean %.3f, lowest %.3f", qPrintable(names[int(i)]),
              static_cast<unsigned long long>(leaves), sum / double(leaves), lowest);
        QVERIFY(sum / double(leaves) > 0.3); // mostly open sky...
        QVERIFY(lowest < 0.8);               // ...with shadowed places (flutes, the net, fractures)
        bounds.push_back(sceneBounds(*octree, project->scene.worldPose(f.id)));
        const Bounds& b = bounds.back();
        qInfo("  scene bounds x [%.3f, %.3f] y [%.3f, %.3f] z [%.3f, %.3f]", b.lo[0], b.hi[0], b.lo[1], b.hi[1],
              b.lo[2], b.hi[2]);
        QVERIFY2(std::abs(bounds.back().lo[2]) < 0.02, qPrintable(names[int(i)])); // standing on the ground
    }

    // The drum at the origin, turned about its vertical axis only, with its axis guide.
    const auto& drum = fragments[0];
    QCOMPARE(drum.pose.translationPart(), (std::array<double, 3>{0, 0, 0}));
    QCOMPARE(drum.pose(2, 2), 1.0);
    QCOMPARE(drum.guides.size(), 49u); // the axis and 48 flutes
    QCOMPARE(drum.guides[0].kind, core::scene::GuideKind::Axis);
    QCOMPARE(drum.guides[0].direction, (std::array<double, 3>{0, 0, 1}));
    for (std::size_t k = 1; k < drum.guides.size(); ++k) {
        QCOMPARE(drum.guides[k].kind, core::scene::GuideKind::Groove);
        QCOMPARE(drum.guides[k].direction, (std::array<double, 3>{0, 0, 1}));
        const double r = std::hypot(drum.guides[k].origin[0], drum.guides[k].origin[1]);
        QVERIFY2(std::abs(r - (0.55 - 0.008)) < 1e-12, qPrintable(QString::number(r))); // a flute's bottom
    }
    QCOMPARE(drum.guides[1].name, std::string("Flute 1"));
    // The drum comes annotated: fractured marble over its broken region, a plaster patch, the rest preserved;
    // the claw band in the tool-mark layer. The other objects carry no labels.
    {
        auto octree = core::octree::PackedOctree::open(drum.octreePath);
        QVERIFY(octree.ok());
        auto material = core::annotation::readLeafLabels(*octree, core::annotation::AnnotationLayer::Material);
        auto toolmark = core::annotation::readLeafLabels(*octree, core::annotation::AnnotationLayer::Toolmark);
        QVERIFY(material.ok() && toolmark.ok());
        std::array<std::uint64_t, 5> m{}, t{};
        for (const auto id : *material) ++m[std::min<std::size_t>(id, 4)];
        for (const auto id : *toolmark) ++t[std::min<std::size_t>(id, 4)];
        QCOMPARE(m[0], 0u);
        QVERIFY(m[1] > m[2] && m[2] > 0 && m[3] > 0);
        QCOMPARE(m[4], 0u);
        QVERIFY(t[3] > 0 && t[0] > t[3]);
        QCOMPARE(t[1] + t[2] + t[4], 0u);
        auto omphalos = core::octree::PackedOctree::open(fragments[3].octreePath);
        QVERIFY(omphalos.ok());
        QVERIFY(!omphalos->attribute("material").has_value());
    }
    QCOMPARE(bounds[0].hi[2] - bounds[0].lo[2] > 0.45, true); // half a metre high
    // Fragment A is of the drum's design, in "Drum 1 reconstruction" docking against the drum, where the layout put it.
    QCOMPARE(project->scene.assemblies().size(), 1u);
    const auto& assembly = project->scene.assemblies()[0];
    QCOMPARE(assembly.name, std::string("Drum 1 reconstruction"));
    QCOMPARE(assembly.drum, drum.id);
    QCOMPARE(project->scene.membersOf(assembly.id), std::vector<core::scene::FragmentId>{fragments[1].id});
    QCOMPARE(fragments[1].pose, core::scene::Pose());
    // Fragment A upright, fragment B lying (its parent drum's axis now horizontal), the omphalos to the left.
    QVERIFY(std::abs(project->scene.worldPose(fragments[1].id)(2, 2) - 1.0) < 1e-12);
    QVERIFY(std::abs(fragments[2].pose(2, 2)) < 1e-12);
    QCOMPARE(fragments[3].pose.translationPart(), (std::array<double, 3>{-1.4, 0.1, 0.0}));
    QVERIFY(bounds[3].hi[0] < bounds[0].lo[0]);
    QVERIFY(bounds[1].lo[0] > bounds[0].hi[0] && bounds[2].lo[0] > bounds[0].hi[0]);
    // No two fragments overlap on the ground.
    for (std::size_t a = 0; a < 4; ++a)
        for (std::size_t b = a + 1; b < 4; ++b) {
            const bool apart = bounds[a].hi[0] < bounds[b].lo[0] || bounds[b].hi[0] < bounds[a].lo[0] ||
                               bounds[a].hi[1] < bounds[b].lo[1] || bounds[b].hi[1] < bounds[a].lo[1];
            QVERIFY2(apart, qPrintable(names[int(a)] + " / " + names[int(b)]));
        }
}

void DemoSceneTest::secondPrepareReusesTheCache()
{
    const QString dir = generatedDirectory();
    const auto before = modificationTimes(dir);
    QCOMPARE(before.size(), 6);
    DemoScene demo(m_tasks, dir);
    demo.setSpacing(kTestSpacing);
    QVERIFY(demo.isGenerated());
    QSignalSpy ready(&demo, &DemoScene::ready);
    QVERIFY(demo.prepare());
    QVERIFY(!demo.isPreparing());
    QVERIFY(m_tasks.isIdle()); // nothing to generate
    QVERIFY(ready.isEmpty());  // queued, not emitted inside prepare()
    QVERIFY(ready.wait(5000));
    QCOMPARE(ready.first().at(0).toString(), demo.projectPath());
    QCOMPARE(modificationTimes(dir), before);
}

void DemoSceneTest::incompleteOrOutdatedCacheIsRegenerated()
{
    // The old PLY-only demo: no project, so it is regenerated, and its scans are removed.
    const QString dir = m_dir.filePath("stale");
    QDir().mkpath(dir);
    for (const char* name : {"drum.ply", "drum.truth.json", "omphalos.ply"})
        stylos::test::writeFile(dir, name, "old");
    DemoScene demo(m_tasks, dir);
    demo.setSpacing(kTestSpacing);
    QVERIFY(!demo.isGenerated());
    QCOMPARE(prepareAndWait(demo), demo.projectPath());
    QVERIFY(demo.isGenerated());
    QVERIFY(!QFileInfo::exists(dir + "/drum.ply") && !QFileInfo::exists(dir + "/drum.truth.json"));

    // A missing octree, another version's stamp, another spacing: incomplete, regenerated whole.
    QVERIFY(QFile::remove(demo.paths()[2]));
    QVERIFY(!demo.isGenerated());
    QCOMPARE(prepareAndWait(demo), demo.projectPath());
    QVERIFY(demo.isGenerated());

    stylos::test::writeFile(dir, "demo.version", "stylos-demo 1\n");
    QVERIFY(!demo.isGenerated());
    const QDateTime drumTime = QFileInfo(demo.paths()[0]).lastModified();
    QTest::qWait(20);
    QCOMPARE(prepareAndWait(demo), demo.projectPath());
    QVERIFY(demo.isGenerated());
    QVERIFY(QFileInfo(demo.paths()[0]).lastModified() > drumTime);

    DemoScene finer(m_tasks, dir);
    finer.setSpacing(kTestSpacing * 0.9);
    QVERIFY(!finer.isGenerated());
}

void DemoSceneTest::cancelLeavesNothing()
{
    const QString dir = m_dir.filePath("cancelled");
    DemoScene demo(m_tasks, dir);
    demo.setSpacing(kTestSpacing * 0.5); // long enough to cancel in the middle
    QSignalSpy cancelled(&demo, &DemoScene::cancelled);
    QSignalSpy ready(&demo, &DemoScene::ready);
    QSignalSpy progress(&m_tasks, &TaskManager::taskProgress);
    QVERIFY(demo.prepare());
    QVERIFY(demo.isPreparing());
    QVERIFY(!demo.prepare()); // already running
    // Cancel once the first item is done and its octree written.
    QTRY_VERIFY_WITH_TIMEOUT(QFileInfo::exists(demo.paths()[0]) || !ready.isEmpty(), 60000);
    QVERIFY(ready.isEmpty());
    demo.cancel();
    QVERIFY(cancelled.wait(60000));
    QVERIFY(ready.isEmpty());
    QVERIFY(!progress.isEmpty());
    QVERIFY(!demo.isPreparing());
    QVERIFY(!demo.isGenerated());
    QVERIFY(m_tasks.waitForIdle(10000));
    QCOMPARE(QDir(dir).entryList(QDir::Files | QDir::Hidden | QDir::AllDirs | QDir::NoDotAndDotDot), QStringList());
}

void DemoSceneTest::unwritableFolderFails()
{
    // The demo folder's place is taken by a file.
    const QString blocker = stylos::test::writeFile(m_dir.path(), "blocker", "x");
    DemoScene demo(m_tasks, blocker + "/demo");
    QSignalSpy failed(&demo, &DemoScene::failed);
    QVERIFY(demo.prepare());
    QVERIFY(failed.wait(5000));
    QVERIFY(failed.first().at(0).toString().contains("blocker"));
    QVERIFY(m_tasks.isIdle());
}

void DemoSceneTest::firstRunAtTheDefaultSpacing()
{
    // A measurement, not a check: STYLOS_DEMO_TIMING=1 [STYLOS_DEMO_SPACING=metres] DemoSceneTest
    // firstRunAtTheDefaultSpacing
    if (qEnvironmentVariableIsEmpty("STYLOS_DEMO_TIMING")) QSKIP("set STYLOS_DEMO_TIMING=1 to time the first run");
    QTemporaryDir dir;
    DemoScene demo(m_tasks, dir.filePath("demo"));
    if (const double spacing = qEnvironmentVariable("STYLOS_DEMO_SPACING").toDouble(); spacing > 0)
        demo.setSpacing(spacing);
    QElapsedTimer timer;
    timer.start();
    QCOMPARE(prepareAndWait(demo, 600000), demo.projectPath());
    const double seconds = timer.elapsed() / 1000.0;
    qInfo("first run at %.4g m: %.1f s", demo.spacing(), seconds);
    for (const QString& path : demo.paths()) {
        auto octree = core::octree::PackedOctree::open(path.toStdString());
        QVERIFY(octree.ok());
        qInfo("%s: depth %d, %llu leaves, %llu cells, %.1f MB", qPrintable(QFileInfo(path).fileName()), octree->depth(),
              static_cast<unsigned long long>(octree->cellCount(octree->depth())),
              static_cast<unsigned long long>(octree->totalCells()), octree->fileBytes() / 1e6);
    }
    // The point counts: the same scans through the public generator (same object and sampling, another pose).
    for (const DemoScene::Item& item : DemoScene::items()) {
        core::synth::SyntheticOptions options;
        options.spacing = demo.spacing();
        options.seed = item.seed;
        auto report = core::synth::generateScan(item.kind, options, dir.filePath("count.ply").toStdString());
        QVERIFY(report.ok());
        qInfo("%s: %llu points", qPrintable(item.name), static_cast<unsigned long long>(report->points));
    }
}

STYLOS_WIDGET_TEST_MAIN(DemoSceneTest)
#include "DemoSceneTest.moc"
