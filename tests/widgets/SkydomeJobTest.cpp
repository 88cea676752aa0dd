// SkydomeJob: a generated drum's .poct gets its "ambient" layer in place through TaskManager — one value in
// [0, 1] per leaf, the exact bits of the core called directly, the cells unchanged, the file re-read with the
// layer, the octree mapped before still readable; Cancel leaves the file byte-identical; bad files come back
// as messages naming them; SceneDocument::replaceOctree and SkydomeRunner hand the result to the document.
#include "DrumOctreeFixture.h"
#include "SceneTestSupport.h"
#include "WidgetTestSupport.h"

#include "stylos/core/ao/AoCells.h"
#include "stylos/core/ao/SkydomeLayer.h"
#include "stylos/core/ao/SkydomeSmoothing.h"
#include "stylos/widgets/document/SceneDocument.h"
#include "stylos/widgets/skydome/SkydomeJob.h"
#include "stylos/widgets/skydome/SkydomeRunner.h"
#include "stylos/widgets/tasks/TaskManager.h"

#include <QFile>
#include <QFileInfo>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QUndoStack>

#include <atomic>
#include <cstring>
#include <mutex>
#include <vector>

using stylos::core::ErrorCode;
using stylos::core::ProgressSink;
using stylos::core::octree::PackedOctree;
using stylos::widgets::SceneDocument;
using stylos::widgets::SkydomeJob;
using stylos::widgets::SkydomeOptions;
using stylos::widgets::SkydomeResult;
using stylos::widgets::SkydomeRunner;
using stylos::widgets::TaskManager;
namespace ao = stylos::core::ao;

namespace {

/** Records every fraction; asks to cancel once progress reaches @p at (never when @p at > 1). */
class Recorder final : public ProgressSink {
public:
    explicit Recorder(double at = 2.0) : m_at(at) {}
    void update(double fraction) override
    {
        std::lock_guard lock(m_mutex);
        m_fractions.push_back(fraction);
        if (fraction >= m_at) m_cancel = true;
    }
    bool isCancelRequested() const override { return m_cancel; }
    std::vector<double> fractions() const
    {
        std::lock_guard lock(m_mutex);
        return m_fractions;
    }

private:
    double m_at;
    std::atomic<bool> m_cancel{false};
    mutable std::mutex m_mutex;
    std::vector<double> m_fractions;
};

QByteArray fileBytes(const QString& path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

/** The core's own chain (as `stylos-cli ao`: leaf receivers against the level's cells): per-leaf values
 *  of @p path's octree. */
std::vector<float> coreValues(const QString& path, const SkydomeOptions& options, int* level = nullptr)
{
    auto octree = PackedOctree::open(path.toStdString());
    if (!octree) return {};
    const int l = options.level.value_or(ao::closedSurfaceLevel(*octree));
    if (level) *level = l;
    auto cells = ao::cellsAtLevel(*octree, l);
    if (!cells) return {};
    if (options.method == ao::AoMethod::Slices) { // the slices measure the cells, each leaf gets its cell's value
        auto values = ao::computeAmbientOcclusion(*cells, options.aoOptions());
        if (!values) return {};
        return ao::valuesPerLeaf(*cells, *values);
    }
    auto receivers = ao::leafReceivers(*octree, *cells);
    if (!receivers) return {};
    auto values = ao::computeAmbientOcclusion(*cells, *receivers, options.aoOptions());
    if (!values) return {};
    // Then the smoothing over neighbouring leaves, at the layer's default radius (in the receivers' unit, the
    // cells' edge).
    ao::SkydomeSmoothing smoothing;
    smoothing.radius = ao::SkydomeLayerOptions{}.smoothing;
    smoothing.threads = options.aoOptions().threads;
    if (!ao::smoothSkydome(*receivers, *values, smoothing)) return {};
    return std::move(values).value();
}

/** The "ambient" layer of @p octree as floats (empty without one). */
std::vector<float> ambientOf(const PackedOctree& octree)
{
    const auto layer = octree.attribute("ambient");
    if (!layer) return {};
    std::vector<float> values(layer->bytes.size() / sizeof(float));
    std::memcpy(values.data(), layer->bytes.data(), values.size() * sizeof(float));
    return values;
}

} // namespace

class SkydomeJobTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void addsTheAmbientLayerInPlace();
    void valuesAreTheCoresExactBits();
    void theOptionsReachTheCore();
    void cancelLeavesTheFileUntouched();
    void missingAndTruncatedFilesAreNamed();
    void aLevelOutOfRangeIsRefused();
    void replaceOctreeSignalsWithoutAnUndoStep();
    void theRunnerUpdatesTheDocument();
    void theRunnerReportsFailures();

private:
    /** A fresh copy of the drum's octree, so that each test starts without the layer. */
    QString copyOfDrum(const QString& name);

    QTemporaryDir m_dir;
    stylos::test::DrumOctree m_drum;
    QString m_poct;
    int m_copies = 0;
};

void SkydomeJobTest::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_drum = stylos::test::makeDrumOctree(m_dir.path(), 0.01, 7);
    m_poct = QString::fromStdString(m_drum.poct.string());
    QVERIFY(!m_drum.octree->attribute("ambient"));
}

QString SkydomeJobTest::copyOfDrum(const QString& name)
{
    const QString path = m_dir.filePath(QStringLiteral("%1-%2.poct").arg(name).arg(++m_copies));
    if (!QFile::copy(m_poct, path)) qFatal("cannot copy %s", qPrintable(m_poct));
    return path;
}

void SkydomeJobTest::addsTheAmbientLayerInPlace()
{
    const QString path = copyOfDrum(QStringLiteral("drum"));
    auto before = PackedOctree::open(path.toStdString());
    QVERIFY(before.ok());
    const PackedOctree& old = *before; // mapped before the job renames a new file over it
    const int leafLevel = old.depth();
    const std::vector<std::uint16_t> leafNormals(old.levelNormalCodes(leafLevel).begin(),
                                                 old.levelNormalCodes(leafLevel).end());

    TaskManager manager;
    const SkydomeJob job(path, 7, SkydomeOptions{}, QStringLiteral("Drum"));
    QCOMPARE(job.label(), QStringLiteral("Skydome of Drum"));
    QCOMPARE(SkydomeJob(path, 7).label(), QStringLiteral("Skydome of %1").arg(QFileInfo(path).fileName()));
    auto* watcher = manager.start<SkydomeResult>(job.label(), job);
    QSignalSpy finished(watcher, &QFutureWatcherBase::finished);
    QVERIFY(finished.wait(30000));
    QCOMPARE(watcher->future().resultCount(), 1);
    const SkydomeResult r = watcher->result();
    QVERIFY2(r.ok(), qPrintable(r.error));
    QCOMPARE(r.fragmentId, quint64(7));
    QCOMPARE(r.octreePath, path);
    QCOMPARE(r.directions, 128);
    QCOMPARE(r.level, ao::closedSurfaceLevel(old));
    QCOMPARE(r.cells, quint64(old.cellCount(r.level)));
    QCOMPARE(r.leaves, quint64(old.cellCount(leafLevel)));
    QVERIFY(r.seconds > 0.0);
    qInfo("drum: %llu leaves, %llu cells at level %d of %d, %d directions: %.3f s",
          (unsigned long long)r.leaves, (unsigned long long)r.cells, r.level, old.depth(), r.directions, r.seconds);

    // The returned octree and the file read again both hold the layer: Float32 × 1, a value per leaf in [0, 1].
    const auto layer = r.octree->attribute("ambient");
    QVERIFY(layer);
    QCOMPARE(layer->type, stylos::core::octree::AttributeType::Float32);
    QCOMPARE(layer->components, std::uint8_t(1));
    const std::vector<float> values = ambientOf(*r.octree);
    QCOMPARE(quint64(values.size()), r.leaves);
    int lit = 0;
    for (float v : values) {
        QVERIFY(v >= 0.0f && v <= 1.0f);
        lit += v > 0.0f;
    }
    QVERIFY(lit > int(values.size()) / 2); // the outside of a drum sees the sky
    auto reread = PackedOctree::open(path.toStdString());
    QVERIFY(reread.ok());
    QVERIFY(ambientOf(*reread) == values);
    // The cells are copied unchanged.
    QCOMPARE(reread->depth(), old.depth());
    for (int l = 0; l <= old.depth(); ++l) QCOMPARE(reread->cellCount(l), old.cellCount(l));
    QVERIFY(std::equal(leafNormals.begin(), leafNormals.end(), reread->levelNormalCodes(leafLevel).begin(),
                       reread->levelNormalCodes(leafLevel).end()));
    // The octree mapped before the rename still reads its old file (no layer, same cells).
    QVERIFY(!old.attribute("ambient"));
    QVERIFY(std::equal(leafNormals.begin(), leafNormals.end(), old.levelNormalCodes(leafLevel).begin(),
                       old.levelNormalCodes(leafLevel).end()));
    // Nothing left beside the file, and a second run replaces the layer (same bits) rather than adding one.
    QVERIFY(!stylos::test::filesUnder(m_dir.path()).join(QLatin1Char(' ')).contains(QStringLiteral(".tmp")));
    const qint64 size = QFileInfo(path).size();
    auto again = job.run();
    QVERIFY(again.ok());
    QCOMPARE(QFileInfo(path).size(), size);
    QCOMPARE(again->octree->attributes().size(), r.octree->attributes().size());
    QVERIFY(ambientOf(*again->octree) == values);
}

void SkydomeJobTest::valuesAreTheCoresExactBits()
{
    const QString path = copyOfDrum(QStringLiteral("bits"));
    const SkydomeOptions options;
    int level = -1;
    const std::vector<float> expected = coreValues(path, options, &level);
    QVERIFY(!expected.empty());
    auto r = SkydomeJob(path, 1, options).run();
    QVERIFY(r.ok());
    QCOMPARE(r->level, level);
    const std::vector<float> got = ambientOf(*r->octree);
    QCOMPARE(got.size(), expected.size());
    QVERIFY(std::memcmp(got.data(), expected.data(), got.size() * sizeof(float)) == 0);
}

void SkydomeJobTest::theOptionsReachTheCore()
{
    const QString path = copyOfDrum(QStringLiteral("options"));
    SkydomeOptions options;
    options.directions = 24;
    options.level = m_drum.octree->depth() - 2;
    options.method = ao::AoMethod::Slices;
    options.threads = 1; // one worker: progress comes in order
    const std::vector<float> expected = coreValues(path, options);
    Recorder progress;
    auto r = SkydomeJob(path, 1, options).run(&progress);
    QVERIFY(r.ok());
    QCOMPARE(r->level, *options.level);
    QCOMPARE(r->directions, 24);
    QCOMPARE(r->cells, quint64(m_drum.octree->cellCount(*options.level)));
    const std::vector<float> got = ambientOf(*r->octree);
    QCOMPARE(got.size(), expected.size());
    QVERIFY(std::memcmp(got.data(), expected.data(), got.size() * sizeof(float)) == 0);
    // Progress: never backwards, through the reading, computing and writing marks, ending at 1.
    const std::vector<double> f = progress.fractions();
    QVERIFY(!f.empty());
    QVERIFY(std::is_sorted(f.begin(), f.end()));
    QCOMPARE(f.back(), 1.0);
    QVERIFY(std::find(f.begin(), f.end(), 0.9) != f.end()); // the write begins (core::ao::computeSkydomeLayer)
    QVERIFY(std::any_of(f.begin(), f.end(), [](double x) { return x > 0.1 && x < 0.9; }));
}

void SkydomeJobTest::cancelLeavesTheFileUntouched()
{
    const QString path = copyOfDrum(QStringLiteral("cancel"));
    const QByteArray original = fileBytes(path);
    const QStringList files = stylos::test::filesUnder(m_dir.path());
    const SkydomeJob job(path, 1);
    // Cancelled once the cells are read, while computing, and once the skydome is done (just before the write).
    for (double at : {0.01, 0.5, 0.9}) {
        Recorder sink(at);
        auto r = job.run(&sink);
        QVERIFY(!r.ok());
        QCOMPARE(r.error().code, ErrorCode::Cancelled);
        QVERIFY(fileBytes(path) == original);
        QCOMPARE(stylos::test::filesUnder(m_dir.path()), files);
    }
    // The task body adds nothing when cancelled.
    QPromise<SkydomeResult> promise;
    QFuture<SkydomeResult> future = promise.future();
    promise.start();
    Recorder sink(0.5);
    job(promise, sink);
    promise.finish();
    QCOMPARE(future.resultCount(), 0);
    QVERIFY(fileBytes(path) == original);
}

void SkydomeJobTest::missingAndTruncatedFilesAreNamed()
{
    const QString absent = m_dir.filePath(QStringLiteral("absent.poct"));
    TaskManager manager;
    auto* watcher = manager.start<SkydomeResult>(QStringLiteral("absent"), SkydomeJob(absent, 3));
    QSignalSpy finished(watcher, &QFutureWatcherBase::finished);
    QVERIFY(finished.wait(10000));
    QCOMPARE(watcher->future().resultCount(), 1);
    const SkydomeResult r = watcher->result();
    QVERIFY(!r.ok() && !r.octree);
    QCOMPARE(r.fragmentId, quint64(3));
    QCOMPARE(r.errorCode, std::optional<ErrorCode>(ErrorCode::NotFound));
    QVERIFY2(r.error.startsWith(QStringLiteral("Could not compute the skydome of absent.poct: the file does not exist.\n")),
             qPrintable(r.error));
    QVERIFY2(r.error.contains(absent), qPrintable(r.error));
    QVERIFY(!QFile::exists(absent));

    // The first half of the drum's file: refused, and left as it was.
    const QByteArray whole = fileBytes(m_poct);
    const QString cut = stylos::test::writeFile(m_dir.path(), QStringLiteral("cut.poct"), whole.left(whole.size() / 2));
    auto computed = SkydomeJob(cut, 1).run();
    QVERIFY(!computed.ok());
    QCOMPARE(computed.error().code, ErrorCode::Truncated);
    const QString text = SkydomeJob::errorText(cut, computed.error());
    QVERIFY2(text.startsWith(QStringLiteral("Could not compute the skydome of cut.poct: the file is truncated.\n")),
             qPrintable(text));
    QVERIFY2(text.contains(cut), qPrintable(text));
    QVERIFY(fileBytes(cut) == whole.left(whole.size() / 2));
}

void SkydomeJobTest::aLevelOutOfRangeIsRefused()
{
    const QString path = copyOfDrum(QStringLiteral("level"));
    const QByteArray original = fileBytes(path);
    SkydomeOptions options;
    options.level = m_drum.octree->depth() + 1;
    auto r = SkydomeJob(path, 1, options).run();
    QVERIFY(!r.ok());
    QCOMPARE(r.error().code, ErrorCode::InvalidArgument);
    QVERIFY2(QString::fromStdString(r.error().message).contains(path), r.error().message.c_str());
    options = {};
    options.directions = 0;
    r = SkydomeJob(path, 1, options).run();
    QVERIFY(!r.ok());
    QCOMPARE(r.error().code, ErrorCode::InvalidArgument);
    QVERIFY(fileBytes(path) == original);
}

void SkydomeJobTest::replaceOctreeSignalsWithoutAnUndoStep()
{
    TaskManager tasks;
    SceneDocument doc(tasks);
    stylos::core::scene::Fragment f;
    f.name = "drum";
    f.octreePath = m_drum.poct;
    const auto id = doc.addFragment(f, m_drum.octree);
    const int steps = doc.undoStack()->count();
    doc.undoStack()->setClean();
    QSignalSpy changed(&doc, &SceneDocument::octreeChanged);
    QSignalSpy fragmentChanged(&doc, &SceneDocument::fragmentChanged);

    auto reopened = PackedOctree::open(m_drum.poct);
    QVERIFY(reopened.ok());
    const auto other = std::make_shared<const PackedOctree>(std::move(reopened).value());
    QVERIFY(doc.replaceOctree(id, other));
    QCOMPARE(doc.octree(id), SceneDocument::OctreePtr(other));
    QCOMPARE(changed.size(), 1);
    QCOMPARE(changed.at(0).at(0).toULongLong(), quint64(id));
    QCOMPARE(fragmentChanged.size(), 0);
    QCOMPARE(doc.undoStack()->count(), steps);
    QVERIFY(!doc.isModified());
    // Nothing for an unknown fragment or a null octree.
    QVERIFY(!doc.replaceOctree(id + 100, other));
    QVERIFY(!doc.replaceOctree(id, nullptr));
    QCOMPARE(doc.octree(id), SceneDocument::OctreePtr(other));
    QCOMPARE(changed.size(), 1);
}

void SkydomeJobTest::theRunnerUpdatesTheDocument()
{
    const QString path = copyOfDrum(QStringLiteral("runner"));
    auto opened = PackedOctree::open(path.toStdString());
    QVERIFY(opened.ok());
    TaskManager tasks;
    SceneDocument doc(tasks);
    stylos::core::scene::Fragment f;
    f.name = "drum";
    f.octreePath = path.toStdString();
    const auto id = doc.addFragment(f, std::make_shared<const PackedOctree>(std::move(opened).value()));
    const auto unknown = id + 100;
    SkydomeRunner runner(doc);
    QSignalSpy computed(&runner, &SkydomeRunner::computed);
    QSignalSpy failed(&runner, &SkydomeRunner::failed);
    QSignalSpy octreeChanged(&doc, &SceneDocument::octreeChanged);
    QSignalSpy taskAdded(&tasks, &TaskManager::taskAdded);

    QCOMPARE(runner.start({id, unknown}), 1);
    QVERIFY(runner.isRunning(id));
    QCOMPARE(runner.start({id}), 0); // already running
    QCOMPARE(taskAdded.size(), 1);
    QCOMPARE(taskAdded.at(0).at(1).toString(), QStringLiteral("Skydome of drum"));
    QVERIFY(computed.wait(30000));
    QCOMPARE(computed.at(0).at(0).toULongLong(), quint64(id));
    QCOMPARE(failed.size(), 0);
    QCOMPARE(octreeChanged.size(), 1);
    QVERIFY(!runner.isRunning(id));
    QCOMPARE(runner.count(), 0);
    QVERIFY(doc.octree(id)->attribute("ambient"));
    QCOMPARE(ambientOf(*doc.octree(id)).size(), std::size_t(doc.octree(id)->cellCount(doc.octree(id)->depth())));
    QCOMPARE(doc.undoStack()->count(), 1); // only the add is an undo step
}

void SkydomeJobTest::theRunnerReportsFailures()
{
    // A fragment whose file went away after it was opened: the job fails and the message names the file.
    const QString path = copyOfDrum(QStringLiteral("gone"));
    auto opened = PackedOctree::open(path.toStdString());
    QVERIFY(opened.ok());
    QVERIFY(QFile::remove(path));
    TaskManager tasks;
    SceneDocument doc(tasks);
    stylos::core::scene::Fragment f;
    f.name = "gone";
    f.octreePath = path.toStdString();
    const auto held = std::make_shared<const PackedOctree>(std::move(opened).value());
    const auto id = doc.addFragment(f, held);
    SkydomeRunner runner(doc);
    QSignalSpy failed(&runner, &SkydomeRunner::failed);
    QSignalSpy octreeChanged(&doc, &SceneDocument::octreeChanged);
    QCOMPARE(runner.start({id}), 1);
    QVERIFY(failed.wait(10000));
    QCOMPARE(failed.at(0).at(0).toULongLong(), quint64(id));
    const QString message = failed.at(0).at(1).toString();
    QVERIFY2(message.startsWith(QStringLiteral("Could not compute the skydome of %1: ").arg(QFileInfo(path).fileName())),
             qPrintable(message));
    QVERIFY2(message.contains(path), qPrintable(message));
    QCOMPARE(octreeChanged.size(), 0);
    QCOMPARE(doc.octree(id), SceneDocument::OctreePtr(held));
    // A new project cancels what runs: the file is left as it was.
    const QString kept = copyOfDrum(QStringLiteral("reset"));
    const QByteArray original = fileBytes(kept);
    auto keptOpened = PackedOctree::open(kept.toStdString());
    QVERIFY(keptOpened.ok());
    f.name = "kept";
    f.octreePath = kept.toStdString();
    const auto keptId = doc.addFragment(f, std::make_shared<const PackedOctree>(std::move(keptOpened).value()));
    QCOMPARE(runner.start({keptId}), 1);
    doc.newProject();
    QCOMPARE(runner.count(), 0);
    QVERIFY(tasks.waitForIdle(30000));
    QCOMPARE(octreeChanged.size(), 0);
    // Cancelled before the write (it then gives no result), or too late and the file has the layer: never half.
    const QByteArray after = fileBytes(kept);
    if (after != original) {
        auto reread = PackedOctree::open(kept.toStdString());
        QVERIFY(reread.ok() && reread->attribute("ambient"));
    }
}

STYLOS_WIDGET_TEST_MAIN(SkydomeJobTest)
#include "SkydomeJobTest.moc"
