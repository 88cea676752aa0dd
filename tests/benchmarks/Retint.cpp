// Re-tinting the 3D view after an annotation edit (issue 15: re-tinting the 3D view of a 30 M-point drum after an
// edit ≤ 2 s, the window never freezing).
//
//   stylos_retint DRUM.poct [--size 1280x800] [--repeat 5]
//
// Opens the octree in the workbench's ViewportWidget with the Annotation shading and all its leaves unlabelled,
// waits until the view is refined, then times, from the call to the end of a frame drawn with it (the GUI thread
// is busy all along: that is how long the window would not answer; the frame is grabbed, QOpenGLWidget::
// grabFramebuffer, so that the GL has finished it):
//   stroke  — ViewportWidget::updateLabels over a range of 1 M leaves in the middle of the leaf order (what
//             AnnotationSync sends after a brush stroke: the bytes between the lowest and highest leaf changed);
//   spread  — the same for a change whose lowest and highest leaves are the first and the last (a flood fill or a
//             3D lasso that reaches both ends of the leaf order: the whole array's bytes);
//   layer   — ViewportWidget::setLabels with a new whole array (a layer switch, a project opened);
//   frame   — a frame with no change (the frame alone, for comparison).
// Prints one JSON object with the median and the worst of `repeat` runs of each. Run under Xvfb or a desktop.
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/widgets/view3d/ViewportWidget.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QJsonDocument>
#include <QJsonObject>
#include <QThread>

#include <algorithm>
#include <cstdio>
#include <vector>

int main(int argc, char** argv)
{
    QApplication app(argc, argv);
    const QStringList args = app.arguments();
    if (args.size() < 2) {
        std::fprintf(stderr, "usage: stylos_retint DRUM.poct [--size WxH] [--repeat N]\n");
        return 2;
    }
    auto option = [&](const char* name, const QString& fallback) {
        const int i = int(args.indexOf(QString::fromLatin1(name)));
        return i > 0 && i + 1 < args.size() ? args[i + 1] : fallback;
    };
    const QStringList size = option("--size", "1280x800").split('x');
    const int repeat = std::max(1, option("--repeat", "5").toInt());
    auto opened = stylos::core::octree::PackedOctree::open(args[1].toStdString());
    if (!opened.ok()) {
        std::fprintf(stderr, "%s\n", opened.error().message.c_str());
        return 1;
    }
    const auto octree = std::make_shared<const stylos::core::octree::PackedOctree>(std::move(opened).value());
    const std::uint64_t leaves = octree->cellCount(octree->depth());

    stylos::widgets::ViewportWidget view;
    view.resize(size.value(0).toInt(), size.value(1).toInt());
    view.show();
    view.setShading(stylos::widgets::PointRenderer::Shading::Annotation);
    stylos::widgets::PointRenderer::ClassColours colours{};
    colours[2] = {200, 60, 40, 255};
    colours[3] = {40, 90, 200, 255};
    view.setClassColours(colours);
    stylos::core::view::ViewFragment f;
    f.id = 1;
    f.octree = octree;
    view.setFragments({f});
    std::vector<std::uint8_t> labels(leaves, 0);
    view.setLabels(1, labels);
    view.fitToScene();
    for (int i = 0; i < 12000 && !view.isSettled(); ++i) {
        app.processEvents(QEventLoop::AllEvents, 10);
        QThread::msleep(5);
    }
    for (int i = 0; i < 20; ++i) app.processEvents();

    auto timed = [&](auto&& change) {
        std::vector<double> ms;
        for (int r = 0; r < repeat; ++r) {
            QElapsedTimer t;
            t.start();
            change(r);
            // A frame drawn and read back: llvmpipe (and any GL) runs the commands only when made to finish.
            const QImage image = view.grabFramebuffer();
            if (image.isNull()) std::fprintf(stderr, "no frame\n");
            ms.push_back(t.nsecsElapsed() / 1e6);
        }
        std::sort(ms.begin(), ms.end());
        QJsonObject o;
        o["median_ms"] = ms[ms.size() / 2];
        o["max_ms"] = ms.back();
        return o;
    };
    const std::uint64_t strokeLeaves = std::min<std::uint64_t>(leaves, 1000000), strokeFirst = (leaves - strokeLeaves) / 2;
    QJsonObject out;
    out["octree"] = args[1];
    out["leaves"] = double(leaves);
    out["size"] = option("--size", "1280x800");
    out["points_drawn"] = double(view.lastPointsDrawn());
    out["frame"] = timed([&](int) {});
    out["stroke"] = timed([&](int r) {
        std::fill_n(labels.begin() + std::ptrdiff_t(strokeFirst), strokeLeaves, std::uint8_t(2 + r % 2));
        view.updateLabels(1, strokeFirst, std::span<const std::uint8_t>(labels).subspan(strokeFirst, strokeLeaves));
    });
    out["spread"] = timed([&](int r) {
        labels.front() = labels.back() = std::uint8_t(2 + r % 2);
        view.updateLabels(1, 0, labels);
    });
    out["layer"] = timed([&](int r) {
        std::fill(labels.begin(), labels.end(), std::uint8_t(r % 2 ? 3 : 0));
        view.setLabels(1, labels);
    });
    // A check that the tint shows: the picture with every leaf of class 3 (blue) against every leaf unlabelled.
    auto blueness = [&](std::uint8_t id) {
        std::fill(labels.begin(), labels.end(), id);
        view.setLabels(1, labels);
        const QImage image = view.grabFramebuffer().convertToFormat(QImage::Format_RGB32);
        double sum = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x) sum += qBlue(image.pixel(x, y)) - qRed(image.pixel(x, y));
        return sum / double(image.width() * image.height());
    };
    const double plain = blueness(0), tinted = blueness(3);
    out["blue_minus_red_plain"] = plain;
    out["blue_minus_red_tinted"] = tinted;
    std::printf("%s\n", QJsonDocument(out).toJson(QJsonDocument::Compact).constData());
    return tinted > plain + 5 ? 0 : 3; // the tint must show
}
