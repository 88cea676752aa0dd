// The GL gap-filling pass (ViewComposite, with its GapTiles shortcut) against its rule on the CPU
// (core::view::fillGaps): a hand-made frame — a surface with an enclosed gap, an unscanned box, a notch in its
// outline, a far surface seen through a 2 px slit and through a wide opening, discs of two reaches, a convex
// block on the background — is uploaded as colour (reach in alpha) and depth, composited, read back and compared
// pixel for pixel with the CPU's result. Needs OpenGL 3.3 (xvfb-run); skipped without it.
#include "WidgetTestSupport.h"

#include "stylos/core/view/Camera.h"
#include "stylos/core/view/GapFill.h"
#include "stylos/widgets/view3d/OffscreenFrame.h"
#include "stylos/widgets/view3d/ViewComposite.h"

#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions_3_3_Core>
#include <QtTest>

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <vector>

using stylos::core::view::GapFrame;
using stylos::widgets::OffscreenFrame;
using stylos::widgets::ViewComposite;

namespace {

constexpr int W = 64, H = 48;
constexpr std::array<std::uint8_t, 3> Paper = {33, 36, 41};

struct Frame {
    std::vector<std::array<std::uint8_t, 4>> rgba = std::vector<std::array<std::uint8_t, 4>>(W * H, {33, 36, 41, 0});
    std::vector<float> depth = std::vector<float>(W * H, 1.0f); ///< window depth, GL rows (0 at the bottom)

    void paint(int x0, int y0, int x1, int y1, float d, std::uint8_t reach, std::uint8_t tone)
    {
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) {
                // colours that vary by pixel, so that which neighbour a fill comes from shows
                rgba[std::size_t(y) * W + x] = {std::uint8_t(tone + 2 * x), std::uint8_t(3 * y), tone, reach};
                depth[std::size_t(y) * W + x] = d;
            }
    }
    void clear(int x0, int y0, int x1, int y1)
    {
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) {
                rgba[std::size_t(y) * W + x] = {Paper[0], Paper[1], Paper[2], 0};
                depth[std::size_t(y) * W + x] = 1.0f;
            }
    }
};

std::uint32_t word(const std::array<std::uint8_t, 4>& c)
{
    return std::uint32_t(c[0]) | std::uint32_t(c[1]) << 8 | std::uint32_t(c[2]) << 16;
}

} // namespace

class GapFillPassTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void theShaderFollowsTheRule();
};

void GapFillPassTest::theShaderFollowsTheRule()
{
    QSurfaceFormat format;
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    QOpenGLContext context;
    context.setFormat(format);
    QOffscreenSurface surface;
    surface.setFormat(format);
    surface.create();
    if (!context.create() || !context.makeCurrent(&surface) || context.format().version() < qMakePair(3, 3))
        QSKIP("no OpenGL 3.3 (run under xvfb-run)");
    QOpenGLFunctions_3_3_Core gl;
    QVERIFY(gl.initializeOpenGLFunctions());

    const float nearD = 0.5f, farD = 0.9f;
    Frame f;
    f.paint(0, 8, 64, 48, nearD, 4, 100);   // the surface, discs of reach 4
    f.paint(40, 8, 64, 48, nearD, 2, 60);   // its right part: smaller discs
    f.clear(10, 30, 13, 33);                // an enclosed 3 × 3 gap
    f.clear(16, 14, 28, 26);                // an unscanned box, 12 × 12
    f.clear(30, 45, 33, 48);                // a notch in the top outline (cut by the border)
    f.clear(34, 40, 37, 43);                // a 3 × 3 gap among discs of reach 4 beside ones of reach 2
    f.paint(32, 12, 34, 40, farD, 4, 200);  // the far surface through a 2 px slit
    f.paint(48, 14, 60, 30, farD, 4, 200);  // and through a wide opening
    f.clear(0, 0, 64, 8);
    f.paint(4, 0, 12, 3, nearD, 4, 150);    // a block on the background, 5 rows below the surface

    stylos::core::view::Camera camera;
    camera.setViewport(W, H);
    const Eigen::Matrix4d projection = camera.projectionMatrix();
    const float a = float(projection(2, 2)), b = float(projection(2, 3));
    auto linear = [&](float d) { // as the shaders do, from the 24-bit depth the texture keeps
        const float stored = float(std::lround(double(d) * 16777215.0)) / 16777215.0f;
        return b / ((stored * 2.0f - 1.0f) + a);
    };
    QVERIFY2(linear(farD) > 1.5f * linear(nearD), "the far surface is well behind the near one");

    GapFrame cpu;
    cpu.width = W;
    cpu.height = H;
    for (int i = 0; i < W * H; ++i) {
        cpu.depth.push_back(f.depth[i] < 1.0f ? linear(f.depth[i]) : GapFrame::Background);
        cpu.colour.push_back(word(f.rgba[i]));
        cpu.reach.push_back(f.rgba[i][3] & 127);
    }
    const std::vector<std::uint32_t> before = cpu.colour;
    const std::int64_t filled = stylos::core::view::fillGaps(cpu);
    QVERIFY(filled > 0);

    OffscreenFrame source, target;
    QVERIFY(source.bind(QSize(W, H)));
    gl.glBindTexture(GL_TEXTURE_2D, source.colourTexture());
    gl.glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, f.rgba.data());
    gl.glBindTexture(GL_TEXTURE_2D, source.depthTexture());
    gl.glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, W, H, GL_DEPTH_COMPONENT, GL_FLOAT, f.depth.data());
    gl.glBindTexture(GL_TEXTURE_2D, 0);
    QVERIFY(target.bind(QSize(W, H)));
    ViewComposite composite;
    QVERIFY(composite.initialize());

    for (const bool on : {true, false}) {
        ViewComposite::Options options;
        options.gapFill = on;
        composite.draw(source, target.framebuffer(), QSize(W, H), camera, options);
        std::vector<std::array<std::uint8_t, 4>> out(W * H);
        gl.glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer());
        gl.glPixelStorei(GL_PACK_ALIGNMENT, 1);
        gl.glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
        const std::vector<std::uint32_t>& expected = on ? cpu.colour : before;
        int differing = 0;
        for (int i = 0; i < W * H; ++i)
            if (word(out[i]) != expected[i]) {
                if (differing++ < 5)
                    qWarning("gap filling %s: pixel (%d, %d) is %08x, the rule says %08x", on ? "on" : "off", i % W,
                             i / W, word(out[i]), expected[i]);
            }
        QCOMPARE(differing, 0);
    }
    composite.release();
    source.release();
    target.release();
    context.doneCurrent();
}

STYLOS_WIDGET_TEST_MAIN(GapFillPassTest)
#include "GapFillPassTest.moc"
