// Baseline images of the 3D view (as F3D's tests do): fixed scenes — the generated drum (headlight, eye-dome
// lighting, selected with its outline) and a small real scan (Igea, 134 K points, from the shared data; skipped
// without it) — drawn offscreen under Xvfb/llvmpipe at 320 × 200, once refined, compared with the PNGs in
// tests/widgets/baselines: the mean difference of the channels at most 3 of 255 and at most 2 % of the pixels
// off by more than 48. On a mismatch the image drawn is written beside the build (its path in the message).
// STYLOS_UPDATE_BASELINES=1 writes the baselines instead (look at them before committing).
#include "DrumOctreeFixture.h"
#include "WidgetTestSupport.h"

#include "stylos/widgets/view3d/ViewportWidget.h"

#include <QDir>
#include <QImage>
#include <QTemporaryDir>

#include <cmath>

using stylos::core::view::StandardView;
using stylos::core::view::ViewFragment;
using stylos::widgets::PointRenderer;
using stylos::widgets::ViewportWidget;

namespace {

struct Difference {
    double mean = 0;        ///< mean |a − b| over the channels, 0–255
    double offFraction = 1; ///< pixels with a channel off by more than 48
};

Difference compare(const QImage& a, const QImage& b)
{
    Difference d;
    if (a.size() != b.size()) return d;
    double sum = 0;
    std::int64_t off = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
            const int dr = std::abs(qRed(p) - qRed(q)), dg = std::abs(qGreen(p) - qGreen(q)),
                      db = std::abs(qBlue(p) - qBlue(q));
            sum += dr + dg + db;
            off += std::max({dr, dg, db}) > 48 ? 1 : 0;
        }
    const double pixels = double(a.width()) * a.height();
    d.mean = sum / (3 * pixels);
    d.offFraction = double(off) / pixels;
    return d;
}

} // namespace

class RenderBaselineTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void drumHeadlight();
    void drumEyeDome();
    void drumSelected();
    void realScan();
    void aChangedPictureFails();

private:
    QImage render(std::shared_ptr<const stylos::core::octree::PackedOctree> octree, PointRenderer::Shading shading,
                  bool selected, StandardView view);
    void check(const QImage& image, const QString& name);

    QTemporaryDir m_dir;
    stylos::test::DrumOctree m_drum;
    std::unique_ptr<ViewportWidget> m_view;
};

void RenderBaselineTest::initTestCase()
{
    if (!ViewportWidget::isSupported()) QSKIP("no OpenGL 3.3 on this platform (run under xvfb-run)");
    QVERIFY(m_dir.isValid());
    m_drum = stylos::test::makeDrumOctree(m_dir.path(), 0.01, 7);
    m_view = std::make_unique<ViewportWidget>();
    m_view->resize(320, 200);
    m_view->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_view.get()));
}

QImage RenderBaselineTest::render(std::shared_ptr<const stylos::core::octree::PackedOctree> octree,
                                  PointRenderer::Shading shading, bool selected, StandardView view)
{
    ViewFragment f;
    f.id = 7;
    f.octree = std::move(octree);
    f.selected = selected;
    m_view->setShading(shading);
    m_view->setFragments({f});
    m_view->setStandardView(view);
    m_view->fitToScene();
    for (int i = 0; i < 3000 && !m_view->isSettled(); ++i) QTest::qWait(10);
    if (!m_view->isSettled()) return {}; // check() fails on a null image
    m_view->repaint();
    QImage image = m_view->grabFramebuffer().convertToFormat(QImage::Format_RGB32);
    return image;
}

void RenderBaselineTest::check(const QImage& image, const QString& name)
{
    QVERIFY(!image.isNull());
    const QString baseline = QStringLiteral(STYLOS_BASELINES "/%1.png").arg(name);
    if (qEnvironmentVariableIntValue("STYLOS_UPDATE_BASELINES") == 1) {
        QVERIFY(image.save(baseline));
        return;
    }
    const QImage expected(baseline);
    QVERIFY2(!expected.isNull(), qPrintable(QStringLiteral("no baseline %1").arg(baseline)));
    const Difference d = compare(image, expected.convertToFormat(QImage::Format_RGB32));
    if (d.mean > 3.0 || d.offFraction > 0.02) {
        const QString actual = QDir::current().absoluteFilePath(name + QStringLiteral(".actual.png"));
        image.save(actual);
        QFAIL(qPrintable(QStringLiteral("%1 differs from its baseline (mean %2 of 255, %3 % of pixels off); drawn: %4")
                             .arg(name)
                             .arg(d.mean, 0, 'f', 2)
                             .arg(100 * d.offFraction, 0, 'f', 2)
                             .arg(actual)));
    }
}

void RenderBaselineTest::drumHeadlight()
{
    check(render(m_drum.octree, PointRenderer::Shading::Headlight, false, StandardView::Front), "drum-headlight");
}

void RenderBaselineTest::drumEyeDome()
{
    check(render(m_drum.octree, PointRenderer::Shading::EyeDome, false, StandardView::Front), "drum-eyedome");
}

void RenderBaselineTest::drumSelected()
{
    check(render(m_drum.octree, PointRenderer::Shading::Headlight, true, StandardView::Top), "drum-selected");
}

void RenderBaselineTest::realScan()
{
    const std::filesystem::path scan = std::filesystem::path(STYLOS_SHARED_DATA) / "scans" / "igea_134k.ply";
    if (!std::filesystem::exists(scan)) QSKIP("no shared data (igea_134k.ply)");
    const auto poct = std::filesystem::path(m_dir.path().toStdString()) / "igea.poct";
    stylos::core::octree::BuildOptions build;
    build.threads = 2;
    const auto built = stylos::core::octree::buildOctreeFile(scan, poct, build);
    QVERIFY2(built.ok(), built.ok() ? "" : built.error().message.c_str());
    auto opened = stylos::core::octree::PackedOctree::open(poct);
    QVERIFY(opened.ok());
    const auto octree = std::make_shared<const stylos::core::octree::PackedOctree>(std::move(opened).value());
    check(render(octree, PointRenderer::Shading::Headlight, false, StandardView::Back), "igea-headlight");
}

void RenderBaselineTest::aChangedPictureFails()
{
    // The comparison can fail: the drum with square splats at a fifteenth of the size (gaps) is not its baseline.
    m_view->setRoundSplats(false);
    m_view->setSplatFactor(0.1);
    const QImage image = render(m_drum.octree, PointRenderer::Shading::Headlight, false, StandardView::Front);
    m_view->setRoundSplats(true);
    m_view->setSplatFactor(1.5);
    const QImage expected(QStringLiteral(STYLOS_BASELINES "/drum-headlight.png"));
    if (expected.isNull()) QSKIP("no baseline yet");
    const Difference d = compare(image, expected.convertToFormat(QImage::Format_RGB32));
    QVERIFY2(d.mean > 3.0 || d.offFraction > 0.02, qPrintable(QString::number(d.mean)));
}

STYLOS_WIDGET_TEST_MAIN(RenderBaselineTest)
#include "RenderBaselineTest.moc"
