// A brush stroke on a large développée in the workbench's own view, timed from the mouse event to the repainted
// window (issue 15: a brush stroke on a 16 k × 4 k développée applies and repaints in ≤ 16 ms, 95th percentile).
//
//   stylos_paint_stroke --poct DRUM.poct [--radius 0.15] [--width 16384] [--height 4096] [--moves 200]
//                       [--radii 10,40,100]
//
// The octree's leaves are placed on a width × height développée of its own z axis (a cylinder of `radius`
// metres through the octree's box centre, the pixel size that makes `width` columns, the rows centred on the
// box centre; a drum of that radius and 2π r / 4 high fills a 16 k × 4 k image), so the leaves
// of a pixel are as scattered in leaf order as a real développée's. A SceneDocument holds the fragment and its
// labels, a DeveloppeeAnnotator joins them to a 1600 × 1000 DeveloppeeView, the brush is chosen, and for every
// radius (image pixels) one stroke of `moves` mouse moves, 3 px apart, is sent at zoom 1 (one image pixel per
// screen pixel, where one paints). Each move is timed from sending the event to the end of a synchronous
// repaint() (the dab's pixels → their leaves → SceneDocument::setLabels → the overlay's pixels → the window);
// the release (the stroke's undo step) is timed apart. Prints one JSON object. Run under Xvfb or a desktop.
#include "stylos/core/annotation/LabelRaster.h"
#include "stylos/core/annotation/LeafLabels.h"
#include "stylos/core/annotation/PixelLeafIndex.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/shading/HeightField.h"
#include "stylos/core/unroll/UnrollMap.h"
#include "stylos/widgets/annotation/DeveloppeeAnnotator.h"
#include "stylos/widgets/developpee/DeveloppeeView.h"
#include "stylos/widgets/document/SceneDocument.h"
#include "stylos/widgets/tasks/TaskManager.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMouseEvent>
#include <QTest>
#include <QUndoStack>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace stylos;

namespace {

[[noreturn]] void die(const std::string& message)
{
    std::fprintf(stderr, "stylos_paint_stroke: %s\n", message.c_str());
    std::exit(1);
}

double percentile(std::vector<double> v, double p)
{
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[std::min(v.size() - 1, std::size_t(p * double(v.size() - 1) + 0.5))];
}

void send(QWidget& w, QEvent::Type type, QPointF pos, Qt::MouseButton button, Qt::MouseButtons buttons)
{
    QMouseEvent event(type, pos, w.mapToGlobal(pos), button, buttons, Qt::NoModifier);
    QApplication::sendEvent(&w, &event);
}

} // namespace

int main(int argc, char** argv)
{
    QApplication app(argc, argv);
    std::string poct;
    int width = 16384, height = 4096, moves = 200;
    double radius = 0.15;
    std::vector<int> radii{10, 40, 100};
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() -> std::string {
            if (i + 1 >= argc) die(a + " needs a value");
            return argv[++i];
        };
        if (a == "--poct") poct = next();
        else if (a == "--width") width = std::stoi(next());
        else if (a == "--height") height = std::stoi(next());
        else if (a == "--moves") moves = std::stoi(next());
        else if (a == "--radius") radius = std::stod(next());
        else if (a == "--radii") {
            radii.clear();
            const std::string list = next();
            for (std::size_t p = 0; p < list.size();) {
                const std::size_t q = list.find(',', p);
                radii.push_back(std::stoi(list.substr(p, q - p)));
                p = q == std::string::npos ? list.size() : q + 1;
            }
        } else die("unknown option " + a + " (usage: --poct DRUM.poct [--width W] [--height H] [--moves N] [--radius M] [--radii 10,40,100])");
    }
    if (poct.empty()) die("--poct DRUM.poct is required (e.g. the drum stylos_ao_benchmark caches)");
    auto opened = core::octree::PackedOctree::open(poct);
    if (!opened) die(opened.error().message);
    auto octree = std::make_shared<const core::octree::PackedOctree>(std::move(opened).value());
    QElapsedTimer setup;
    setup.start();

    // The développée's grid: the octree's z axis through its box centre.
    const auto root = octree->root();
    const Eigen::Vector3d centre(root.centre[0], root.centre[1], root.centre[2]);
    const core::unroll::Axis axis{centre, Eigen::Vector3d::UnitZ()};
    const double pixel = 2 * M_PI * radius / width;
    const core::unroll::UnrollMap map(core::unroll::Surface::cylinder(axis, radius).value(),
                                      core::unroll::defaultReferenceDir(axis.direction), 0.0, pixel, width, height,
                                      0.5 * height * pixel);
    auto leafPixels = core::annotation::leafPixels(*octree, map);
    if (!leafPixels) die(leafPixels.error().message);
    const auto onImage = std::count_if(leafPixels->begin(), leafPixels->end(), [](std::int64_t p) { return p >= 0; });
    auto index = std::make_shared<const core::annotation::PixelLeafIndex>(
        core::annotation::PixelLeafIndex::build(*leafPixels, width, height));
    auto heights = std::make_shared<core::shading::HeightField>(core::shading::HeightField::create(width, height, pixel).value());
    QImage image(width, height, QImage::Format_Grayscale8);
    for (int r = 0; r < height; ++r) std::fill_n(image.scanLine(r), width, std::uint8_t(96 + (r / 64 % 2) * 64));

    widgets::TaskManager tasks;
    widgets::SceneDocument document(tasks);
    core::scene::Fragment fragment;
    fragment.name = "drum";
    fragment.octreePath = poct;
    const auto id = document.addFragment(fragment, octree);
    document.undoStack()->clear(); // only the strokes are counted
    widgets::DeveloppeeView view;
    view.resize(1600, 1000);
    view.show();
    if (!QTest::qWaitForWindowExposed(&view)) die("the view's window was not exposed (no display?)");
    widgets::DeveloppeeAnnotator annotator(document, view);
    view.setDeveloppee(id, image, heights, map, index);
    if (!view.canPaint()) die("the view cannot paint this développée");
    annotator.setActive(core::annotation::AnnotationLayer::Material, 2);
    view.setTool(widgets::PaintTool::Brush);
    view.setTransform(1.0, QPointF(-0.5 * width + 800, -0.5 * height + 500)); // zoom 1 on the image's centre
    QApplication::processEvents();
    const double setupSeconds = setup.elapsed() / 1000.0;

    QJsonArray strokes;
    for (std::size_t k = 0; k < radii.size(); ++k) {
        view.setBrushSize(2.0 * radii[k] * pixel);
        const double y = 200 + 250 * double(k);
        QPointF at(200, y);
        QElapsedTimer timer;
        std::vector<double> ms;
        timer.start();
        send(view, QEvent::MouseButtonPress, at, Qt::LeftButton, Qt::LeftButton);
        view.repaint();
        const double pressMs = timer.nsecsElapsed() / 1e6;
        for (int m = 0; m < moves; ++m) {
            at += QPointF(3.0, (m / 50) % 2 ? -1.0 : 1.0);
            timer.restart();
            send(view, QEvent::MouseMove, at, Qt::NoButton, Qt::LeftButton);
            view.repaint();
            ms.push_back(timer.nsecsElapsed() / 1e6);
        }
        timer.restart();
        send(view, QEvent::MouseButtonRelease, at, Qt::LeftButton, Qt::NoButton);
        view.repaint();
        const double releaseMs = timer.nsecsElapsed() / 1e6;
        QJsonObject s;
        s["radius_px"] = radii[k];
        s["brush_mm"] = 2000.0 * radii[k] * pixel;
        s["moves"] = moves;
        s["press_ms"] = pressMs;
        s["median_ms"] = percentile(ms, 0.5);
        s["p95_ms"] = percentile(ms, 0.95);
        s["max_ms"] = percentile(ms, 1.0);
        s["release_ms"] = releaseMs;
        strokes.append(s);
    }
    QJsonObject out;
    out["octree"] = QString::fromStdString(poct);
    out["leaves"] = double(octree->cellCount(octree->depth()));
    out["leaves_on_image"] = double(onImage);
    out["width"] = width;
    out["height"] = height;
    out["pixel_mm"] = pixel * 1000.0;
    out["view"] = "1600x1000, zoom 1";
    out["setup_s"] = setupSeconds;
    out["undo_steps"] = document.undoStack()->count();
    out["strokes"] = strokes;
    std::printf("%s\n", QJsonDocument(out).toJson(QJsonDocument::Compact).constData());
    return document.undoStack()->count() == int(radii.size()) ? 0 : 2;
}
