// ViewportWidget: renders a small generated drum (.poct built in the test) with OpenGL 3.3 core under
// Xvfb/llvmpipe; the framebuffer is not blank and the drum covers the middle; a click in the middle
// picks a point of the drum's front surface (within a cell of the scanned samples); keys and markers;
// a pose change moves the drawn fragment without a new cut; the orbit and pose benchmarks.
#include "DrumOctreeFixture.h"
#include "WidgetTestSupport.h"

#include "stylos/core/ao/AoExport.h"
#include "stylos/core/io/PointFileFormat.h"
#include "stylos/core/io/PointReader.h"
#include "stylos/widgets/view3d/OrbitBenchmark.h"
#include "stylos/widgets/view3d/PoseBenchmark.h"
#include "stylos/widgets/view3d/ViewportWidget.h"

#include <Eigen/Geometry>

#include <QImage>
#include <QJsonObject>
#include <QSignalSpy>
#include <QTemporaryDir>

#include <limits>

using stylos::core::view::StandardView;
using stylos::core::view::ViewFragment;
using stylos::widgets::OrbitBenchmark;
using stylos::widgets::PoseBenchmark;
using stylos::widgets::ViewportWidget;

namespace {

bool isBackground(QRgb c) { return qAbs(qRed(c) - 33) <= 3 && qAbs(qGreen(c) - 36) <= 3 && qAbs(qBlue(c) - 41) <= 3; }

double coveredFraction(const QImage& image, const QRect& rect)
{
    int covered = 0;
    for (int y = rect.top(); y <= rect.bottom(); ++y)
        for (int x = rect.left(); x <= rect.right(); ++x) covered += isBackground(image.pixel(x, y)) ? 0 : 1;
    return double(covered) / double(rect.width() * rect.height());
}

} // namespace

class ViewportTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void rendersTheDrum();
    void clickPicksTheSurface();
    void keysChangeTheView();
    void markerIsDrawn();
    void ambientShading();
    void aPoseChangeMovesTheDrawnFragmentWithoutACut();
    void aFragmentFarAwayLeavesTheDrumInView();
    void fragmentsArrivingOneByOneAreFramedUntilTheCameraMoves();
    void orbitBenchmarkReports();
    void poseBenchmarkReports();

private:
    void waitRefined();

    QTemporaryDir m_dir;
    stylos::test::DrumOctree m_drum;
    std::unique_ptr<ViewportWidget> m_view;
    std::vector<Eigen::Vector3d> m_samples;
};

void ViewportTest::initTestCase()
{
    if (!ViewportWidget::isSupported()) QSKIP("no OpenGL 3.3 on this platform (run under xvfb-run)");
    QVERIFY(m_dir.isValid());
    m_drum = stylos::test::makeDrumOctree(m_dir.path(), 0.01, 7);
    auto reader = stylos::core::io::openPointReader(m_drum.ply);
    QVERIFY(reader.ok());
    stylos::core::io::PointBatch batch;
    for (;;) {
        auto n = (*reader)->read(batch, 65536);
        QVERIFY(n.ok());
        if (*n == 0) break;
        for (std::size_t i = 0; i < batch.size(); ++i)
            m_samples.emplace_back(batch.positions[3 * i], batch.positions[3 * i + 1], batch.positions[3 * i + 2]);
    }
    QVERIFY(m_samples.size() > 10000);

    m_view = std::make_unique<ViewportWidget>();
    m_view->resize(400, 300);
    m_view->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_view.get()));
    ViewFragment f;
    f.id = 42;
    f.octree = m_drum.octree;
    m_view->setFragments({f});
    waitRefined();
    QVERIFY2(m_view->glError().isEmpty(), qPrintable(m_view->glError()));
}

void ViewportTest::waitRefined()
{
    QTRY_VERIFY_WITH_TIMEOUT(m_view->isSettled(), 20000);
    m_view->repaint();
}

void ViewportTest::rendersTheDrum()
{
    const QImage image = m_view->grabFramebuffer();
    if (qEnvironmentVariableIsSet("STYLOS_VIEWPORT_TEST_IMAGE")) // to look at it: the path of a PNG to write
        image.save(qEnvironmentVariable("STYLOS_VIEWPORT_TEST_IMAGE"));
    QCOMPARE(image.size(), QSize(400, 300) * m_view->devicePixelRatio());
    QVERIFY(m_view->lastPointsDrawn() == m_drum.octree->cellCount(7) || m_view->lastPointsDrawn() > 10000);
    QVERIFY(m_view->firstFrameMs() >= 0);
    const double all = coveredFraction(image, image.rect());
    QVERIFY2(all > 0.1 && all < 0.9, qPrintable(QString::number(all)));
    // The fitted drum covers the middle of the view, and it is shaded (not one flat colour).
    const QRect middle(image.width() / 2 - 10, image.height() / 2 - 10, 20, 20);
    QVERIFY2(coveredFraction(image, middle) > 0.95, qPrintable(QString::number(coveredFraction(image, middle))));
    QSet<QRgb> colours;
    for (int y = middle.top(); y <= middle.bottom(); ++y)
        for (int x = middle.left(); x <= middle.right(); ++x) colours.insert(image.pixel(x, y));
    QVERIFY(colours.size() > 3);
    // Corners are background.
    QVERIFY(isBackground(image.pixel(1, 1)));
    QVERIFY(isBackground(image.pixel(image.width() - 2, image.height() - 2)));
}

void ViewportTest::clickPicksTheSurface()
{
    QSignalSpy picked(m_view.get(), &ViewportWidget::pointPicked);
    const QPoint centre(200, 150);
    QTest::mouseClick(m_view.get(), Qt::LeftButton, {}, centre);
    QCOMPARE(picked.size(), 1);
    const auto point = picked.first().at(0).value<Eigen::Vector3d>();
    QCOMPARE(picked.first().at(1).value<quint64>(), 42u);
    QVERIFY(m_view->marker() && (*m_view->marker() - point).norm() == 0);

    // On the ray through the click, within the pick radius (3 px) and a cell.
    const double cell = m_drum.octree->box().cellSize(7);
    const auto& camera = m_view->camera();
    const auto ray = camera.rayAt(centre.x(), centre.y());
    const Eigen::Vector3d toPoint = point - ray.origin;
    const double along = toPoint.dot(ray.direction);
    const double off = (toPoint - along * ray.direction).norm();
    QVERIFY2(off <= 3.0 * along / (camera.pixelsPerMetre() * camera.distance()) + cell,
             qPrintable(QString::number(off)));
    // Within a cell of the scanned surface: the leaf holds a sample, within √3/2 of an edge of its centre.
    double nearest = std::numeric_limits<double>::infinity();
    for (const Eigen::Vector3d& s : m_samples) nearest = std::min(nearest, (s - point).norm());
    QVERIFY2(nearest <= 0.87 * cell, qPrintable(QString("%1 > %2").arg(nearest).arg(cell)));
    // The front of the drum: nearer the eye than its axis.
    const auto& axis = m_drum.truth["axis"];
    const Eigen::Vector3d axisPoint(axis["point"][0], axis["point"][1], axis["point"][2]);
    const Eigen::Vector3d axisDirection(axis["direction"][0], axis["direction"][1], axis["direction"][2]);
    const Eigen::Vector3d axisMiddle = axisPoint + 0.25 * axisDirection; // the drum is 0.5 m high
    QVERIFY(along < (axisMiddle - ray.origin).dot(ray.direction));

    // Nothing is picked in an empty corner; a drag is not a click.
    QTest::mouseClick(m_view.get(), Qt::LeftButton, {}, QPoint(2, 2));
    QCOMPARE(picked.size(), 1);
    QTest::mousePress(m_view.get(), Qt::LeftButton, {}, centre);
    QTest::mouseMove(m_view.get(), centre + QPoint(30, 0));
    QTest::mouseRelease(m_view.get(), Qt::LeftButton, {}, centre + QPoint(30, 0));
    QCOMPARE(picked.size(), 1);
    waitRefined();
}

void ViewportTest::keysChangeTheView()
{
    QTest::keyClick(m_view.get(), Qt::Key_1);
    QVERIFY((m_view->camera().forward() - Eigen::Vector3d::UnitY()).norm() < 1e-12);
    QTest::keyClick(m_view.get(), Qt::Key_7);
    QVERIFY((m_view->camera().forward() + Eigen::Vector3d::UnitZ()).norm() < 1e-12);
    QTest::keyClick(m_view.get(), Qt::Key_5);
    QVERIFY(m_view->camera().isOrthographic());
    QTest::keyClick(m_view.get(), Qt::Key_5);
    QVERIFY(!m_view->camera().isOrthographic());
    QTest::keyClick(m_view.get(), Qt::Key_0);
    m_view->setCamera([&] {
        auto c = m_view->camera();
        c.dolly(5);
        c.pan(100, 0);
        return c;
    }());
    QTest::keyClick(m_view.get(), Qt::Key_F);
    { // Fit: every corner of the occupied cells in view, and the picture filling most of it along one axis.
        double loX = INFINITY, hiX = -INFINITY, loY = INFINITY, hiY = -INFINITY;
        for (const Eigen::Vector3d& corner : stylos::core::view::sceneCorners(m_view->fragments())) {
            const auto p = m_view->camera().project(corner);
            QVERIFY(p.has_value());
            loX = std::min(loX, p->x());
            hiX = std::max(hiX, p->x());
            loY = std::min(loY, p->y());
            hiY = std::max(hiY, p->y());
        }
        const double w = m_view->camera().width(), h = m_view->camera().height();
        QVERIFY2(loX >= -1e-6 && hiX <= w + 1e-6 && loY >= -1e-6 && hiY <= h + 1e-6,
                 qPrintable(QString("%1 %2 %3 %4").arg(loX).arg(hiX).arg(loY).arg(hiY)));
        QVERIFY(std::max((hiX - loX) / w, (hiY - loY) / h) > 0.85);
    }
    waitRefined();
    QVERIFY(coveredFraction(m_view->grabFramebuffer(), QRect(190, 140, 20, 20)) > 0.95);
}

void ViewportTest::markerIsDrawn()
{
    // A marker in an empty part of the view shows as non-background pixels there.
    const auto ray = m_view->camera().rayAt(20, 20);
    const Eigen::Vector3d point = ray.origin + ray.direction * m_view->camera().distance();
    QVERIFY(isBackground(m_view->grabFramebuffer().pixel(20, 20)));
    m_view->setMarker(point);
    QVERIFY(!isBackground(m_view->grabFramebuffer().pixel(20, 20)));
    m_view->setMarker(std::nullopt);
    QVERIFY(isBackground(m_view->grabFramebuffer().pixel(20, 20)));
}

void ViewportTest::ambientShading()
{
    // The same drum with an ambient layer of a everywhere: the Ambient shading is grey 0.95 · a² times the
    // headlight's 0.7 + 0.3 · lambert, so at one pixel, a = 0.5 gives a quarter of a = 1.
    const auto& octree = *m_drum.octree;
    const auto greyAt = [&](float a) {
        const std::vector<float> ambient(octree.cellCount(octree.depth()), a);
        const std::filesystem::path path = m_dir.filePath(QStringLiteral("ambient-%1.poct").arg(a)).toStdString();
        if (!stylos::core::ao::writeAmbientPoct(octree, ambient, path).ok()) return -1;
        auto opened = stylos::core::octree::PackedOctree::open(path);
        if (!opened.ok()) return -1;
        ViewFragment f;
        f.id = 42;
        f.octree = std::make_shared<const stylos::core::octree::PackedOctree>(std::move(opened.value()));
        m_view->setFragments({f});
        m_view->setShading(stylos::widgets::PointRenderer::Shading::Ambient);
        waitRefined();
        const QRgb c = m_view->grabFramebuffer().pixel(200, 150);
        return qRed(c) == qGreen(c) && qGreen(c) == qBlue(c) ? qRed(c) : -2; // grey
    };
    const int full = greyAt(1.0f);
    const int half = greyAt(0.5f);
    QVERIFY2(full >= int(0.95 * 0.7 * 255) - 1 && full <= int(0.95 * 255) + 1, qPrintable(QString::number(full)));
    QVERIFY2(std::abs(4 * half - full) <= 4, qPrintable(QStringLiteral("%1 %2").arg(half).arg(full)));
    // Colour shading without a colour layer falls back to the headlight: not grey.
    m_view->setShading(stylos::widgets::PointRenderer::Shading::Colour);
    waitRefined();
    const QRgb colour = m_view->grabFramebuffer().pixel(200, 150);
    QVERIFY(qRed(colour) != qBlue(colour)); // the fragment's warm default colour, lit
    m_view->setShading(stylos::widgets::PointRenderer::Shading::Headlight);
    waitRefined();
}

void ViewportTest::aPoseChangeMovesTheDrawnFragmentWithoutACut()
{
    waitRefined();
    const auto camera = m_view->camera();
    const std::uint64_t cuts = m_view->scheduler().cutsStarted();
    const auto before = m_view->renderer().points().modelMatrix(42);
    QVERIFY(before);
    const auto& origin = m_drum.octree->box().origin;
    Eigen::Matrix4d expectedBefore = Eigen::Matrix4d::Identity();
    expectedBefore.topRightCorner<3, 1>() << origin[0], origin[1], origin[2];
    QVERIFY(*before == expectedBefore); // identity pose · the buffer's origin
    QVERIFY(!isBackground(m_view->grabFramebuffer().pixel(200, 150)));

    // 150 pixels to the right at the target's depth: the drum leaves the middle of the view.
    Eigen::Matrix4d pose = Eigen::Matrix4d::Identity();
    pose.topRightCorner<3, 1>() = camera.right() * (150.0 / camera.pixelsPerMetre());
    QVERIFY(m_view->setFragmentPose(42, pose));
    QCOMPARE(m_view->scheduler().cutsStarted(), cuts); // no cut
    QVERIFY(m_view->scheduler().isMoving());
    QVERIFY(m_view->fragments().front().pose == pose);
    const auto after = m_view->renderer().points().modelMatrix(42);
    QVERIFY(after);
    QVERIFY((*after - pose * expectedBefore).cwiseAbs().maxCoeff() == 0); // the drawn model matrix
    const QImage image = m_view->grabFramebuffer();
    QVERIFY(isBackground(image.pixel(200, 150)));
    QVERIFY(!isBackground(image.pixel(350, 150)));
    QCOMPARE(m_view->scheduler().cutsStarted(), cuts); // drawing it started none either
    QVERIFY(!m_view->setFragmentPose(7, pose));      // no such fragment

    // Once still, the cut for the new pose follows; back where it was.
    waitRefined();
    QVERIFY(m_view->scheduler().cutsStarted() > cuts);
    QVERIFY(m_view->setFragmentPose(42, Eigen::Matrix4d::Identity()));
    waitRefined();
    QVERIFY(!isBackground(m_view->grabFramebuffer().pixel(200, 150)));
}

void ViewportTest::aFragmentFarAwayLeavesTheDrumInView()
{
    waitRefined();
    QVERIFY(!isBackground(m_view->grabFramebuffer().pixel(200, 150)));
    // A second fragment typed 10,000 km away (the scene's box then spans 10,000 km): the drum the camera
    // looks at stays drawn (the near plane was put at 1 km, a blank view until Fit).
    ViewFragment drum;
    drum.id = 42;
    drum.octree = m_drum.octree;
    ViewFragment far = drum;
    far.id = 43;
    far.pose.topRightCorner<3, 1>() = Eigen::Vector3d(1e7, 0, 0);
    m_view->setCamera(m_view->camera(), false); // the user's camera: a fragment that joins is not framed
    m_view->setFragments({drum, far});
    waitRefined();
    QVERIFY(m_view->camera().nearPlane() < 0.5 * m_view->camera().distance());
    QVERIFY(!isBackground(m_view->grabFramebuffer().pixel(200, 150)));
    m_view->setFragments({drum});
    waitRefined();
    QVERIFY(!isBackground(m_view->grabFramebuffer().pixel(200, 150)));
}

// Files imported together arrive one by one: each that joins is framed with the others while the camera has not been
// moved (before, only the first was: the drum imported last was out of view until Fit); once it has, it stays.
void ViewportTest::fragmentsArrivingOneByOneAreFramedUntilTheCameraMoves()
{
    ViewFragment drum;
    drum.id = 42;
    drum.octree = m_drum.octree;
    ViewFragment beside = drum;
    beside.id = 44;
    beside.pose.topRightCorner<3, 1>() = Eigen::Vector3d(3.0, 0, 0);
    ViewFragment further = drum;
    further.id = 45;
    further.pose.topRightCorner<3, 1>() = Eigen::Vector3d(0, 6.0, 0);
    const auto framed = [](stylos::core::view::Camera camera, const std::vector<ViewFragment>& fragments) {
        camera.fit(stylos::core::view::sceneCorners(fragments));
        return camera;
    };
    m_view->setFragments({});
    m_view->setFragments({drum});
    const auto alone = m_view->camera();
    m_view->setFragments({drum, beside}); // the second file finished: both framed
    const auto both = framed(alone, {drum, beside});
    QVERIFY(m_view->camera().target().isApprox(both.target(), 1e-9));
    QCOMPARE(m_view->camera().distance(), both.distance());
    QVERIFY((both.target() - alone.target()).norm() > 1.0); // a real move: the pair's middle, 1.5 m over
    auto turned = m_view->camera();
    turned.orbit(0.3, 0.0); // the user turns the view
    m_view->setCamera(turned, false);
    const Eigen::Vector3d target = m_view->camera().target();
    const double distance = m_view->camera().distance();
    m_view->setFragments({drum, beside, further});
    QVERIFY(m_view->camera().target() == target); // the user's view is kept
    QCOMPARE(m_view->camera().distance(), distance);
    m_view->fitToScene(); // Fit frames all, and framing goes on from there
    const auto all = m_view->camera();
    ViewFragment last = drum;
    last.id = 46;
    last.pose.topRightCorner<3, 1>() = Eigen::Vector3d(0, 0, 5.0);
    m_view->setFragments({drum, beside, further, last});
    QVERIFY(m_view->camera().target().isApprox(framed(all, {drum, beside, further, last}).target(), 1e-9));
    m_view->setFragments({drum});
    waitRefined();
}

void ViewportTest::orbitBenchmarkReports()
{
    OrbitBenchmark::Options options;
    options.frames = 12;
    options.degreesPerFrame = 5;
    OrbitBenchmark benchmark(*m_view, options);
    QSignalSpy finished(&benchmark, &OrbitBenchmark::finished);
    const Eigen::Vector3d target = m_view->camera().target();
    benchmark.start();
    QVERIFY(finished.wait(30000));
    const QJsonObject o = finished.first().at(0).toJsonObject();
    QCOMPARE(o["frames"].toInt(), 12);
    QVERIFY(o["medianMs"].toDouble() > 0);
    QVERIFY(o["p95Ms"].toDouble() >= o["medianMs"].toDouble());
    QVERIFY(o["meanPointsDrawn"].toDouble() > 1000);
    QCOMPARE(o["width"].toInt(), 400);
    QVERIFY(!o.contains("error"));
    QVERIFY((m_view->camera().target() - target).norm() < 1e-12); // orbits about the target

    // The summary, exactly: median of an even count, p95 by nearest rank.
    const QJsonObject s = OrbitBenchmark::summarize({4, 1, 3, 2}, {10, 20, 30, 40});
    QCOMPARE(s["medianMs"].toDouble(), 2.5);
    QCOMPARE(s["p95Ms"].toDouble(), 4.0);
    QCOMPARE(s["meanPointsDrawn"].toDouble(), 25.0);
}

void ViewportTest::poseBenchmarkReports()
{
    waitRefined();
    PoseBenchmark::Options options;
    options.frames = 12;
    options.degreesPerFrame = 5;
    PoseBenchmark benchmark(*m_view, options);
    QSignalSpy finished(&benchmark, &PoseBenchmark::finished);
    const auto camera = m_view->camera();
    const std::uint64_t cuts = m_view->scheduler().cutsStarted();
    const Eigen::Vector3d centre = m_view->sceneBounds().center();
    const Eigen::Matrix4d model = *m_view->renderer().points().modelMatrix(42);
    benchmark.start();
    QVERIFY(finished.wait(30000));
    const QJsonObject o = finished.first().at(0).toJsonObject();
    QVERIFY2(!o.contains("error"), qPrintable(o["error"].toString()));
    QCOMPARE(o["frames"].toInt(), 12);
    QCOMPARE(o["fragmentId"].toDouble(), 42.0);
    QCOMPARE(o["degreesPerFrame"].toDouble(), 5.0);
    QVERIFY(o["medianMs"].toDouble() > 0);
    QVERIFY(o["meanPointsDrawn"].toDouble() > 1000);
    QCOMPARE(m_view->scheduler().cutsStarted(), cuts); // twelve poses, not one cut
    QCOMPARE(o["cutsStarted"].toDouble(), 0.0);
    QVERIFY((m_view->camera().viewMatrix() - camera.viewMatrix()).cwiseAbs().maxCoeff() == 0); // the camera stays
    // The fragment turned 60° about the vertical through its centre.
    const Eigen::Affine3d turn = Eigen::Translation3d(centre) * Eigen::AngleAxisd(M_PI / 3, Eigen::Vector3d::UnitZ()) *
                                 Eigen::Translation3d(-centre);
    const Eigen::Matrix4d drawn = *m_view->renderer().points().modelMatrix(42);
    QVERIFY2((drawn - turn.matrix() * model).cwiseAbs().maxCoeff() < 1e-12,
             qPrintable(QString::number((drawn - turn.matrix() * model).cwiseAbs().maxCoeff())));

    // An unknown fragment is an error, at once.
    PoseBenchmark::Options none;
    none.frames = 3;
    none.fragmentId = 7;
    PoseBenchmark missing(*m_view, none);
    QSignalSpy failed(&missing, &PoseBenchmark::finished);
    m_view->setFragmentPose(42, Eigen::Matrix4d::Identity());
    waitRefined();
    missing.start();
    QVERIFY(failed.wait(30000));
    QCOMPARE(failed.first().at(0).toJsonObject()["frames"].toInt(), 0);
    QVERIFY(failed.first().at(0).toJsonObject()["error"].toString().contains("7"));
}

STYLOS_WIDGET_TEST_MAIN(ViewportTest)
#include "ViewportTest.moc"
