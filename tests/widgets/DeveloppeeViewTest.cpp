// DeveloppeeView and DeveloppeePanel on a hand-made développée (a cylinder's map, a height field with known
// heights and holes): a click emits the 3D point of the pixel's centre exactly, setMarker puts it back on
// that pixel, the wheel zooms about the cursor, the readout reads the pixel, drags pan without picking; the
// dock's Compute carries the bar's settings and its status shows the fit or the error.
#include "WidgetTestSupport.h"

#include "stylos/widgets/developpee/DeveloppeePanel.h"
#include "stylos/widgets/developpee/DeveloppeeJob.h"
#include "stylos/widgets/developpee/DeveloppeeView.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>

#include <cmath>
#include <numbers>

using stylos::core::shading::HeightField;
using stylos::core::unroll::Axis;
using stylos::core::unroll::Surface;
using stylos::core::unroll::UnrollMap;
using stylos::widgets::DeveloppeePanel;
using stylos::widgets::DeveloppeeResult;
using stylos::widgets::DeveloppeeSettings;
using stylos::widgets::DeveloppeeShading;
using stylos::widgets::DeveloppeeView;

namespace {

constexpr double PixelSize = 0.01;
constexpr int Height = 40;
constexpr double VTop = 0.4;
constexpr quint64 FragmentId = 42;

/** A cylinder of radius 0.5 m about a tilted axis through (1, 2, 3): the map, known heights, a grey image. */
struct Fixture {
    Axis axis{Eigen::Vector3d(1.0, 2.0, 3.0), Eigen::Vector3d(0.2, -0.1, 1.0).normalized()};
    UnrollMap map{Surface::cylinder(axis, 0.5).value(), stylos::core::unroll::defaultReferenceDir(axis.direction), 0.3,
                  PixelSize, int(std::ceil(2.0 * std::numbers::pi * 0.5 / PixelSize)), Height, VTop};
    std::shared_ptr<HeightField> heights;
    QImage image;

    Fixture()
    {
        heights = std::make_shared<HeightField>(HeightField::create(map.width(), Height, PixelSize).value());
        image = QImage(map.width(), Height, QImage::Format_ARGB32_Premultiplied);
        image.fill(0);
        for (int row = 0; row < Height; ++row)
            for (int column = 0; column < map.width(); ++column) {
                if ((column + 2 * row) % 13 == 0) continue; // a sprinkling of Empty pixels
                heights->setMeasured(column, row, 0.001f * float((3 * column + row) % 11) - 0.004f);
                const int grey = (column * 5 + row * 3) % 256;
                image.setPixel(column, row, qRgba(grey, grey, grey, 255));
            }
        heights->setMeasured(20, 7, 0.0025f);
        heights->clear(21, 7);
    }
};

void send(QWidget& w, QEvent::Type type, QPoint pos, Qt::MouseButton button, Qt::MouseButtons buttons)
{
    QMouseEvent event(type, QPointF(pos), QPointF(w.mapToGlobal(pos)), button, buttons, Qt::NoModifier);
    QApplication::sendEvent(&w, &event);
}

void click(QWidget& w, QPoint pos)
{
    send(w, QEvent::MouseButtonPress, pos, Qt::LeftButton, Qt::LeftButton);
    send(w, QEvent::MouseButtonRelease, pos, Qt::LeftButton, Qt::NoButton);
}

void wheel(QWidget& w, QPoint pos, int delta)
{
    QWheelEvent event(QPointF(pos), QPointF(w.mapToGlobal(pos)), QPoint(), QPoint(0, delta), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(&w, &event);
}

} // namespace

class DeveloppeeViewTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void init();
    void cleanup();
    void fitsTheWholeImage();
    void clickEmitsThePixelCentrePoint();
    void clickAtAnyZoomPicksThePixelUnderTheCursor();
    void clickOnEmptyOrOutsideEmitsNothing();
    void dragPansWithoutPicking();
    void setMarkerPutsItBackOnThePixel();
    void markerIsDrawn();
    void guideLinesLandOnTheirAzimuth();
    void wheelZoomsAboutTheCursor();
    void readoutOfAKnownPixel();
    void dockComputeCarriesTheBarSettings();
    void dockShowsTheFitOrTheError();

private:
    std::unique_ptr<Fixture> m_fixture;
    std::unique_ptr<DeveloppeeView> m_view;
};

void DeveloppeeViewTest::initTestCase()
{
    QLocale::setDefault(QLocale::c()); // readouts with a decimal point
    m_fixture = std::make_unique<Fixture>();
}

void DeveloppeeViewTest::init()
{
    m_view = std::make_unique<DeveloppeeView>();
    m_view->resize(400, 300);
    m_view->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_view.get()));
    m_view->setDeveloppee(FragmentId, m_fixture->image, m_fixture->heights, m_fixture->map);
}

void DeveloppeeViewTest::cleanup() { m_view.reset(); }

void DeveloppeeViewTest::fitsTheWholeImage()
{
    DeveloppeeView& v = *m_view;
    QVERIFY(v.hasDeveloppee());
    QCOMPARE(v.fragmentId(), FragmentId);
    const QRectF shown(v.imageToWidget(QPointF(0, 0)), v.imageToWidget(QPointF(v.image().width(), v.image().height())));
    QVERIFY(QRectF(v.rect()).contains(shown));
    QCOMPARE(shown.center(), QRectF(v.rect()).center());
    // The image is wider than tall: it spans the width less the margins.
    QVERIFY(std::abs(shown.width() - (v.width() - 16.0)) < 1e-9);
    // Resizing keeps fitting until the user zooms.
    v.resize(600, 300);
    QTRY_COMPARE(v.width(), 600);
    QVERIFY(std::abs(v.imageToWidget(QPointF(v.image().width(), 0)).x() - 592.0) < 1e-9);
    wheel(v, QPoint(100, 100), 120);
    const double zoom = v.zoom();
    v.resize(500, 300);
    QTRY_COMPARE(v.width(), 500);
    QCOMPARE(v.zoom(), zoom);
    v.fitToWindow();
    QVERIFY(std::abs(v.imageToWidget(QPointF(v.image().width(), 0)).x() - 492.0) < 1e-9);
}

void DeveloppeeViewTest::clickEmitsThePixelCentrePoint()
{
    DeveloppeeView& v = *m_view;
    v.setTransform(4.0, QPointF(10, 20));
    QSignalSpy picked(&v, &DeveloppeeView::pointPicked);
    // Pixel (20, 7) covers widget [90, 94) × [48, 52).
    click(v, QPoint(92, 50));
    QCOMPARE(picked.size(), 1);
    QCOMPARE(picked.at(0).at(0).value<quint64>(), FragmentId);
    const auto point = picked.at(0).at(1).value<Eigen::Vector3d>();
    const Eigen::Vector3d expected = m_fixture->map.worldAtPixel(20.5, 7.5, double(0.0025f));
    QCOMPARE(point.x(), expected.x());
    QCOMPARE(point.y(), expected.y());
    QCOMPARE(point.z(), expected.z());
    QVERIFY(v.marker() && *v.marker() == expected);
    // The same pixel from its corner.
    click(v, QPoint(90, 48));
    QCOMPARE(picked.size(), 2);
    QVERIFY(picked.at(1).at(1).value<Eigen::Vector3d>() == expected);
}

void DeveloppeeViewTest::clickAtAnyZoomPicksThePixelUnderTheCursor()
{
    DeveloppeeView& v = *m_view;
    v.setTransform(2.7, QPointF(-13.3, 7.1));
    QSignalSpy picked(&v, &DeveloppeeView::pointPicked);
    int expectedSignals = 0;
    for (QPoint pos : {QPoint(3, 9), QPoint(150, 60), QPoint(399, 100), QPoint(257, 111)}) {
        const QPointF image = v.widgetToImage(QPointF(pos));
        const int c = int(std::floor(image.x())), r = int(std::floor(image.y()));
        click(v, pos);
        if (!m_fixture->heights->contains(c, r) || !m_fixture->heights->hasHeight(c, r)) continue;
        ++expectedSignals;
        QCOMPARE(picked.size(), expectedSignals);
        const Eigen::Vector3d expected =
            m_fixture->map.worldAtPixel(c + 0.5, r + 0.5, double(m_fixture->heights->heightAt(c, r)));
        QVERIFY(picked.last().at(1).value<Eigen::Vector3d>() == expected);
        QVERIFY(v.pointAtPixel(c, r) == expected);
    }
    QVERIFY(expectedSignals >= 3);
}

void DeveloppeeViewTest::clickOnEmptyOrOutsideEmitsNothing()
{
    DeveloppeeView& v = *m_view;
    v.setTransform(4.0, QPointF(10, 20));
    QSignalSpy picked(&v, &DeveloppeeView::pointPicked);
    click(v, QPoint(96, 50)); // pixel (21, 7): Empty
    click(v, QPoint(5, 50));  // left of the image
    click(v, QPoint(92, 19)); // above it
    QCOMPARE(picked.size(), 0);
    QVERIFY(!v.pointAtPixel(21, 7));
    QVERIFY(!v.pointAtPixel(-1, 7));
    QVERIFY(!v.pointAtPixel(m_fixture->map.width(), 0));
    QVERIFY(!v.marker());
}

void DeveloppeeViewTest::dragPansWithoutPicking()
{
    DeveloppeeView& v = *m_view;
    v.setTransform(4.0, QPointF(10, 20));
    QSignalSpy picked(&v, &DeveloppeeView::pointPicked);
    send(v, QEvent::MouseButtonPress, QPoint(92, 50), Qt::LeftButton, Qt::LeftButton);
    send(v, QEvent::MouseMove, QPoint(100, 55), Qt::NoButton, Qt::LeftButton);
    send(v, QEvent::MouseMove, QPoint(120, 70), Qt::NoButton, Qt::LeftButton);
    send(v, QEvent::MouseButtonRelease, QPoint(120, 70), Qt::LeftButton, Qt::NoButton);
    QCOMPARE(picked.size(), 0);
    QCOMPARE(v.offset(), QPointF(38, 40));
    QCOMPARE(v.zoom(), 4.0);
    // The pixel that was under the press is under the release.
    QCOMPARE(v.widgetToImage(QPointF(120, 70)), QPointF(20.5, 7.5));
}

void DeveloppeeViewTest::setMarkerPutsItBackOnThePixel()
{
    DeveloppeeView& v = *m_view;
    QVERIFY(!v.markerPixel());
    const double period = m_fixture->map.circumference() / PixelSize;
    for (auto [c, r] : {std::pair{20, 7}, std::pair{1, 0}, std::pair{int(period) - 1, Height - 1}, std::pair{157, 21}}) {
        const auto point = v.pointAtPixel(c, r);
        QVERIFY(point);
        v.setMarker(point);
        const auto pixel = v.markerPixel();
        QVERIFY(pixel);
        QCOMPARE(int(std::floor(pixel->x())), c);
        QCOMPARE(int(std::floor(pixel->y())), r);
        QVERIFY2(std::abs(pixel->x() - (c + 0.5)) < 1e-9 && std::abs(pixel->y() - (r + 0.5)) < 1e-9,
                 qPrintable(QStringLiteral("%1 %2").arg(pixel->x(), 0, 'g', 17).arg(pixel->y(), 0, 'g', 17)));
    }
    // A click's point comes back on the clicked pixel.
    v.setTransform(4.0, QPointF(10, 20));
    click(v, QPoint(92, 50));
    QVERIFY(v.markerPixel() && std::abs(v.markerPixel()->x() - 20.5) < 1e-9);
    // A new développée keeps the marker of its own fragment and drops another fragment's.
    v.setDeveloppee(FragmentId, m_fixture->image, m_fixture->heights, m_fixture->map);
    QVERIFY(v.marker());
    v.setDeveloppee(FragmentId + 1, m_fixture->image, m_fixture->heights, m_fixture->map);
    QVERIFY(!v.marker());
    v.setMarker(v.pointAtPixel(20, 7));
    v.setMarker(std::nullopt);
    QVERIFY(!v.markerPixel());
}

void DeveloppeeViewTest::markerIsDrawn()
{
    DeveloppeeView& v = *m_view;
    v.setTransform(4.0, QPointF(10, 20));
    v.setMarker(v.pointAtPixel(20, 7));
    const QImage shot = v.grab().toImage();
    // The ring (radius 7) about the pixel's centre, widget (92, 50), is drawn in the marker's orange.
    int orange = 0;
    for (int y = 40; y <= 60; ++y)
        for (int x = 82; x <= 102; ++x) {
            const QColor c = shot.pixelColor(QPoint(x, y) * shot.devicePixelRatio());
            if (c.red() > 200 && c.green() > 60 && c.green() < 140 && c.blue() < 90) ++orange;
        }
    QVERIFY2(orange > 10, qPrintable(QString::number(orange)));
}

void DeveloppeeViewTest::guideLinesLandOnTheirAzimuth()
{
    // Two flute lines parallel to the axis, at azimuths 1 rad and 2 rad past the cut, on the surface: columns
    // R·(φ − cut) / s by the map's definition (u = R·((φ − cut) mod 2π), column = u / s).
    const Axis& axis = m_fixture->axis;
    const Eigen::Vector3d e1 = m_fixture->map.referenceDir(), e2 = axis.direction.cross(e1);
    // Lines on the surface, parallel to the axis, at these angles past the cut.
    const auto linesAt = [&](std::initializer_list<double> offsets) {
        std::vector<DeveloppeeView::GuideLine> lines;
        for (double offset : offsets) {
            const double phi = 0.3 + offset;
            lines.push_back({axis.point + 0.25 * axis.direction + 0.5 * (std::cos(phi) * e1 + std::sin(phi) * e2),
                             axis.direction});
        }
        return lines;
    };
    m_view->setGuideLines(linesAt({1.0, 2.0}));
    const auto columns = m_view->guideColumns();
    QCOMPARE(columns.size(), 2u);
    QVERIFY(std::abs(columns[0] - 1.0 * 0.5 / PixelSize) < 1e-6);
    QVERIFY(std::abs(columns[1] - 2.0 * 0.5 / PixelSize) < 1e-6);
    // Drawn: the guide colour on the column of the first line, mid-height.
    m_view->resize(800, 400);
    m_view->fitToWindow();
    const QImage shot = m_view->grab().toImage();
    const QPointF at = m_view->imageToWidget(QPointF(columns[0], Height / 2.0));
    bool seen = false;
    for (int dx = -2; dx <= 2 && !seen; ++dx)
        for (int dy = -3; dy <= 3 && !seen; ++dy)
            seen = shot.pixelColor(int(at.x()) + dx, int(at.y()) + dy).blue() > 200 &&
                   shot.pixelColor(int(at.x()) + dx, int(at.y()) + dy).red() < 160;
    QVERIFY2(seen, "the guide line is drawn");
    m_view->setGuideLines({});
    QVERIFY(m_view->guideColumns().empty());

    // A fragment's développée (an arc: here the image's first 0.5 rad, 25 × 40 pixels, narrower than the view so
    // the canvas shows on both sides): a line at 0.25 rad is drawn on it, the one at 1 rad, beyond it, is not.
    const int arcColumns = int(std::lround(0.5 * 0.5 / PixelSize));
    const QImage arc = m_fixture->image.copy(0, 0, arcColumns, m_fixture->image.height());
    auto arcHeights = std::make_shared<HeightField>(HeightField::create(arcColumns, Height, PixelSize).value());
    for (int r = 0; r < Height; ++r)
        for (int c = 0; c < arcColumns; ++c) arcHeights->setMeasured(c, r, m_fixture->heights->heightAt(c, r));
    m_view->setDeveloppee(FragmentId, arc, arcHeights, m_fixture->map);
    m_view->setGuideLines(linesAt({0.25, 1.0}));
    m_view->fitToWindow();
    const QImage arcShot = m_view->grab().toImage();
    const auto guideNear = [&](const QPointF& p) {
        for (int dx = -2; dx <= 2; ++dx)
            for (int dy = -3; dy <= 3; ++dy) {
                const QColor c = arcShot.pixelColor(int(p.x()) + dx, int(p.y()) + dy);
                if (c.blue() - c.red() > 40) return true; // the guide's blue over the grey image or canvas
            }
        return false;
    };
    QVERIFY(guideNear(m_view->imageToWidget(QPointF(0.25 * 0.5 / PixelSize, Height / 2.0))));
    const QPointF beyond = m_view->imageToWidget(QPointF(1.0 * 0.5 / PixelSize, Height / 2.0));
    QVERIFY(beyond.x() > m_view->imageToWidget(QPointF(arcColumns, 0)).x() + 5 && beyond.x() < m_view->width() - 3);
    QVERIFY2(!guideNear(beyond), "no line beyond the fragment's arc");
}

void DeveloppeeViewTest::wheelZoomsAboutTheCursor()
{
    DeveloppeeView& v = *m_view;
    v.setTransform(1.5, QPointF(5, 9));
    for (auto [pos, delta] : {std::pair{QPoint(123, 77), 120}, std::pair{QPoint(31, 200), -240},
                              std::pair{QPoint(390, 5), 360}}) {
        const QPointF before = v.widgetToImage(QPointF(pos));
        const double zoom = v.zoom();
        wheel(v, pos, delta);
        QVERIFY(std::abs(v.zoom() - zoom * std::pow(1.25, delta / 120.0)) < 1e-12);
        const QPointF after = v.widgetToImage(QPointF(pos));
        QVERIFY2(std::abs(after.x() - before.x()) < 1e-9 && std::abs(after.y() - before.y()) < 1e-9,
                 qPrintable(QStringLiteral("%1,%2 -> %3,%4").arg(before.x()).arg(before.y()).arg(after.x()).arg(after.y())));
    }
    // The zoom is bounded.
    for (int i = 0; i < 100; ++i) wheel(v, QPoint(100, 100), 120);
    QCOMPARE(v.zoom(), DeveloppeeView::MaxZoom);
}

void DeveloppeeViewTest::readoutOfAKnownPixel()
{
    DeveloppeeView& v = *m_view;
    v.setTransform(4.0, QPointF(10, 20));
    QSignalSpy changed(&v, &DeveloppeeView::readoutChanged);
    // The centre of pixel (20, 7): u = 20.5 × 10 mm, v = 400 mm − 7.5 × 10 mm, h = 2.5 mm.
    send(v, QEvent::MouseMove, QPoint(92, 50), Qt::NoButton, Qt::NoButton);
    QCOMPARE(v.readout(), QStringLiteral("u 205.0 mm   v 325.0 mm   h 2.50 mm"));
    QCOMPARE(changed.size(), 1);
    QCOMPARE(changed.at(0).at(0).toString(), v.readout());
    // Pixel (21, 7) has no height; outside the image there is no readout.
    send(v, QEvent::MouseMove, QPoint(94, 50), Qt::NoButton, Qt::NoButton);
    QCOMPARE(v.readout(), QStringLiteral("u 210.0 mm   v 325.0 mm   (no data)"));
    send(v, QEvent::MouseMove, QPoint(5, 50), Qt::NoButton, Qt::NoButton);
    QCOMPARE(v.readout(), QString());
    QCOMPARE(v.readoutAt(QPointF(1.25, 39.5)),
             DeveloppeeView::formatReadout(1.25 * PixelSize, VTop - 39.5 * PixelSize, double(m_fixture->heights->heightAt(1, 39))));
    QCOMPARE(v.readoutAt(QPointF(0.25, 39.5)), // (0, 39) is Empty
             DeveloppeeView::formatReadout(0.25 * PixelSize, VTop - 39.5 * PixelSize, std::nullopt));
}

void DeveloppeeViewTest::dockComputeCarriesTheBarSettings()
{
    DeveloppeePanel dock;
    auto* compute = dock.findChild<QPushButton*>(QStringLiteral("developpeeCompute"));
    auto* surface = dock.findChild<QComboBox*>(QStringLiteral("developpeeSurface"));
    auto* shading = dock.findChild<QComboBox*>(QStringLiteral("developpeeShading"));
    auto* directions = dock.findChild<QSpinBox*>(QStringLiteral("developpeeDirections"));
    auto* pixel = dock.findChild<QDoubleSpinBox*>(QStringLiteral("developpeePixelSize"));
    QVERIFY(compute && surface && shading && directions && pixel);
    QSignalSpy requested(&dock, &DeveloppeePanel::computeRequested);
    QVERIFY(!compute->isEnabled()); // no fragment yet
    dock.setFragment(5, QStringLiteral("drum"), m_fixture->axis);
    QVERIFY(compute->isEnabled());
    surface->setCurrentIndex(surface->findData(int(stylos::core::unroll::SurfaceKind::Cone)));
    shading->setCurrentIndex(shading->findData(int(DeveloppeeShading::Skydome)));
    directions->setValue(64);
    pixel->setValue(0.5);
    compute->click();
    QCOMPARE(requested.size(), 1);
    const auto s = requested.at(0).at(0).value<DeveloppeeSettings>();
    QCOMPARE(s.surface, stylos::core::unroll::SurfaceKind::Cone);
    QCOMPARE(s.shading, DeveloppeeShading::Skydome);
    QCOMPARE(s.directions, 64);
    QCOMPARE(s.pixelSize, 0.0005);
    // Typed in scientific notation, and back to Automatic (0, the special value's text).
    dock.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dock));
    const auto type = [pixel](const QString& text) {
        pixel->setFocus();
        pixel->selectAll();
        QTest::keyClicks(pixel, text);
        QTest::keyClick(pixel, Qt::Key_Return);
    };
    type(QStringLiteral("2.5e-1"));
    QCOMPARE(pixel->value(), 0.25);
    type(QStringLiteral("2e3")); // beyond 1000 mm: not applied
    QCOMPARE(pixel->value(), 0.25);
    type(QStringLiteral("1e-3")); // rounds to 0.00 mm, which is "Automatic": not applied (it became Automatic)
    QCOMPARE(pixel->value(), 0.25);
    pixel->setValue(0.0);
    QCOMPARE(pixel->text(), pixel->specialValueText());
    // Typed and not entered (a shortcut pressed with the focus still in the field): the settings read what is shown.
    pixel->setFocus();
    pixel->selectAll();
    QTest::keyClicks(pixel, QStringLiteral("3e-1"));
    QCOMPARE(dock.settings().pixelSize, 0.0003);
    pixel->setValue(0.5);
    QVERIFY(s.axis && s.axis->point == m_fixture->axis.point && s.axis->direction == m_fixture->axis.direction);
    // Directions only apply to the skydome; busy disables Compute.
    shading->setCurrentIndex(shading->findData(int(DeveloppeeShading::Light)));
    QVERIFY(!directions->isEnabled());
    dock.setBusy(true);
    QVERIFY(!compute->isEnabled());
    compute->click();
    QCOMPARE(requested.size(), 1);
    // setSettings round-trips what the bar shows (the axis comes from the fragment).
    DeveloppeeSettings given;
    given.surface = stylos::core::unroll::SurfaceKind::Revolution;
    given.shading = DeveloppeeShading::Height;
    given.directions = 12;
    given.pixelSize = 0.002;
    given.stretch = false;
    dock.setSettings(given);
    DeveloppeeSettings shown = dock.settings();
    QVERIFY(shown.axis);
    shown.axis.reset();
    QCOMPARE(shown, given);
    dock.setFragment(0, QString());
    QVERIFY(!dock.settings().axis);
}

void DeveloppeeViewTest::dockShowsTheFitOrTheError()
{
    DeveloppeePanel dock;
    dock.setFragment(FragmentId, QStringLiteral("drum"));
    dock.setBusy(true);
    DeveloppeeResult failed;
    failed.fragmentId = FragmentId;
    failed.error = QStringLiteral("Could not compute the développée of drum.poct: the file is malformed.\ndetail");
    dock.showResult(failed);
    QVERIFY(!dock.isBusy());
    QCOMPARE(dock.statusText(), failed.error);
    QVERIFY(!dock.view()->hasDeveloppee());

    DeveloppeeResult done;
    done.fragmentId = FragmentId;
    done.octreePath = QStringLiteral("/data/drum.poct");
    done.image = m_fixture->image;
    done.heights = m_fixture->heights;
    done.map = m_fixture->map;
    done.fit.surface = m_fixture->map.surface();
    done.fit.rmsResidual = 0.00042;
    done.fit.inlierFraction = 0.98;
    done.unroll.pixelSize = PixelSize;
    done.timings.total = 1.5;
    done.heightNoise = 0.00014;
    done.smoothing = 0.0008;
    dock.showResult(done);
    QVERIFY(dock.view()->hasDeveloppee());
    QCOMPARE(dock.view()->fragmentId(), FragmentId);
    QCOMPARE(dock.statusText(), QStringLiteral("drum.poct: Cylinder, radius 500.0 mm, RMS 0.42 mm, 98 % inliers; "
                                               "%1 × 40 pixels of 10.00 mm; 1.5 s; noise 0.14 mm smoothed by 0.80 mm")
                                    .arg(m_fixture->map.width()));
}

STYLOS_WIDGET_TEST_MAIN(DeveloppeeViewTest)
#include "DeveloppeeViewTest.moc"
