// The docking gizmo in the 3D view, driven by synthesized mouse events: each handle dragged (World and
// Fragment arrows and rings, the Drum frame's θ ring and radial arrow) gives the pose expected to 1e-9 after
// snapping (1 mm, 0.1 mm with Shift, θ by the flute pitch or by degrees with Ctrl), one undo step per drag that
// undo() takes back exactly, Escape cancelling a drag, a press off the handles left to navigation, the hovered
// handle highlighted (its colour read back from the frame), Alt showing the tilts and L cycling the frame.
// The view is orthographic, looking down or from the front, at known pixels per metre.
#include "DrumOctreeFixture.h"
#include "WidgetTestSupport.h"

#include "stylos/core/scene/SceneEigen.h"
#include "stylos/core/view/GuideGeometry.h"
#include "stylos/widgets/docking/GizmoController.h"
#include "stylos/widgets/docking/GizmoTool.h"
#include "stylos/widgets/document/SceneDocument.h"
#include "stylos/widgets/tasks/TaskManager.h"
#include "stylos/widgets/view3d/ViewportWidget.h"

#include <QMouseEvent>
#include <QTemporaryDir>
#include <QUndoStack>

#include <Eigen/Geometry>

#include <cmath>
#include <memory>
#include <numbers>

using stylos::core::view::GizmoFrame;
using stylos::core::view::HandleRole;
using stylos::widgets::GizmoController;
using stylos::widgets::GizmoTool;
using stylos::widgets::SceneDocument;
using stylos::widgets::TaskManager;
using stylos::widgets::ViewportWidget;
namespace scene = stylos::core::scene;

namespace {

constexpr double Pi = std::numbers::pi;
constexpr double Degree = Pi / 180;

Eigen::Matrix4d translation(const Eigen::Vector3d& t)
{
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m.topRightCorner<3, 1>() = t;
    return m;
}

Eigen::Matrix4d rotationAbout(const Eigen::Vector3d& point, const Eigen::Vector3d& axis, double angle)
{
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    const Eigen::Matrix3d r = Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
    m.topLeftCorner<3, 3>() = r;
    m.topRightCorner<3, 1>() = point - r * point;
    return m;
}

bool near(const Eigen::Matrix4d& a, const Eigen::Matrix4d& b, double tolerance = 1e-9)
{
    return (a - b).cwiseAbs().maxCoeff() <= tolerance;
}

QByteArray show(const Eigen::Matrix4d& m)
{
    std::ostringstream s;
    s << m;
    return QByteArray::fromStdString(s.str());
}

} // namespace

class GizmoToolTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void init();
    void worldArrowSnapsByTheMillimetre();
    void shiftMovesATenthByTheTenthOfAMillimetre();
    void fragmentFrameArrowAndRing();
    void drumThetaSnapsByTheFlutePitch();
    void drumRadialArrowAndTilts();
    void escapeCancelsTheDrag();
    void aControllerGoneEndsItsDrag();
    void aDragBackToTheStartLeavesNoStep();
    void aPressOffTheHandlesIsNavigation();
    void theHoveredHandleIsHighlighted();
    void keyLCyclesTheFrames();

private:
    /** Orthographic camera from @p view of the scene centred on @p target at @p pixelsPerMetre. */
    void lookAt(stylos::core::view::StandardView view, const Eigen::Vector3d& target, double pixelsPerMetre);
    void press(const QPointF& p, Qt::KeyboardModifiers modifiers = {});
    void move(const QPointF& p, Qt::KeyboardModifiers modifiers = {}, Qt::MouseButtons buttons = Qt::LeftButton);
    void release(const QPointF& p);
    Eigen::Matrix4d poseOf(scene::FragmentId id) const { return scene::toEigen(m_document->fragment(id)->pose); }
    QPointF pixelOf(const Eigen::Vector3d& p) const
    {
        const auto q = m_view->camera().project(p);
        return {q->x(), q->y()};
    }
    GizmoTool* tool() const { return m_gizmo->tool(); }

    QTemporaryDir m_dir;
    stylos::test::DrumOctree m_drum;
    std::unique_ptr<TaskManager> m_tasks;
    std::unique_ptr<SceneDocument> m_document;
    std::unique_ptr<ViewportWidget> m_view;
    std::unique_ptr<GizmoController> m_gizmo;
    Eigen::Vector3d m_localCentre = Eigen::Vector3d::Zero();
    scene::FragmentId m_drumId = 0;
    scene::FragmentId m_pieceId = 0;
    Eigen::Matrix4d m_start = Eigen::Matrix4d::Identity(); ///< the piece's pose before each test
};

void GizmoToolTest::initTestCase()
{
    if (!ViewportWidget::isSupported()) QSKIP("no OpenGL 3.3 on this platform (run under xvfb-run)");
    QVERIFY(m_dir.isValid());
    m_drum = stylos::test::makeDrumOctree(m_dir.path(), 0.02, 5);
    m_localCentre = stylos::core::view::occupiedBounds(*m_drum.octree).center();
    m_view = std::make_unique<ViewportWidget>();
    m_view->resize(640, 480);
    m_view->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_view.get()));
    QTRY_COMPARE(m_view->camera().width(), 640);
    QCOMPARE(m_view->camera().height(), 480);
}

void GizmoToolTest::init()
{
    // A fresh document each test: the drum with its axis (vertical through its centre) and 48 flute guides,
    // and a piece (the same octree) 0.6 m along +X from it.
    m_gizmo.reset();
    m_document.reset();
    m_tasks = std::make_unique<TaskManager>();
    m_document = std::make_unique<SceneDocument>(*m_tasks);
    scene::Fragment drum;
    drum.name = "drum";
    drum.octreePath = m_drum.poct;
    drum.guides.push_back({"Axis", scene::GuideKind::Axis, scene::toArray(m_localCentre), {0, 0, 1}});
    for (int k = 0; k < 48; ++k)
        drum.guides.push_back({"Flute", scene::GuideKind::Groove, scene::toArray(m_localCentre), {0, 0, 1}});
    m_drumId = m_document->addFragment(drum, m_drum.octree);
    scene::Fragment piece;
    piece.name = "piece";
    piece.octreePath = m_drum.poct;
    piece.pose = scene::Pose::translation({0.6, 0, 0});
    m_pieceId = m_document->addFragment(piece, m_drum.octree);
    m_start = poseOf(m_pieceId);
    m_gizmo = std::make_unique<GizmoController>(*m_document, *m_view);
    m_gizmo->setFragment(m_pieceId);
    m_gizmo->setEnabled(true);
    QVERIFY(tool() != nullptr);
    QCOMPARE(tool()->targetId(), quint64(m_pieceId));
}

void GizmoToolTest::lookAt(stylos::core::view::StandardView view, const Eigen::Vector3d& target, double pixelsPerMetre)
{
    auto camera = m_view->camera();
    camera.setStandardView(view);
    camera.setOrthographic(true);
    camera.setTarget(target);
    camera.setDistance(240.0 / (pixelsPerMetre * std::tan(camera.fieldOfView() / 2)));
    m_view->setCamera(camera, false);
    QVERIFY(std::abs(m_view->camera().pixelsPerMetre() - pixelsPerMetre) < 1e-9);
}

void GizmoToolTest::press(const QPointF& p, Qt::KeyboardModifiers modifiers)
{
    QMouseEvent e(QEvent::MouseButtonPress, p, m_view->mapToGlobal(p), Qt::LeftButton, Qt::LeftButton, modifiers);
    QApplication::sendEvent(m_view.get(), &e);
}

void GizmoToolTest::move(const QPointF& p, Qt::KeyboardModifiers modifiers, Qt::MouseButtons buttons)
{
    QMouseEvent e(QEvent::MouseMove, p, m_view->mapToGlobal(p), Qt::NoButton, buttons, modifiers);
    QApplication::sendEvent(m_view.get(), &e);
}

void GizmoToolTest::release(const QPointF& p)
{
    QMouseEvent e(QEvent::MouseButtonRelease, p, m_view->mapToGlobal(p), Qt::LeftButton, Qt::NoButton, {});
    QApplication::sendEvent(m_view.get(), &e);
}

void GizmoToolTest::worldArrowSnapsByTheMillimetre()
{
    const Eigen::Vector3d centre = (m_start * m_localCentre.homogeneous()).head<3>();
    lookAt(stylos::core::view::StandardView::Top, centre, 1000); // a pixel is a millimetre
    m_gizmo->setFrame(GizmoFrame::World);
    const int steps = m_document->undoStack()->count();
    QSignalSpy readout(m_gizmo.get(), &GizmoController::dragReadout);
    const auto said = [&readout] { return readout.isEmpty() ? QStringLiteral("(nothing)") : readout.last().at(0).toString(); };
    const QPointF onX = pixelOf(centre) + QPointF(60, 0);
    press(onX);
    QVERIFY(tool()->isDragging());
    QCOMPARE(said(), QStringLiteral("Along X: 0.0 mm · Esc cancels"));
    move(onX + QPointF(10, 4));
    move(onX + QPointF(25, -3));
    move(onX + QPointF(37, 2)); // 37 mm along X; the cursor's drift across the arrow does nothing
    QCOMPARE(said(), QStringLiteral("Along X: +37.0 mm · Esc cancels"));
    release(onX + QPointF(37, 2));
    QVERIFY(!tool()->isDragging());
    QCOMPARE(said(), QString()); // the drag ended: the readout goes
    const Eigen::Matrix4d expected = translation({0.037, 0, 0}) * m_start;
    QVERIFY2(near(poseOf(m_pieceId), expected), show(poseOf(m_pieceId)));
    QCOMPARE(m_document->undoStack()->count(), steps + 1);
    m_document->undoStack()->undo();
    QVERIFY(poseOf(m_pieceId) == m_start);
    m_document->undoStack()->redo();
    QVERIFY(near(poseOf(m_pieceId), expected));
}

void GizmoToolTest::shiftMovesATenthByTheTenthOfAMillimetre()
{
    const Eigen::Vector3d centre = (m_start * m_localCentre.homogeneous()).head<3>();
    lookAt(stylos::core::view::StandardView::Top, centre, 1000);
    m_gizmo->setFrame(GizmoFrame::World);
    const QPointF onY = pixelOf(centre) + QPointF(0, -60); // +Y is up on screen
    press(onY, Qt::ShiftModifier);
    move(onY + QPointF(1, -20), Qt::ShiftModifier);
    move(onY + QPointF(2, -37), Qt::ShiftModifier); // 37 px at a tenth: 3.7 mm
    release(onY + QPointF(2, -37));
    QVERIFY2(near(poseOf(m_pieceId), translation({0, 0.0037, 0}) * m_start), show(poseOf(m_pieceId)));
    QCOMPARE(m_document->undoStack()->count(), 3); // two adds and the drag
}

void GizmoToolTest::fragmentFrameArrowAndRing()
{
    // The piece turned 30° about its centre: its own X axis points 30° from the scene's.
    const Eigen::Vector3d centre = (m_start * m_localCentre.homogeneous()).head<3>();
    const Eigen::Matrix4d turned = rotationAbout(centre, {0, 0, 1}, 30 * Degree) * m_start;
    QVERIFY(m_document->setFragmentPose(m_pieceId, scene::poseFromEigen(turned)));
    lookAt(stylos::core::view::StandardView::Top, centre, 1000);
    m_gizmo->setFrame(GizmoFrame::Fragment);
    QCOMPARE(tool()->effectiveFrame(), GizmoFrame::Fragment);
    const QPointF onX = pixelOf(centre + 0.06 * Eigen::Vector3d(std::cos(30 * Degree), std::sin(30 * Degree), 0));
    press(onX);
    move(onX + QPointF(43, -25)); // 43·cos 30° + 25·sin 30° = 49.74 px along the arrow → 50 mm
    release(onX + QPointF(43, -25));
    const Eigen::Matrix4d moved = translation(0.05 * Eigen::Vector3d(std::cos(30 * Degree), std::sin(30 * Degree), 0)) * turned;
    QVERIFY2(near(poseOf(m_pieceId), moved), show(poseOf(m_pieceId)));

    // Its Z ring (70 px about the centre, seen face on): from the ring's +X point to 45° → 45°, by degrees.
    const Eigen::Vector3d newCentre = (moved * m_localCentre.homogeneous()).head<3>();
    lookAt(stylos::core::view::StandardView::Top, newCentre, 1000);
    const QPointF c = pixelOf(newCentre);
    press(c + QPointF(70, 0));
    QVERIFY(tool()->isDragging());
    move(c + QPointF(49, -49));
    release(c + QPointF(49, -49));
    QVERIFY2(near(poseOf(m_pieceId), rotationAbout(newCentre, {0, 0, 1}, 45 * Degree) * moved),
             show(poseOf(m_pieceId)));
    QCOMPARE(m_document->undoStack()->count(), 5); // two adds, the typed pose, two drags
}

void GizmoToolTest::drumThetaSnapsByTheFlutePitch()
{
    QVERIFY(m_document->setDockingDrum(m_drumId));
    QCOMPARE(m_gizmo->frame(), GizmoFrame::Drum);
    QCOMPARE(tool()->effectiveFrame(), GizmoFrame::Drum);
    // Looking down the drum axis at 250 px/m: the θ ring (0.6 m) is 150 px about the axis.
    const Eigen::Vector3d axisPoint = m_localCentre;
    lookAt(stylos::core::view::StandardView::Top, axisPoint, 250);
    const QPointF axis = pixelOf(axisPoint);
    const auto onRing = [&axis](double degrees) {
        return axis + 150 * QPointF(std::cos(degrees * Degree), -std::sin(degrees * Degree)); // y down
    };
    press(onRing(-10)); // on the ring, away from the radial arrow
    QVERIFY(tool()->isDragging());
    QSignalSpy readout(m_gizmo.get(), &GizmoController::dragReadout);
    move(onRing(7)); // 17° → two flutes, 15°
    QVERIFY2(near(poseOf(m_pieceId), rotationAbout(axisPoint, {0, 0, 1}, 15 * Degree) * m_start), show(poseOf(m_pieceId)));
    QCOMPARE(readout.last().at(0).toString(), QStringLiteral("About the drum axis: +15.00° (2 flute(s)) · Esc cancels")); // "flutes": the English
                                                                                             // plural comes with the translator
    move(onRing(10)); // 20° → three flutes, 22.5°
    const Eigen::Matrix4d flutes = rotationAbout(axisPoint, {0, 0, 1}, 22.5 * Degree) * m_start;
    QVERIFY2(near(poseOf(m_pieceId), flutes), show(poseOf(m_pieceId)));
    move(onRing(10.3), Qt::ControlModifier); // Ctrl: by degrees → 20°
    QVERIFY2(near(poseOf(m_pieceId), rotationAbout(axisPoint, {0, 0, 1}, 20 * Degree) * m_start),
             show(poseOf(m_pieceId)));
    QCOMPARE(readout.last().at(0).toString(), QStringLiteral("About the drum axis: +20.00° · Esc cancels")); // not whole flutes
    move(onRing(10.3 + 3.14), Qt::ControlModifier | Qt::ShiftModifier); // a tenth of 3.14°: 20.614° → 20.6°
    QVERIFY2(near(poseOf(m_pieceId), rotationAbout(axisPoint, {0, 0, 1}, 20.6 * Degree) * m_start),
             show(poseOf(m_pieceId)));
    move(onRing(35)); // 45° → six flutes
    release(onRing(35));
    QVERIFY2(near(poseOf(m_pieceId), rotationAbout(axisPoint, {0, 0, 1}, 45 * Degree) * m_start),
             show(poseOf(m_pieceId)));
    QCOMPARE(m_document->undoStack()->count(), 3);
    m_document->undoStack()->undo();
    QVERIFY(poseOf(m_pieceId) == m_start);
}

void GizmoToolTest::drumRadialArrowAndTilts()
{
    QVERIFY(m_document->setDockingDrum(m_drumId));
    const Eigen::Vector3d centre = (m_start * m_localCentre.homogeneous()).head<3>();
    lookAt(stylos::core::view::StandardView::Top, m_localCentre, 250);
    // The radial arrow from the piece's centre outward (+X), 90 px: 13 px at 250 px/m = 52 mm.
    const QPointF onRadial = pixelOf(centre) + QPointF(60, 0);
    press(onRadial);
    move(onRadial + QPointF(13, 2));
    release(onRadial + QPointF(13, 2));
    const Eigen::Matrix4d out = translation({0.052, 0, 0}) * m_start;
    QVERIFY2(near(poseOf(m_pieceId), out), show(poseOf(m_pieceId)));

    // z along the axis, seen from the front at 1000 px/m: 21 px up = 21 mm.
    const Eigen::Vector3d outCentre = (out * m_localCentre.homogeneous()).head<3>();
    lookAt(stylos::core::view::StandardView::Front, outCentre, 1000);
    const QPointF onZ = pixelOf(outCentre) + QPointF(0, -50);
    press(onZ);
    move(onZ + QPointF(-2, -21));
    release(onZ + QPointF(-2, -21));
    const Eigen::Matrix4d up = translation({0, 0, 0.021}) * out;
    QVERIFY2(near(poseOf(m_pieceId), up), show(poseOf(m_pieceId)));

    // Alt shows the tilts; the tangential one (about +Y through the centre) is a 48 px ring seen face on from
    // the front (the radial one, about +X, edge-on, is hidden).
    const Eigen::Vector3d upCentre = (up * m_localCentre.homogeneous()).head<3>();
    lookAt(stylos::core::view::StandardView::Front, upCentre, 1000);
    move(pixelOf(upCentre) + QPointF(200, 200), Qt::AltModifier, Qt::NoButton);
    QVERIFY(tool()->tiltsShown());
    const auto shown = tool()->handles(m_view->camera());
    QCOMPARE(shown.size(), 4u); // z, r, θ and the tangential tilt; the radial tilt is edge-on
    QCOMPARE(shown.back().role, HandleRole::TiltTangential);
    const QPointF c = pixelOf(upCentre);
    press(c + 48 * QPointF(-std::cos(Pi / 4), -std::sin(Pi / 4)), Qt::AltModifier); // up and left on the ring
    QVERIFY(tool()->isDragging());
    move(c + QPointF(0, -48), Qt::AltModifier); // to the top
    release(c + QPointF(0, -48));
    // Seen from the front (looking along +Y), a turn about +Y by +a turns +Z toward +X, clockwise: +45°.
    QVERIFY2(near(poseOf(m_pieceId), rotationAbout(upCentre, {0, 1, 0}, 45 * Degree) * up), show(poseOf(m_pieceId)));
    QCOMPARE(m_document->undoStack()->count(), 5);
    move(pixelOf(upCentre) + QPointF(200, 200), {}, Qt::NoButton);
    QVERIFY(!tool()->tiltsShown());
}

void GizmoToolTest::escapeCancelsTheDrag()
{
    const Eigen::Vector3d centre = (m_start * m_localCentre.homogeneous()).head<3>();
    lookAt(stylos::core::view::StandardView::Top, centre, 1000);
    m_gizmo->setFrame(GizmoFrame::World);
    const QPointF onX = pixelOf(centre) + QPointF(60, 0);
    QSignalSpy readout(m_gizmo.get(), &GizmoController::dragReadout);
    press(onX);
    move(onX + QPointF(20, 0));
    move(onX + QPointF(30, 0));
    QVERIFY(near(poseOf(m_pieceId), translation({0.03, 0, 0}) * m_start));
    QCOMPARE(readout.last().at(0).toString(), QStringLiteral("Along X: +30.0 mm · Esc cancels"));
    QTest::keyClick(m_view.get(), Qt::Key_Escape);
    QVERIFY(!tool()->isDragging());
    QCOMPARE(readout.last().at(0).toString(), QString()); // cancelled: the readout goes
    QVERIFY(poseOf(m_pieceId) == m_start);
    QCOMPARE(m_document->undoStack()->count(), 2); // the drag left no step
    move(onX + QPointF(45, 0));                     // the rest of that drag does nothing
    release(onX + QPointF(45, 0));
    QVERIFY(poseOf(m_pieceId) == m_start);
    QCOMPARE(m_document->undoStack()->count(), 2);
}

// The view outlives the controller (a test's, or a window's teardown): the controller takes its tool away with it,
// cancelling a drag under way, so no later event or tool reaches the controller that is gone (it crashed).
void GizmoToolTest::aControllerGoneEndsItsDrag()
{
    const Eigen::Vector3d centre = (m_start * m_localCentre.homogeneous()).head<3>();
    lookAt(stylos::core::view::StandardView::Top, centre, 1000);
    m_gizmo->setFrame(GizmoFrame::World);
    const QPointF onX = pixelOf(centre) + QPointF(60, 0);
    press(onX);
    move(onX + QPointF(20, 0));
    QVERIFY(near(poseOf(m_pieceId), translation({0.02, 0, 0}) * m_start));
    m_gizmo.reset();
    QVERIFY(m_view->tool() == nullptr);
    QVERIFY(poseOf(m_pieceId) == m_start); // the drag was cancelled
    move(onX + QPointF(30, 0));
    release(onX + QPointF(30, 0));
    QVERIFY(poseOf(m_pieceId) == m_start);
}

void GizmoToolTest::aDragBackToTheStartLeavesNoStep()
{
    const Eigen::Vector3d centre = (m_start * m_localCentre.homogeneous()).head<3>();
    lookAt(stylos::core::view::StandardView::Top, centre, 1000);
    m_gizmo->setFrame(GizmoFrame::World);
    // A first drag: one step.
    const QPointF onX = pixelOf(centre) + QPointF(60, 0);
    press(onX);
    move(onX + QPointF(10, 0));
    release(onX + QPointF(10, 0));
    QCOMPARE(m_document->undoStack()->count(), 3);
    const Eigen::Matrix4d first = poseOf(m_pieceId);
    // A second one that comes back where it started, then goes on: its own step, never merged into the first.
    const QPointF again = onX + QPointF(10, 0);
    press(again);
    move(again + QPointF(5, 0));
    move(again);
    QCOMPARE(m_document->undoStack()->count(), 3);
    move(again + QPointF(-4, 0));
    release(again + QPointF(-4, 0));
    QCOMPARE(m_document->undoStack()->count(), 4);
    m_document->undoStack()->undo();
    QVERIFY(poseOf(m_pieceId) == first);
}

void GizmoToolTest::aPressOffTheHandlesIsNavigation()
{
    const Eigen::Vector3d centre = (m_start * m_localCentre.homogeneous()).head<3>();
    lookAt(stylos::core::view::StandardView::Top, centre, 1000);
    const auto camera = m_view->camera();
    const QPointF corner(30, 30);
    press(corner);
    QVERIFY(!tool()->isDragging());
    move(corner + QPointF(40, 10));
    release(corner + QPointF(40, 10));
    QVERIFY(m_view->camera().viewMatrix() != camera.viewMatrix()); // orbited
    QVERIFY(poseOf(m_pieceId) == m_start);
    QCOMPARE(m_document->undoStack()->count(), 2);
}

void GizmoToolTest::theHoveredHandleIsHighlighted()
{
    const Eigen::Vector3d centre = (m_start * m_localCentre.homogeneous()).head<3>();
    lookAt(stylos::core::view::StandardView::Top, centre, 1000);
    m_gizmo->setFrame(GizmoFrame::World);
    const QPointF onX = pixelOf(centre) + QPointF(40, 0);
    const double dpr = m_view->devicePixelRatio();
    const QPoint device = (onX * dpr).toPoint();
    QCOMPARE(m_view->grabFramebuffer().pixel(device), qRgb(235, 70, 60)); // X red
    move(onX, {}, Qt::NoButton);
    QCOMPARE(tool()->hovered(), std::optional(HandleRole::MoveX));
    QCOMPARE(m_view->cursor().shape(), Qt::OpenHandCursor);
    QCOMPARE(m_view->grabFramebuffer().pixel(device), qRgb(255, 240, 130)); // lit
    move(onX + QPointF(0, 40), {}, Qt::NoButton);
    QVERIFY(!tool()->hovered());
    QCOMPARE(m_view->grabFramebuffer().pixel(device), qRgb(235, 70, 60));
    // The mouse leaving the view over a handle leaves it unlit (it stayed lit).
    move(onX, {}, Qt::NoButton);
    QCOMPARE(tool()->hovered(), std::optional(HandleRole::MoveX));
    QEvent leave(QEvent::Leave);
    QCoreApplication::sendEvent(m_view.get(), &leave);
    QVERIFY(!tool()->hovered());
    QCOMPARE(m_view->grabFramebuffer().pixel(device), qRgb(235, 70, 60));
    // Without the tool, nothing of the gizmo is drawn.
    m_gizmo->setEnabled(false);
    QVERIFY(m_view->tool() == nullptr);
    QVERIFY(m_view->grabFramebuffer().pixel(device) != qRgb(235, 70, 60));
}

void GizmoToolTest::keyLCyclesTheFrames()
{
    m_gizmo->setFrame(GizmoFrame::World);
    QSignalSpy frames(m_gizmo.get(), &GizmoController::frameChanged);
    QTest::keyClick(m_view.get(), Qt::Key_L);
    QCOMPARE(m_gizmo->frame(), GizmoFrame::Fragment);
    QTest::keyClick(m_view.get(), Qt::Key_L); // no drum: back to World
    QCOMPARE(m_gizmo->frame(), GizmoFrame::World);
    QVERIFY(m_document->setDockingDrum(m_drumId)); // switches to Drum
    QCOMPARE(m_gizmo->frame(), GizmoFrame::Drum);
    QTest::keyClick(m_view.get(), Qt::Key_L);
    QCOMPARE(m_gizmo->frame(), GizmoFrame::World);
    QTest::keyClick(m_view.get(), Qt::Key_L);
    QTest::keyClick(m_view.get(), Qt::Key_L);
    QCOMPARE(m_gizmo->frame(), GizmoFrame::Drum);
    QCOMPARE(frames.size(), 6);
    // The drum removed: no docking drum, the Drum frame falls back to World.
    QVERIFY(m_document->removeFragment(m_drumId));
    QCOMPARE(m_document->dockingDrum(), scene::NoFragment);
    QCOMPARE(tool()->effectiveFrame(), GizmoFrame::World);
}

STYLOS_WIDGET_TEST_MAIN(GizmoToolTest)
#include "GizmoToolTest.moc"
