// The 3D view's seams: a custom ViewportTool receives the mouse, wheel and key events first and, when it
// consumes them, navigation does not move the camera (what it leaves goes to navigation); its cursor shows;
// resetTool() brings navigation back. A ViewOverlay is initialised, drawn after the points with the camera's
// matrices (read back from an offscreen render: its colour at its pixels), and released when removed.
#include "DrumOctreeFixture.h"
#include "WidgetTestSupport.h"

#include "stylos/widgets/view3d/ViewOverlay.h"
#include "stylos/widgets/view3d/ViewportTool.h"
#include "stylos/widgets/view3d/ViewportWidget.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QWheelEvent>

#include <memory>

using stylos::core::view::ViewFragment;
using stylos::widgets::OverlayFrame;
using stylos::widgets::ViewOverlay;
using stylos::widgets::ViewportTool;
using stylos::widgets::ViewportWidget;

namespace {

/** Records what it is offered; consumes everything when `consume`. */
class RecordingTool : public ViewportTool {
public:
    struct Log {
        QStringList events;
        int activated = 0;
        int deactivated = 0;
    };

    RecordingTool(std::shared_ptr<Log> log, bool consume) : m_log(std::move(log)), m_consume(consume) {}

    void activate(ViewportWidget&) override { ++m_log->activated; }
    void deactivate(ViewportWidget&) override { ++m_log->deactivated; }
    bool mousePress(ViewportWidget&, QMouseEvent& e) override { return record("press", e.position().toPoint()); }
    bool mouseMove(ViewportWidget&, QMouseEvent& e) override { return record("move", e.position().toPoint()); }
    bool mouseRelease(ViewportWidget&, QMouseEvent& e) override { return record("release", e.position().toPoint()); }
    bool hover(ViewportWidget&, QMouseEvent& e) override { return record("hover", e.position().toPoint()); }
    bool wheel(ViewportWidget&, QWheelEvent& e) override { return record("wheel", QPoint(0, e.angleDelta().y())); }
    bool keyPress(ViewportWidget&, QKeyEvent& e) override { return record("key", QPoint(e.key(), 0)); }
    QCursor cursor() const override { return QCursor(Qt::CrossCursor); }

private:
    bool record(const char* what, const QPoint& p)
    {
        m_log->events << QStringLiteral("%1 %2,%3").arg(QLatin1String(what)).arg(p.x()).arg(p.y());
        return m_consume;
    }

    std::shared_ptr<Log> m_log;
    bool m_consume;
};

/** Clears a square of 20 × 20 device pixels around where a scene point projects, in pure green. */
class SquareOverlay : public ViewOverlay {
public:
    explicit SquareOverlay(const Eigen::Vector3d& point) : m_point(point) {}

    bool initialize() override
    {
        ++initialized;
        return true;
    }
    void release() override { ++released; }
    void draw(const OverlayFrame& frame) override
    {
        ++drawn;
        view = frame.view;
        projection = frame.projection;
        size = frame.size;
        const Eigen::Vector4d clip = frame.projection * frame.view * m_point.homogeneous();
        const double x = (clip.x() / clip.w() + 1) * 0.5 * frame.size.width();
        const double y = (clip.y() / clip.w() + 1) * 0.5 * frame.size.height(); // GL: from the bottom
        QOpenGLFunctions* f = QOpenGLContext::currentContext()->functions();
        f->glEnable(GL_SCISSOR_TEST);
        f->glScissor(int(x) - 10, int(y) - 10, 20, 20);
        f->glClearColor(0, 1, 0, 1);
        f->glClear(GL_COLOR_BUFFER_BIT);
        f->glDisable(GL_SCISSOR_TEST);
    }

    int initialized = 0, released = 0, drawn = 0;
    Eigen::Matrix4d view = Eigen::Matrix4d::Zero(), projection = Eigen::Matrix4d::Zero();
    QSize size;

private:
    Eigen::Vector3d m_point;
};

bool sameCamera(const stylos::core::view::Camera& a, const stylos::core::view::Camera& b)
{
    return a.viewMatrix() == b.viewMatrix() && a.projectionMatrix() == b.projectionMatrix();
}

} // namespace

class ViewportToolTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void aToolConsumesTheEventsFirst();
    void whatAToolLeavesGoesToNavigation();
    void anOverlayIsDrawnOverThePoints();

private:
    void waitRefined();

    QTemporaryDir m_dir;
    stylos::test::DrumOctree m_drum;
    std::unique_ptr<ViewportWidget> m_view;
};

void ViewportToolTest::initTestCase()
{
    if (!ViewportWidget::isSupported()) QSKIP("no OpenGL 3.3 on this platform (run under xvfb-run)");
    QVERIFY(m_dir.isValid());
    m_drum = stylos::test::makeDrumOctree(m_dir.path(), 0.02, 5);
    m_view = std::make_unique<ViewportWidget>();
    m_view->resize(320, 240);
    m_view->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_view.get()));
    ViewFragment f;
    f.id = 5;
    f.octree = m_drum.octree;
    m_view->setFragments({f});
    waitRefined();
    QVERIFY2(m_view->glError().isEmpty(), qPrintable(m_view->glError()));
}

void ViewportToolTest::waitRefined() { QTRY_VERIFY_WITH_TIMEOUT(m_view->isSettled(), 20000); }

void ViewportToolTest::aToolConsumesTheEventsFirst()
{
    auto log = std::make_shared<RecordingTool::Log>();
    QCOMPARE(m_view->cursor().shape(), Qt::ArrowCursor);
    m_view->setTool(std::make_unique<RecordingTool>(log, true));
    QVERIFY(m_view->tool() != nullptr);
    QCOMPARE(log->activated, 1);
    QCOMPARE(m_view->cursor().shape(), Qt::CrossCursor);

    QSignalSpy picked(m_view.get(), &ViewportWidget::pointPicked);
    QSignalSpy cameraChanged(m_view.get(), &ViewportWidget::cameraChanged);
    const auto camera = m_view->camera();
    const QPoint centre(160, 120);
    QTest::mousePress(m_view.get(), Qt::LeftButton, {}, centre);          // would start an orbit
    QTest::mouseMove(m_view.get(), centre + QPoint(40, 10));
    QTest::mouseRelease(m_view.get(), Qt::LeftButton, {}, centre + QPoint(40, 10));
    QTest::mouseClick(m_view.get(), Qt::LeftButton, {}, centre);         // would pick and mark
    QWheelEvent wheel(QPointF(centre), m_view->mapToGlobal(QPointF(centre)), {}, QPoint(0, 240), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(m_view.get(), &wheel);                        // would dolly
    QTest::keyClick(m_view.get(), Qt::Key_7);                             // would look from the top
    QMouseEvent hover(QEvent::MouseMove, QPointF(centre), m_view->mapToGlobal(QPointF(centre)), Qt::NoButton,
                      Qt::NoButton, Qt::NoModifier);
    QApplication::sendEvent(m_view.get(), &hover);

    QCOMPARE(log->events, (QStringList{"press 160,120", "move 200,130", "release 200,130", "press 160,120",
                                       "release 160,120", "wheel 0,240", "key 55,0", "hover 160,120"}));
    QVERIFY(sameCamera(m_view->camera(), camera)); // navigation did not move it
    QCOMPARE(cameraChanged.size(), 0);
    QCOMPARE(picked.size(), 0);
    QVERIFY(!m_view->marker());

    // Back to navigation: the same drag orbits.
    m_view->resetTool();
    QVERIFY(m_view->tool() == nullptr);
    QCOMPARE(log->deactivated, 1);
    QCOMPARE(m_view->cursor().shape(), Qt::ArrowCursor);
    QTest::mousePress(m_view.get(), Qt::LeftButton, {}, centre);
    QTest::mouseMove(m_view.get(), centre + QPoint(40, 10));
    QTest::mouseRelease(m_view.get(), Qt::LeftButton, {}, centre + QPoint(40, 10));
    QVERIFY(!sameCamera(m_view->camera(), camera));
    QVERIFY(cameraChanged.size() > 0);
    QCOMPARE(log->events.size(), 8); // the tool is gone: it saw nothing more
    waitRefined();
}

void ViewportToolTest::whatAToolLeavesGoesToNavigation()
{
    auto log = std::make_shared<RecordingTool::Log>();
    m_view->setTool(std::make_unique<RecordingTool>(log, false));
    const auto camera = m_view->camera();
    // The tool sees the key first, then navigation turns the view to the top.
    QTest::keyClick(m_view.get(), Qt::Key_7);
    QCOMPARE(log->events, QStringList{"key 55,0"});
    QVERIFY((m_view->camera().forward() + Eigen::Vector3d::UnitZ()).norm() < 1e-12);
    // The wheel dollies by 0.85 per step, after the tool saw it.
    const double distance = m_view->camera().distance();
    QWheelEvent wheel(QPointF(160, 120), m_view->mapToGlobal(QPointF(160, 120)), {}, QPoint(0, 120), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(m_view.get(), &wheel);
    QCOMPARE(log->events.last(), QStringLiteral("wheel 0,120"));
    QCOMPARE(m_view->camera().distance(), distance * 0.85);
    // Setting another tool deactivates this one.
    auto other = std::make_shared<RecordingTool::Log>();
    m_view->setTool(std::make_unique<RecordingTool>(other, true));
    QCOMPARE(log->deactivated, 1);
    QCOMPARE(other->activated, 1);
    m_view->resetTool();
    QCOMPARE(other->deactivated, 1);
    m_view->setCamera(camera, false);
    waitRefined();
}

void ViewportToolTest::anOverlayIsDrawnOverThePoints()
{
    // Over the middle of the drum: the points are there, then the overlay's green over them.
    const Eigen::Vector3d target = m_view->camera().target();
    const QPoint pixel(160, 120);
    const QRgb under = m_view->grabFramebuffer().pixel(pixel);
    QVERIFY(under != qRgb(0, 255, 0));
    QVERIFY(qRed(under) != 33 || qGreen(under) != 36); // not the background: the drum is there

    auto overlay = std::make_shared<SquareOverlay>(target);
    m_view->addOverlay(overlay);
    QCOMPARE(overlay->initialized, 1); // the GL has started: at once
    m_view->addOverlay(overlay);       // already there: nothing
    QCOMPARE(overlay->initialized, 1);
    const QImage image = m_view->grabFramebuffer();
    QCOMPARE(image.pixel(pixel), qRgb(0, 255, 0));
    QCOMPARE(image.pixel(pixel + QPoint(8, 8)), qRgb(0, 255, 0));
    QVERIFY(image.pixel(pixel + QPoint(12, 12)) != qRgb(0, 255, 0)); // only its square
    QVERIFY(overlay->drawn >= 1);
    QVERIFY(overlay->view == m_view->camera().viewMatrix());
    QVERIFY(overlay->projection == m_view->camera().projectionMatrix());
    QCOMPARE(overlay->size, QSize(320, 240) * m_view->devicePixelRatio());
    // The marker, the first overlay, stays drawn; overlays after it draw over it.
    QCOMPARE(m_view->renderer().overlays().size(), 2u);
    QVERIFY(m_view->renderer().overlays().back() == overlay);

    QVERIFY(m_view->removeOverlay(overlay.get()));
    QCOMPARE(overlay->released, 1);
    QVERIFY(!m_view->removeOverlay(overlay.get()));
    const int drawn = overlay->drawn;
    QCOMPARE(m_view->grabFramebuffer().pixel(pixel), under);
    QCOMPARE(overlay->drawn, drawn);
}

STYLOS_WIDGET_TEST_MAIN(ViewportToolTest)
#include "ViewportToolTest.moc"
