// The 3D view's picture, measured (docs/benchmarks.md, "Splats that close the surface"):
//   stylos_render_quality FILE [--leaf-pixels 8] [--size 1280x800] [--splat 1.5] [--shading headlight|eyedome]
//                         [--view front|back|left|right|top|bottom] [--image OUT.png] [--holes OUT.png]
//                         [--all-leaves] [--no-gap-fill] [--gap-steps 8] [--gap-directions 5]
// FILE: a point file (its octree is built first, default depth) or a .poct. The view (ViewportWidget, as in the
// workbench) is fitted to the object, its centre pixel picked, the camera brought to that surface point at the
// distance where a leaf edge spans --leaf-pixels pixels, and the refined image taken. Prints JSON:
//   holes: background pixels inside the silhouette / silhouette pixels. The silhouette is the closing of the
//          covered pixels by a 25 × 25 square (gaps narrower than 24 px are inside); split (core::view::ImageCoverage)
//          into holesThrough (background enclosed by drawn surface: seen through the surface) and holesEdge (the
//          notches the closing fills along an outline, the object's or that of an opening of the scan);
//   dark:  object pixels whose luminance is below 0.15 while the median of their 5 × 5 neighbourhood is above
//          0.5, / object pixels.
//   speckle: object pixels darker than 0.6 × the median of the object pixels of their 5 × 5 neighbourhood (at
//          least 13 of them), with at most one of their 8 neighbours that dark: the isolated dark grain of wrong
//          normals (a crease's line has two such neighbours or more), / object pixels.
// --holes writes the picture with the hole pixels in red (through) and orange (edge), the isolated dark pixels in
// yellow, the speckle in cyan. --all-leaves draws every leaf (no level-of-detail cut, no frustum culling): holes that stay are not the
// cut's. --no-gap-fill measures the splats alone, without the composite pass's gap filling (core/view/GapFill.h).
#include "stylos/core/octree/OctreeBuild.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/view/ImageCoverage.h"
#include "stylos/widgets/view3d/ViewportWidget.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QImage>
#include <QJsonDocument>
#include <QJsonObject>
#include <QThread>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <vector>

namespace {

bool isBackground(QRgb c) { return std::abs(qRed(c) - 33) <= 3 && std::abs(qGreen(c) - 36) <= 3 && std::abs(qBlue(c) - 41) <= 3; }

double luminance(QRgb c) { return (0.2126 * qRed(c) + 0.7152 * qGreen(c) + 0.0722 * qBlue(c)) / 255.0; }

} // namespace

int main(int argc, char** argv)
{
    QApplication app(argc, argv);
    const QStringList args = app.arguments();
    if (args.size() < 2) {
        std::fprintf(stderr, "usage: stylos_render_quality FILE [--leaf-pixels N] [--size WxH] [--splat F] "
                             "[--shading headlight|eyedome] [--view V] [--image OUT.png] [--holes OUT.png] [--all-leaves] [--no-gap-fill] [--gap-steps N] [--gap-directions N]\n");
        return 2;
    }
    auto option = [&](const char* name, const QString& fallback) {
        const int i = int(args.indexOf(QString::fromLatin1(name)));
        return i > 0 && i + 1 < args.size() ? args[i + 1] : fallback;
    };
    const double leafPixels = option("--leaf-pixels", "8").toDouble();
    const QStringList size = option("--size", "1280x800").split('x');
    const double splat = option("--splat", "1.5").toDouble();
    const QString shading = option("--shading", "headlight");
    const QString viewName = option("--view", "front");

    std::filesystem::path input = args[1].toStdString();
    std::filesystem::path poct = input;
    QElapsedTimer timer;
    timer.start();
    if (input.extension() != ".poct") {
        poct = std::filesystem::temp_directory_path() / (input.stem().string() + ".render-quality.poct");
        stylos::core::octree::BuildOptions build;
        build.threads = 2;
        const auto built = stylos::core::octree::buildOctreeFile(input, poct, build);
        if (!built.ok()) {
            std::fprintf(stderr, "%s\n", built.error().message.c_str());
            return 1;
        }
    }
    auto opened = stylos::core::octree::PackedOctree::open(poct);
    if (!opened.ok()) {
        std::fprintf(stderr, "%s\n", opened.error().message.c_str());
        return 1;
    }
    const auto octree = std::make_shared<const stylos::core::octree::PackedOctree>(std::move(opened).value());
    const double leafEdge = octree->box().cellSize(octree->depth());

    stylos::widgets::ViewportWidget view;
    view.resize(size.value(0).toInt(), size.value(1).toInt());
    view.show();
    view.setSplatFactor(splat);
    view.setGapFilling(!args.contains("--no-gap-fill"));
    stylos::core::view::GapFillOptions gap;
    gap.maxSteps = option("--gap-steps", QString::number(gap.maxSteps)).toInt();
    gap.minDirections = option("--gap-directions", QString::number(gap.minDirections)).toInt();
    view.setGapFillOptions(gap);
    view.setShading(shading == "eyedome" ? stylos::widgets::PointRenderer::Shading::EyeDome
                                         : stylos::widgets::PointRenderer::Shading::Headlight);
    stylos::core::view::ViewFragment f;
    f.id = 1;
    f.octree = octree;
    if (args.contains("--all-leaves")) {
        auto settings = view.scheduler().settings();
        settings.mode = stylos::core::view::CutMode::GlobalLevel;
        settings.globalLevel = octree->depth();
        view.scheduler().setSettings(settings);
        view.scheduler().setPointBudget(octree->cellCount(octree->depth()));
    }
    view.setFragments({f});
    const QStringList views{"front", "back", "left", "right", "top", "bottom"};
    view.setStandardView(static_cast<stylos::core::view::StandardView>(std::max<qsizetype>(0, views.indexOf(viewName))));
    view.fitToScene();
    auto settle = [&] {
        for (int i = 0; i < 6000 && !view.isSettled(); ++i) {
            app.processEvents(QEventLoop::AllEvents, 10);
            QThread::msleep(5);
        }
        for (int i = 0; i < 20; ++i) app.processEvents();
        view.repaint();
    };
    settle();
    const auto pick = view.pickAt(QPointF(view.width() / 2.0, view.height() / 2.0));
    stylos::core::view::Camera camera = view.camera();
    if (pick) camera.setTarget(pick->point);
    // Perspective: pixels per metre at the target = height / (2 d tan(fov / 2)); a leaf spans leafPixels there.
    const double wanted = leafPixels / leafEdge;
    camera.setDistance(double(camera.height()) / (wanted * 2.0 * std::tan(camera.fieldOfView() / 2.0)));
    view.setCamera(camera, false);
    settle();
    const QImage image = view.grabFramebuffer().convertToFormat(QImage::Format_RGB32);
    const QString imagePath = option("--image", QString());
    if (!imagePath.isEmpty()) image.save(imagePath);

    const int w = image.width(), h = image.height();
    stylos::core::view::CoverageMask covered(std::size_t(w) * h);
    std::vector<double> lum(covered.size());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const QRgb c = image.pixel(x, y);
            covered[std::size_t(y) * w + x] = isBackground(c) ? 0 : 1;
            lum[std::size_t(y) * w + x] = luminance(c);
        }
    using stylos::core::view::HoleKind;
    std::vector<HoleKind> kinds;
    const stylos::core::view::CoverageCounts coverage = stylos::core::view::measureCoverage(covered, w, h, 12, &kinds);
    QImage marked = image;
    std::int64_t object = 0, dark = 0;
    std::vector<double> window;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = std::size_t(y) * w + x;
            if (kinds[i] != HoleKind::None)
                marked.setPixel(x, y, kinds[i] == HoleKind::Through ? qRgb(255, 0, 0) : qRgb(255, 140, 0));
            if (!covered[i]) continue;
            ++object;
            if (lum[i] >= 0.15 || x < 2 || y < 2 || x >= w - 2 || y >= h - 2) continue;
            window.clear();
            for (int dy = -2; dy <= 2; ++dy)
                for (int dx = -2; dx <= 2; ++dx) window.push_back(lum[std::size_t(y + dy) * w + x + dx]);
            std::nth_element(window.begin(), window.begin() + 12, window.end());
            if (window[12] > 0.5) {
                ++dark;
                marked.setPixel(x, y, qRgb(255, 255, 0));
            }
        }
    std::int64_t speckle = 0;
    std::vector<std::uint8_t> darker(covered.size(), 0);
    for (int y = 2; y < h - 2; ++y)
        for (int x = 2; x < w - 2; ++x) {
            const std::size_t i = std::size_t(y) * w + x;
            if (!covered[i]) continue;
            window.clear();
            for (int dy = -2; dy <= 2; ++dy)
                for (int dx = -2; dx <= 2; ++dx)
                    if (covered[std::size_t(y + dy) * w + x + dx]) window.push_back(lum[std::size_t(y + dy) * w + x + dx]);
            if (window.size() < 13) continue;
            const auto mid = window.begin() + std::ptrdiff_t(window.size() / 2);
            std::nth_element(window.begin(), mid, window.end());
            if (lum[i] < 0.6 * *mid) darker[i] = 1;
        }
    for (int y = 1; y < h - 1; ++y)
        for (int x = 1; x < w - 1; ++x) {
            const std::size_t i = std::size_t(y) * w + x;
            if (!darker[i]) continue;
            int around = 0;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) around += (dx || dy) ? darker[std::size_t(y + dy) * w + x + dx] : 0;
            if (around <= 1) {
                ++speckle;
                marked.setPixel(x, y, qRgb(0, 200, 255));
            }
        }
    const QString holesPath = option("--holes", QString());
    if (!holesPath.isEmpty()) marked.save(holesPath);
    // The cost of presenting the complete image (the composite pass and the overlays, then glFinish), with and
    // without the gap filling: the median of 9 frames each, alternating.
    std::vector<double> presentOn, presentOff;
    const bool gapFill = view.gapFilling();
    for (int i = 0; i < 18; ++i) {
        view.setGapFilling(i % 2 == 0);
        view.grabFramebuffer();
        (i % 2 == 0 ? presentOn : presentOff).push_back(view.lastFrameMs());
    }
    view.setGapFilling(gapFill);
    auto median = [](std::vector<double> v) {
        std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
        return v[v.size() / 2];
    };
    QJsonObject o;
    o["presentMsGapFill"] = median(presentOn);
    o["presentMsPlain"] = median(presentOff);
    o["file"] = args[1];
    o["leaves"] = double(octree->cellCount(octree->depth()));
    o["leafEdgeM"] = leafEdge;
    o["storedSpacing"] = octree->hasStoredLeafSpacing();
    o["leafPixels"] = leafPixels;
    o["width"] = w;
    o["height"] = h;
    o["splatFactor"] = splat;
    o["shading"] = shading;
    o["pointsDrawn"] = double(view.lastPointsDrawn());
    o["allLeaves"] = args.contains("--all-leaves");
    o["gapFill"] = view.gapFilling();
    o["gapSteps"] = gap.maxSteps;
    o["gapDirections"] = gap.minDirections;
    o["silhouettePixels"] = double(coverage.silhouette);
    o["holes"] = coverage.holeFraction();
    o["holesThrough"] = coverage.throughFraction();
    o["holesEdge"] = coverage.edgeFraction();
    o["objectPixels"] = double(object);
    o["dark"] = object ? double(dark) / double(object) : 0.0;
    o["speckle"] = object ? double(speckle) / double(object) : 0.0;
    o["seconds"] = timer.elapsed() / 1000.0;
    std::printf("%s\n", QJsonDocument(o).toJson(QJsonDocument::Compact).constData());
    return 0;
}
