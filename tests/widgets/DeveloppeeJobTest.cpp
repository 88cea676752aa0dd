// DeveloppeeJob: a generated drum's .poct becomes a développée (image, heights and map of one size) through
// TaskManager; a pixel's 3D point lies on the drum; bad files come back as messages naming them; Cancel
// gives Cancelled and no result; the settings persist.
#include "DrumOctreeFixture.h"
#include "WidgetTestSupport.h"

#include "stylos/core/annotation/LabelRaster.h"
#include "stylos/core/cloud/LoadPointCloud.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/widgets/developpee/DeveloppeeJob.h"
#include "stylos/widgets/tasks/TaskManager.h"

#include <QDir>
#include <QImage>
#include <QProcess>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>

#include <atomic>
#include <limits>
#include <numbers>

using stylos::core::ErrorCode;
using stylos::core::ProgressSink;
using stylos::widgets::DeveloppeeJob;
using stylos::widgets::DeveloppeeResult;
using stylos::widgets::DeveloppeeSettings;
using stylos::widgets::DeveloppeeShading;
using stylos::widgets::TaskManager;

namespace {

/** Asks to cancel once progress reaches @p at. */
class CancelAt final : public ProgressSink {
public:
    explicit CancelAt(double at) : m_at(at) {}
    void update(double fraction) override
    {
        if (fraction >= m_at) m_cancel = true;
    }
    bool isCancelRequested() const override { return m_cancel; }

private:
    double m_at;
    std::atomic<bool> m_cancel{false};
};

/** Runs @p job on @p manager and returns its watcher once finished (QFAIL-free: callers check). */
QFutureWatcher<DeveloppeeResult>* runToEnd(TaskManager& manager, const DeveloppeeJob& job)
{
    auto* watcher = manager.start<DeveloppeeResult>(job.label(), job);
    QSignalSpy finished(watcher, &QFutureWatcherBase::finished);
    if (!finished.wait(60000)) return nullptr;
    return watcher;
}

} // namespace

class DeveloppeeJobTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void computesTheDrum();
    void aPixelMapsOntoTheDrum();
    void shadingsGiveImagesOfTheMapSize();
    void sameAsTheCommandLine();
    void invalidFileIsNamed();
    void missingFileIsNamed();
    void badSettingsAreRefused();
    void cancelGivesCancelledAndNoResult();
    void cancelThroughTheTaskManager();
    void settingsPersist();

private:
    QTemporaryDir m_dir;
    stylos::test::DrumOctree m_drum;
    QString m_poct;
};

void DeveloppeeJobTest::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_drum = stylos::test::makeDrumOctree(m_dir.path(), 0.01, 7);
    m_poct = QString::fromStdString(m_drum.poct.string());
}

void DeveloppeeJobTest::computesTheDrum()
{
    TaskManager manager;
    const DeveloppeeJob job(m_poct, 7, DeveloppeeSettings{});
    QVERIFY(job.label().contains(QStringLiteral("drum.poct")));
    auto* watcher = runToEnd(manager, job);
    QVERIFY(watcher);
    QVERIFY(!watcher->isCanceled());
    QCOMPARE(watcher->future().resultCount(), 1);
    const DeveloppeeResult r = watcher->result();
    QVERIFY2(r.ok(), qPrintable(r.error));
    QCOMPARE(r.fragmentId, quint64(7));
    QCOMPARE(r.octreePath, m_poct);
    QVERIFY(r.map && r.heights);
    // Image, heights and map agree on the size.
    QCOMPARE(r.image.width(), r.map->width());
    QCOMPARE(r.image.height(), r.map->height());
    QCOMPARE(r.heights->width(), r.map->width());
    QCOMPARE(r.heights->height(), r.map->height());
    QCOMPARE(r.image.format(), QImage::Format_ARGB32_Premultiplied);
    QCOMPARE(r.unroll.pixelSize, r.map->pixelSize());
    // The automatic pixel size of a .poct: the sampling spacing, at least three leaf edges; the width is
    // the circumference in pixels; the image covers the drum.
    auto octree = stylos::core::octree::PackedOctree::open(m_poct.toStdString());
    QVERIFY(octree.ok());
    const double leafEdge = std::ldexp(octree->box().size, -octree->depth());
    QVERIFY(r.unroll.samplingSpacing > 0.0);
    QCOMPARE(r.map->pixelSize(), std::max(r.unroll.samplingSpacing, stylos::core::unroll::kLeafEdgesPerPixel * leafEdge));
    QVERIFY2(r.unroll.coverage >= 0.9, qPrintable(QString::number(r.unroll.coverage)));
    QCOMPARE(r.map->width(), int(std::ceil(r.map->circumference() / r.map->pixelSize())));
    // Not blank: most pixels covered (a drum scanned all round), covered exactly where a height is, greys vary.
    qsizetype covered = 0;
    int lo = 255, hi = 0;
    for (int row = 0; row < r.image.height(); ++row)
        for (int column = 0; column < r.image.width(); ++column) {
            const QRgb p = r.image.pixel(column, row);
            QCOMPARE(qAlpha(p) == 255, r.heights->hasHeight(column, row));
            if (qAlpha(p) == 0) {
                QCOMPARE(p, QRgb(0));
                continue;
            }
            ++covered;
            QCOMPARE(qRed(p), qGreen(p));
            lo = std::min(lo, qRed(p));
            hi = std::max(hi, qRed(p));
        }
    QVERIFY2(covered > qsizetype(r.image.width()) * r.image.height() * 8 / 10, qPrintable(QString::number(covered)));
    QVERIFY(hi - lo > 128); // the stretched skydome spans the greys
    // The fit: a cylinder of the drum's radius about its axis.
    QCOMPARE(r.fit.surface.kind(), stylos::core::unroll::SurfaceKind::Cylinder);
    QVERIFY(std::abs(r.fit.surface.referenceRadius() - m_drum.truth["radius"].get<double>()) < 0.01);
    const auto& d = m_drum.truth["axis"]["direction"];
    const Eigen::Vector3d axis(d[0].get<double>(), d[1].get<double>(), d[2].get<double>());
    QVERIFY(std::abs(r.fit.surface.axis().direction.dot(axis.normalized())) > std::cos(std::numbers::pi / 180.0));
    QVERIFY(r.timings.total > 0.0 && r.timings.total >= r.timings.fit + r.timings.unroll);
    qInfo("drum: %d x %d pixels of %.2f mm, %llu points; load %.3f s, fit %.3f s, unroll %.3f s, shading %.3f s, total %.3f s",
          r.image.width(), r.image.height(), r.map->pixelSize() * 1e3, (unsigned long long)r.fit.points,
          r.timings.load, r.timings.fit, r.timings.unroll, r.timings.shading, r.timings.total);
}

void DeveloppeeJobTest::aPixelMapsOntoTheDrum()
{
    // The 3D point of a measured pixel (its centre at its height) lies on the drum, next to a leaf of the octree.
    auto computed = DeveloppeeJob(m_poct, 1, DeveloppeeSettings{}).run();
    QVERIFY(computed.ok());
    const DeveloppeeResult& r = *computed;
    auto cloud = stylos::core::cloud::loadPointCloud(m_drum.poct);
    QVERIFY(cloud.ok());
    const auto& a = m_drum.truth["axis"];
    const Eigen::Vector3d o(a["point"][0].get<double>(), a["point"][1].get<double>(), a["point"][2].get<double>());
    const Eigen::Vector3d dir =
        Eigen::Vector3d(a["direction"][0].get<double>(), a["direction"][1].get<double>(), a["direction"][2].get<double>())
            .normalized();
    int checked = 0;
    for (int row = r.map->height() / 4; row < r.map->height() * 3 / 4; row += 3)
        for (int column = 0; column < r.map->width(); column += 37) {
            if (r.heights->stateAt(column, row) != stylos::core::shading::PixelState::Measured) continue;
            const Eigen::Vector3d p = r.map->worldAtPixel(column + 0.5, row + 0.5, r.heights->heightAt(column, row));
            const Eigen::Vector3d d = p - o;
            const double radial = (d - d.dot(dir) * dir).norm();
            QVERIFY2(std::abs(radial - m_drum.truth["radius"].get<double>()) < 0.015, qPrintable(QString::number(radial)));
            double nearest = std::numeric_limits<double>::infinity();
            for (std::size_t i = 0; i < cloud->size(); ++i) nearest = std::min(nearest, (cloud->world(i) - p).norm());
            QVERIFY2(nearest < 2.0 * r.map->pixelSize(), qPrintable(QString::number(nearest)));
            // And back: the point lands in its pixel.
            const auto hit = r.map->pixelOf(p);
            QVERIFY(hit);
            QCOMPARE(int(std::floor(hit->column)), column);
            QCOMPARE(int(std::floor(hit->row)), row);
            ++checked;
        }
    QVERIFY(checked > 10);
    // The painting's pixel ↔ leaf index: every leaf at the pixel core::annotation::leafPixels gives, both ways.
    QVERIFY(r.leafIndex);
    // Painting takes the surface the développée shows: leaves under it (the bed faces' insides) are left out.
    const double depth = stylos::core::annotation::paintDepth(r.map->pixelSize());
    auto pixels = stylos::core::annotation::leafPixels(*m_drum.octree, *r.map, nullptr, depth);
    auto every = stylos::core::annotation::leafPixels(*m_drum.octree, *r.map);
    QVERIFY(pixels.ok() && every.ok());
    QCOMPARE(r.leafIndex->leafCount(), pixels->size());
    std::size_t hidden = 0;
    for (std::size_t leaf = 0; leaf < pixels->size(); ++leaf) {
        if ((*pixels)[leaf] >= 0) QCOMPARE((*pixels)[leaf], (*every)[leaf]);
        hidden += (*pixels)[leaf] < 0 && (*every)[leaf] >= 0 ? 1 : 0;
    }
    // Painting takes the surface the développée shows: the bed faces (edge-on to it) are left out.
    std::size_t mapped = 0;
    for (std::size_t leaf = 0; leaf < pixels->size(); ++leaf) {
        QCOMPARE(r.leafIndex->pixelOf(std::uint32_t(leaf)), (*pixels)[leaf]);
        if ((*pixels)[leaf] < 0) continue;
        ++mapped;
        const auto at = r.leafIndex->leavesAt(std::uint32_t((*pixels)[leaf]));
        QVERIFY(std::binary_search(at.begin(), at.end(), std::uint32_t(leaf)));
    }
    QCOMPARE(r.leafIndex->mappedLeafCount(), mapped);
    // Every pixel with a height shows some leaves' class (its own or its nearest ones'), none an unpainted speck; an
    // empty pixel shows none.
    std::size_t borrowers = 0;
    for (std::uint32_t p = 0; p < r.leafIndex->pixelCount(); ++p) {
        const bool height = r.heights->states()[p] != stylos::core::shading::PixelState::Empty;
        QCOMPARE(r.leafIndex->shownPixel(p) >= 0, height);
        borrowers += height && r.leafIndex->leavesAt(p).empty() ? 1 : 0;
    }
    QVERIFY(borrowers > 0); // filled pixels, and gaps of the leaves' grid
    // The lateral surface (about half the leaves of this drum, its two bed faces the other half) is painted.
    QVERIFY2(mapped > pixels->size() / 3 && hidden > pixels->size() / 4,
             qPrintable(QString("%1 mapped, %2 hidden of %3").arg(mapped).arg(hidden).arg(pixels->size())));
}

void DeveloppeeJobTest::shadingsGiveImagesOfTheMapSize()
{
    for (auto shading : {DeveloppeeShading::Height, DeveloppeeShading::Light}) {
        DeveloppeeSettings settings;
        settings.shading = shading;
        settings.pixelSize = 0.02; // a given pixel size is used
        auto computed = DeveloppeeJob(m_poct, 1, settings).run();
        QVERIFY(computed.ok());
        QCOMPARE(computed->map->pixelSize(), 0.02);
        QCOMPARE(computed->image.size(), QSize(computed->map->width(), computed->map->height()));
        QCOMPARE(computed->settings, settings);
    }
}

void DeveloppeeJobTest::invalidFileIsNamed()
{
    const QString path = stylos::test::writeFile(m_dir.path(), QStringLiteral("broken.poct"), "not an octree\n");
    TaskManager manager;
    auto* watcher = runToEnd(manager, DeveloppeeJob(path, 3, DeveloppeeSettings{}));
    QVERIFY(watcher);
    QCOMPARE(watcher->future().resultCount(), 1);
    const DeveloppeeResult r = watcher->result();
    QVERIFY(!r.ok());
    QVERIFY(!r.map && !r.heights && r.image.isNull());
    QCOMPARE(r.fragmentId, quint64(3));
    QVERIFY(r.errorCode.has_value());
    QVERIFY2(r.error.startsWith(QStringLiteral("Could not compute the développée of broken.poct: ")), qPrintable(r.error));
    QVERIFY2(r.error.contains(path), qPrintable(r.error)); // the core's detail names the whole path
}

void DeveloppeeJobTest::missingFileIsNamed()
{
    const QString path = m_dir.filePath(QStringLiteral("absent.poct"));
    auto computed = DeveloppeeJob(path, 1, DeveloppeeSettings{}).run();
    QVERIFY(!computed.ok());
    QCOMPARE(computed.error().code, ErrorCode::NotFound);
    const QString text = DeveloppeeJob::errorText(path, computed.error());
    QVERIFY2(text.startsWith(QStringLiteral("Could not compute the développée of absent.poct: the file does not exist.\n")),
             qPrintable(text));
}

void DeveloppeeJobTest::badSettingsAreRefused()
{
    DeveloppeeSettings settings;
    settings.directions = 0;
    QVERIFY(!settings.problem().isEmpty());
    auto computed = DeveloppeeJob(m_poct, 1, settings).run();
    QVERIFY(!computed.ok());
    QCOMPARE(computed.error().code, ErrorCode::InvalidArgument);
    QVERIFY(QString::fromStdString(computed.error().message).startsWith(m_poct + QStringLiteral(": ")));
    settings = {};
    settings.pixelSize = -1.0;
    QVERIFY(!settings.problem().isEmpty());
    settings = {};
    settings.axis = stylos::core::unroll::Axis{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    QVERIFY(!settings.problem().isEmpty());
}

void DeveloppeeJobTest::cancelGivesCancelledAndNoResult()
{
    const DeveloppeeJob job(m_poct, 1, DeveloppeeSettings{});
    // Cancelled at each step: reading, fitting, unrolling, shading.
    for (double at : {0.05, 0.2, 0.5, 0.8}) {
        CancelAt sink(at);
        auto computed = job.run(&sink);
        QVERIFY(!computed.ok());
        QCOMPARE(computed.error().code, ErrorCode::Cancelled);
    }
    // The task body adds nothing when cancelled.
    QPromise<DeveloppeeResult> promise;
    QFuture<DeveloppeeResult> future = promise.future();
    promise.start();
    CancelAt sink(0.5);
    job(promise, sink);
    promise.finish();
    QCOMPARE(future.resultCount(), 0);
}

void DeveloppeeJobTest::cancelThroughTheTaskManager()
{
    TaskManager manager;
    // A long job (a finer drum and many skydome directions: seconds) so that Cancel finds it running.
    QVERIFY(QDir(m_dir.path()).mkpath(QStringLiteral("fine")));
    const auto fine = stylos::test::makeDrumOctree(m_dir.filePath(QStringLiteral("fine")), 0.004, 9);
    DeveloppeeSettings slow;
    slow.directions = DeveloppeeSettings::MaxDirections;
    const DeveloppeeJob job(QString::fromStdString(fine.poct.string()), 1, slow);
    auto* watcher = manager.start<DeveloppeeResult>(job.label(), job);
    QSignalSpy finished(watcher, &QFutureWatcherBase::finished);
    QSignalSpy taskFinished(&manager, &TaskManager::taskFinished);
    // Cancel once it runs (or before: either way no result).
    QTRY_VERIFY_WITH_TIMEOUT(watcher->progressValue() > 0 || watcher->isFinished(), 30000);
    manager.cancel(manager.taskOf(watcher));
    QVERIFY(finished.wait(30000) || watcher->isFinished());
    QVERIFY(watcher->isCanceled());
    QCOMPARE(watcher->future().resultCount(), 0);
    QCOMPARE(taskFinished.size(), 1);
    QCOMPARE(taskFinished.at(0).at(1).toBool(), true);
}

void DeveloppeeJobTest::settingsPersist()
{
    QSettings store(m_dir.filePath(QStringLiteral("settings.ini")), QSettings::IniFormat);
    DeveloppeeSettings s;
    s.surface = stylos::core::unroll::SurfaceKind::Revolution;
    s.shading = DeveloppeeShading::Light;
    s.directions = 64;
    s.pixelSize = 0.0005;
    s.light.azimuth = 1.0;
    s.light.elevation = 0.5;
    s.stretch = false;
    s.save(store);
    QCOMPARE(DeveloppeeSettings::load(store), s);
    // Out-of-range values fall back to the defaults.
    store.setValue(QStringLiteral("developpee/directions"), 0);
    store.setValue(QStringLiteral("developpee/shading"), QStringLiteral("nonsense"));
    const DeveloppeeSettings loaded = DeveloppeeSettings::load(store);
    QCOMPARE(loaded.directions, DeveloppeeSettings{}.directions);
    QCOMPARE(loaded.shading, DeveloppeeSettings{}.shading);
    QCOMPARE(loaded.surface, s.surface);
}

void DeveloppeeJobTest::sameAsTheCommandLine()
{
    // The same settings in the Développée dock and on the command line give the same pixels: one
    // pipeline (core::developpee), one pixel-size rule, one quantisation to 8 bits.
    struct Case {
        DeveloppeeShading shading;
        QStringList args;
        double pixelSize;
    };
    const Case cases[] = {{DeveloppeeShading::Skydome, {QStringLiteral("--directions"), QStringLiteral("24")}, 0.0},
                          {DeveloppeeShading::Light, {}, 0.0},
                          {DeveloppeeShading::Height, {QStringLiteral("--pixel-size"), QStringLiteral("0.02")}, 0.02}};
    for (const Case& c : cases) {
        DeveloppeeSettings settings;
        settings.shading = c.shading;
        settings.directions = 24;
        settings.pixelSize = c.pixelSize;
        auto made = DeveloppeeJob(m_poct, 1, settings).run();
        QVERIFY2(made.ok(), made.ok() ? "" : made.error().message.c_str());

        const QString png = m_dir.filePath(QStringLiteral("cli-%1.png").arg(DeveloppeeSettings::shadingKey(c.shading)));
        QProcess cli;
        cli.start(QStringLiteral(STYLOS_CLI),
                  QStringList{QStringLiteral("unroll"), m_poct, QStringLiteral("-o"), png, QStringLiteral("--shading"),
                              QString::fromLatin1(DeveloppeeSettings::shadingKey(c.shading))} + c.args);
        QVERIFY(cli.waitForFinished(120000));
        QVERIFY2(cli.exitCode() == 0, cli.readAllStandardError().constData());
        QImage written(png);
        QVERIFY(!written.isNull());
        written = written.convertToFormat(QImage::Format_ARGB32);
        const QImage shown = made->image.convertToFormat(QImage::Format_ARGB32);
        QCOMPARE(written.size(), shown.size());
        int differing = 0;
        for (int row = 0; row < shown.height(); ++row)
            for (int column = 0; column < shown.width(); ++column)
                if (written.pixel(column, row) != shown.pixel(column, row)) ++differing;
        QCOMPARE(differing, 0);
    }
}

STYLOS_WIDGET_TEST_MAIN(DeveloppeeJobTest)
#include "DeveloppeeJobTest.moc"
