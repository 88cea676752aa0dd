// Camera: exact view and projection matrices for the standard views, orbit/pan/dolly, fitting a box,
// the pixel ray round trip and the perspective/orthographic switch. Pure maths: no window, no GL.
#include "WidgetTestSupport.h"

#include "stylos/widgets/Camera.h"

#include <cmath>
#include <random>
#include <sstream>

Q_DECLARE_METATYPE(Eigen::Vector3d)

using stylos::widgets::Camera;
using stylos::widgets::StandardView;

namespace {

bool near(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, double tolerance = 1e-12)
{
    return a.rows() == b.rows() && a.cols() == b.cols() && (a - b).cwiseAbs().maxCoeff() <= tolerance;
}

QByteArray show(const Eigen::MatrixXd& m)
{
    std::ostringstream s;
    s << m;
    return QByteArray::fromStdString(s.str());
}

/** The view matrix expected for a camera whose right/up/back axes are the given scene vectors. */
Eigen::Matrix4d expectedView(const Eigen::Vector3d& right, const Eigen::Vector3d& up, const Eigen::Vector3d& back,
                             const Eigen::Vector3d& target, double distance)
{
    const Eigen::Vector3d eye = target + back * distance;
    Eigen::Matrix4d v = Eigen::Matrix4d::Identity();
    v.row(0).head<3>() = right;
    v.row(1).head<3>() = up;
    v.row(2).head<3>() = back;
    v(0, 3) = -right.dot(eye);
    v(1, 3) = -up.dot(eye);
    v(2, 3) = -back.dot(eye);
    return v;
}

} // namespace

class CameraTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void standardViewMatrices_data();
    void standardViewMatrices();
    void frontViewExactly();
    void projectionMatrices();
    void orbitReachesStandardViews();
    void panFollowsTheDrag();
    void dolly();
    void fitPutsTheBoxInView_data();
    void fitPutsTheBoxInView();
    void pixelRayRoundTrip_data();
    void pixelRayRoundTrip();
    void orthographicSwitchKeepsTheTargetScale();
    void clipPlanesHoldTheScene();
};

void CameraTest::standardViewMatrices_data()
{
    QTest::addColumn<int>("view");
    QTest::addColumn<Eigen::Vector3d>("right");
    QTest::addColumn<Eigen::Vector3d>("up");
    QTest::addColumn<Eigen::Vector3d>("back");
    const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY(), z = Eigen::Vector3d::UnitZ();
    QTest::newRow("front") << int(StandardView::Front) << x << z << Eigen::Vector3d(-y);
    QTest::newRow("back") << int(StandardView::Back) << Eigen::Vector3d(-x) << z << y;
    QTest::newRow("left") << int(StandardView::Left) << Eigen::Vector3d(-y) << z << Eigen::Vector3d(-x);
    QTest::newRow("right") << int(StandardView::Right) << y << z << x;
    QTest::newRow("top") << int(StandardView::Top) << x << y << z;
    QTest::newRow("bottom") << int(StandardView::Bottom) << Eigen::Vector3d(-x) << y << Eigen::Vector3d(-z);
    const Eigen::Vector3d isoBack = Eigen::Vector3d(1, -1, 1) / std::sqrt(3.0);
    const Eigen::Vector3d isoRight = Eigen::Vector3d(1, 1, 0) / std::sqrt(2.0);
    QTest::newRow("iso") << int(StandardView::Iso) << isoRight << Eigen::Vector3d(isoBack.cross(isoRight)) << isoBack;
}

void CameraTest::standardViewMatrices()
{
    QFETCH(int, view);
    QFETCH(Eigen::Vector3d, right);
    QFETCH(Eigen::Vector3d, up);
    QFETCH(Eigen::Vector3d, back);
    Camera camera;
    const Eigen::Vector3d target(1.5, -2, 100);
    camera.setTarget(target);
    camera.setDistance(4);
    camera.setStandardView(StandardView(view));
    const Eigen::Matrix4d expected = expectedView(right, up, back, target, 4);
    QVERIFY2(near(camera.viewMatrix(), expected), show(camera.viewMatrix()));
    QVERIFY(near(camera.eye(), target + 4 * back));
    QVERIFY(near(camera.forward(), -back));
    // The target lies on the view axis, 4 m ahead.
    const Eigen::Vector4d t = camera.viewMatrix() * target.homogeneous();
    QVERIFY(near(t, Eigen::Vector4d(0, 0, -4, 1)));
}

void CameraTest::frontViewExactly()
{
    Camera camera;
    camera.setTarget({1, 2, 3});
    camera.setDistance(4);
    camera.setStandardView(StandardView::Front);
    Eigen::Matrix4d expected;
    expected << 1, 0, 0, -1, //
        0, 0, 1, -3,         //
        0, -1, 0, -2,        //
        0, 0, 0, 1;
    QVERIFY2(near(camera.viewMatrix(), expected), show(camera.viewMatrix()));
}

void CameraTest::projectionMatrices()
{
    Camera camera;
    camera.setViewport(200, 100);
    camera.setFieldOfView(M_PI / 2);
    camera.setDistance(2);
    // No scene bounds: near = 0.01 d, far = 100 d.
    const double n = 0.02, f = 200;
    Eigen::Matrix4d perspective;
    perspective << 0.5, 0, 0, 0, //
        0, 1, 0, 0,              //
        0, 0, (f + n) / (n - f), 2 * f * n / (n - f), //
        0, 0, -1, 0;
    QVERIFY2(near(camera.projectionMatrix(), perspective), show(camera.projectionMatrix()));
    QCOMPARE(camera.pixelsPerRadian(), 100 / (M_PI / 2));

    camera.setOrthographic(true);
    QVERIFY(std::abs(camera.viewHeight() - 4.0) < 1e-12); // 2 d tan(45°)
    Eigen::Matrix4d orthographic;
    orthographic << 0.25, 0, 0, 0, //
        0, 0.5, 0, 0,              //
        0, 0, -2 / (f - n), -(f + n) / (f - n), //
        0, 0, 0, 1;
    QVERIFY2(near(camera.projectionMatrix(), orthographic), show(camera.projectionMatrix()));
    QVERIFY(std::abs(camera.pixelsPerMetre() - 25.0) < 1e-12);
}

void CameraTest::orbitReachesStandardViews()
{
    Camera camera;
    camera.setTarget({0.5, 0.25, -1});
    camera.setStandardView(StandardView::Front);
    camera.orbit(M_PI / 2, 0); // the eye goes counter-clockwise from −Y to +X
    Camera right = camera;
    right.setStandardView(StandardView::Right);
    QVERIFY2(near(camera.viewMatrix(), right.viewMatrix(), 1e-12), show(camera.viewMatrix()));

    camera.setStandardView(StandardView::Front);
    camera.orbit(0, M_PI / 2); // the eye rises over the target
    Camera top = camera;
    top.setStandardView(StandardView::Top);
    QVERIFY2(near(camera.viewMatrix(), top.viewMatrix(), 1e-12), show(camera.viewMatrix()));
    QVERIFY(near(camera.target(), Eigen::Vector3d(0.5, 0.25, -1)));
}

void CameraTest::panFollowsTheDrag()
{
    for (bool ortho : {false, true}) {
        Camera camera;
        camera.setViewport(640, 400);
        camera.setOrthographic(ortho);
        camera.setStandardView(StandardView::Iso);
        camera.setTarget({3, 4, 5});
        const Eigen::Vector3d before = camera.target();
        camera.pan(10, -5);
        const auto p = camera.project(before);
        QVERIFY(p);
        QVERIFY2(std::abs(p->x() - 330) < 1e-9 && std::abs(p->y() - 195) < 1e-9,
                 qPrintable(QString("%1 %2").arg(p->x()).arg(p->y())));
    }
}

void CameraTest::dolly()
{
    Camera camera;
    camera.setDistance(3);
    camera.dolly(0.5);
    QCOMPARE(camera.distance(), 1.5);
    camera.dolly(-1); // ignored
    QCOMPARE(camera.distance(), 1.5);
    camera.dolly(1e-12);
    QCOMPARE(camera.distance(), 1e-6); // clamped
}

void CameraTest::fitPutsTheBoxInView_data()
{
    QTest::addColumn<bool>("orthographic");
    QTest::addColumn<int>("view");
    QTest::addColumn<int>("width");
    QTest::addColumn<int>("height");
    for (bool ortho : {false, true})
        for (int view = 0; view <= int(StandardView::Iso); ++view)
            for (auto [w, h] : {std::pair{800, 600}, std::pair{300, 900}})
                QTest::addRow("%s view %d %dx%d", ortho ? "ortho" : "persp", view, w, h) << ortho << view << w << h;
}

void CameraTest::fitPutsTheBoxInView()
{
    QFETCH(bool, orthographic);
    QFETCH(int, view);
    QFETCH(int, width);
    QFETCH(int, height);
    const Eigen::AlignedBox3d box(Eigen::Vector3d(-1, 0, 5), Eigen::Vector3d(2, 1, 9));
    Camera camera;
    camera.setViewport(width, height);
    camera.setOrthographic(orthographic);
    camera.setStandardView(StandardView(view));
    camera.setSceneBounds(box);
    camera.setTarget({50, 50, 50});
    camera.fit(box);
    QVERIFY(near(camera.target(), box.center()));
    double maxX = 0, maxY = 0;
    for (int corner = 0; corner < 8; ++corner) {
        const auto p = camera.project(box.corner(Eigen::AlignedBox3d::CornerType(corner)));
        QVERIFY(p);
        QVERIFY2(p->x() >= 0 && p->x() <= width && p->y() >= 0 && p->y() <= height,
                 qPrintable(QString("corner %1 at %2, %3").arg(corner).arg(p->x()).arg(p->y())));
        QVERIFY(p->z() > -1 && p->z() < 1);
        maxX = std::max(maxX, std::abs(p->x() - width / 2.0) / (width / 2.0));
        maxY = std::max(maxY, std::abs(p->y() - height / 2.0) / (height / 2.0));
    }
    QVERIFY2(std::max(maxX, maxY) > 0.4, "the box fills a fair part of the view"); // not fitted absurdly far
}

void CameraTest::pixelRayRoundTrip_data()
{
    QTest::addColumn<bool>("orthographic");
    QTest::newRow("perspective") << false;
    QTest::newRow("orthographic") << true;
}

void CameraTest::pixelRayRoundTrip()
{
    QFETCH(bool, orthographic);
    Camera camera;
    camera.setViewport(1280, 800);
    camera.setOrthographic(orthographic);
    camera.setTarget({1000.25, -2000.5, 12}); // a museum frame: large coordinates
    camera.setDistance(3);
    camera.setStandardView(StandardView::Iso);
    camera.orbit(0.3, -0.2);
    camera.setSceneBounds(Eigen::AlignedBox3d(camera.target() - Eigen::Vector3d::Constant(1),
                                              camera.target() + Eigen::Vector3d::Constant(1)));
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-0.9, 0.9);
    for (int i = 0; i < 100; ++i) {
        const Eigen::Vector3d point = camera.target() + Eigen::Vector3d(u(rng), u(rng), u(rng));
        const auto pixel = camera.project(point);
        QVERIFY(pixel);
        const auto ray = camera.rayAt(pixel->x(), pixel->y());
        QVERIFY(std::abs(ray.direction.norm() - 1) < 1e-12);
        const Eigen::Vector3d toPoint = point - ray.origin;
        const double along = toPoint.dot(ray.direction);
        QVERIFY(along > 0);
        const double off = (toPoint - along * ray.direction).norm();
        QVERIFY2(off < 1e-9, qPrintable(QString::number(off)));
    }
    // The centre pixel looks straight at the target.
    const auto centre = camera.rayAt(640, 400);
    QVERIFY(near(centre.direction, camera.forward(), 1e-12));
    const Eigen::Vector3d toTarget = camera.target() - centre.origin;
    QVERIFY((toTarget - toTarget.dot(centre.direction) * centre.direction).norm() < 1e-9);
    if (!orthographic) QVERIFY(near(centre.origin, camera.eye(), 1e-12));
}

void CameraTest::orthographicSwitchKeepsTheTargetScale()
{
    Camera camera;
    camera.setViewport(800, 600);
    camera.setStandardView(StandardView::Iso);
    camera.setTarget({0.1, 0.2, 0.3});
    camera.setDistance(2.5);
    const Eigen::Vector3d offset = camera.target() + 0.1 * camera.right() - 0.05 * camera.up();
    const Eigen::Matrix4d view = camera.viewMatrix();
    const auto inPerspective = camera.project(offset);
    camera.setOrthographic(true);
    QVERIFY(camera.isOrthographic());
    QVERIFY(near(camera.viewMatrix(), view)); // only the projection changes
    const auto inOrthographic = camera.project(offset);
    QVERIFY(inPerspective && inOrthographic);
    QVERIFY((inPerspective->head<2>() - inOrthographic->head<2>()).norm() < 1e-9);
    camera.setOrthographic(false);
    QVERIFY(!camera.isOrthographic());
    QVERIFY((camera.project(offset)->head<2>() - inPerspective->head<2>()).norm() < 1e-12);
}

void CameraTest::clipPlanesHoldTheScene()
{
    Camera camera;
    const Eigen::AlignedBox3d box(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 2, 3));
    camera.setSceneBounds(box);
    camera.fit(box);
    const double radius = 0.5 * box.diagonal().norm();
    QVERIFY(camera.nearPlane() > 0);
    QVERIFY(camera.nearPlane() <= camera.distance() - radius);
    QVERIFY(camera.farPlane() >= camera.distance() + radius);
    // Inside the scene the perspective near plane stays positive; orthographic may go behind the eye.
    camera.setDistance(0.1);
    QVERIFY(camera.nearPlane() > 0 && camera.nearPlane() < 0.1);
    camera.setOrthographic(true);
    QVERIFY(camera.nearPlane() < 0);
}

QTEST_APPLESS_MAIN(CameraTest)
#include "CameraTest.moc"
