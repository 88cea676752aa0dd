#include "Automation.h"

#include "stylos/core/scene/SceneEigen.h"

#include "AnnotationActions.h"
#include "DeveloppeeLink.h"
#include "DisplaySettingsWidget.h"
#include "DockingActions.h"
#include "LegendDock.h"
#include "MainActions.h"
#include "LogDock.h"
#include "PropertiesDock.h"
#include "SceneDock.h"
#include "MainWindow.h"
#include "ViewportSync.h"
#include "PlateActions.h"
#include "stylos/core/annotation/PaintRegion.h"
#include "stylos/plate/PlateComposer.h"
#include "stylos/widgets/plate/PlateDialog.h"
#include "stylos/widgets/annotation/DeveloppeeAnnotator.h"
#include "stylos/widgets/developpee/DeveloppeePanel.h"
#include "stylos/widgets/developpee/DeveloppeeView.h"
#include "stylos/widgets/view3d/OrbitBenchmark.h"
#include "stylos/widgets/view3d/PoseBenchmark.h"
#include "stylos/widgets/docking/ContactMonitor.h"
#include "stylos/widgets/docking/DockRunner.h"
#include "stylos/widgets/docking/GizmoController.h"
#include "stylos/widgets/docking/GuideFitRunner.h"
#include "stylos/widgets/document/SceneDocument.h"
#include "stylos/widgets/view3d/ViewportWidget.h"

#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QJsonDocument>
#include <QPainter>
#include <QPixmap>
#include <QTimer>
#include <QToolBar>

#include <algorithm>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>

namespace stylos::app {

namespace {

/** Calls @p then once @p window has been ready for two polls in a row; quits with 1 after @p timeoutMs. */
void whenReady(MainWindow& window, int timeoutMs, std::function<void()> then)
{
    auto* timer = new QTimer(&window);
    auto* clock = new QElapsedTimer;
    clock->start();
    auto streak = std::make_shared<int>(0);
    QObject::connect(timer, &QTimer::timeout, &window, [&window, timer, clock, streak, timeoutMs, then] {
        *streak = isWindowReady(window) ? *streak + 1 : 0;
        if (*streak >= 2) {
            timer->stop();
            delete clock;
            then();
            return;
        }
        if (clock->elapsed() > timeoutMs) {
            timer->stop();
            std::fprintf(stderr, "stylos: the scene was not ready after %d s\n", timeoutMs / 1000);
            QApplication::exit(1);
        }
    });
    timer->start(200);
}

/** The frame benchmarks' common run: the view alone at 1280 × 800, then @p make's benchmark once ready. */
void benchmarkWhenReady(MainWindow& window, const char* option, int timeoutMs,
                        std::function<widgets::FrameBenchmark*(widgets::ViewportWidget&)> make)
{
    window.setErrorDialogsEnabled(false);
    widgets::ViewportWidget* viewport = window.viewport();
    if (!viewport) {
        std::fprintf(stderr, "stylos: %s needs OpenGL 3.3 (core profile)\n", option);
        QTimer::singleShot(0, qApp, [] { QApplication::exit(1); });
        return;
    }
    // From here (just before the file is opened) to the first frame that drew points.
    auto sinceOpen = std::make_shared<QElapsedTimer>();
    sinceOpen->start();
    auto openToFirstFrame = std::make_shared<double>(-1.0);
    QObject::connect(viewport, &widgets::ViewportWidget::pointsDrawn, &window, [sinceOpen, openToFirstFrame](quint64 n) {
        if (*openToFirstFrame < 0 && n > 0) *openToFirstFrame = double(sinceOpen->nsecsElapsed()) / 1e6;
    });
    for (QDockWidget* dock : window.findChildren<QDockWidget*>()) dock->hide();
    for (QToolBar* bar : window.findChildren<QToolBar*>()) bar->hide();
    viewport->setFixedSize(1280, 800);
    window.adjustSize();
    whenReady(window, timeoutMs, [&window, viewport, openToFirstFrame, make] {
        if (window.logDock().errorCount() > 0 || viewport->fragments().empty()) {
            std::fprintf(stderr, "stylos: nothing to show: the file did not open\n");
            QApplication::exit(1);
            return;
        }
        widgets::FrameBenchmark* benchmark = make(*viewport);
        benchmark->setParent(&window);
        QObject::connect(benchmark, &widgets::FrameBenchmark::finished, &window,
                         [openToFirstFrame](QJsonObject result) {
            result.insert(QStringLiteral("openToFirstFrameMs"), *openToFirstFrame);
            std::fputs(QJsonDocument(result).toJson(QJsonDocument::Indented).constData(), stdout);
            std::fflush(stdout);
            QApplication::exit(result.contains(QStringLiteral("error")) ? 1 : 0);
        });
        benchmark->start();
    });
}

} // namespace

bool isWindowReady(const MainWindow& window)
{
    if (window.isBusy()) return false;
    const widgets::ViewportWidget* viewport = window.viewport();
    if (!viewport) return true;
    std::size_t opened = 0;
    for (const auto& f : window.document().scene().fragments()) opened += window.document().octree(f.id) ? 1 : 0;
    return viewport->fragments().size() == opened && (opened == 0 || viewport->isSettled());
}

void grabWhenReady(MainWindow& window, const QString& path, int timeoutMs)
{
    window.setErrorDialogsEnabled(false);
    whenReady(window, timeoutMs, [&window, path] {
        QImage image = window.grab().toImage();
        // The 3D view is a native window, which QWidget::grab() does not capture: its own frame over it.
        if (widgets::ViewportWidget* viewport = window.viewport(); viewport && viewport->isVisible()) {
            const QImage frame = viewport->grabFramebuffer();
            if (!frame.isNull()) {
                QPainter painter(&image);
                painter.drawImage(QRect(viewport->mapTo(&window, QPoint(0, 0)), viewport->size()), frame);
            }
        }
        if (!image.save(path, "PNG")) {
            std::fprintf(stderr, "stylos: %s: could not write the image\n", qPrintable(path));
            QApplication::exit(1);
            return;
        }
        QApplication::exit(window.logDock().errorCount() > 0 ? 1 : 0);
    });
}

void grabGizmoWhenReady(MainWindow& window, const QString& path, int timeoutMs)
{
    window.setErrorDialogsEnabled(false);
    whenReady(window, timeoutMs, [&window, path, timeoutMs] {
        const auto& fragments = window.document().scene().fragments();
        if (fragments.size() < 2 || !window.docking().gizmo()) {
            std::fprintf(stderr, "stylos: --gizmo needs two fragments and the 3D view\n");
            QApplication::exit(1);
            return;
        }
        const auto drum = fragments[0].id, piece = fragments[1].id;
        const auto hasFlutes = [&window, drum] {
            const auto& guides = window.document().fragment(drum)->guides;
            return std::any_of(guides.begin(), guides.end(),
                               [](const core::scene::Guide& g) { return g.kind == core::scene::GuideKind::Groove; });
        };
        const bool fit = !hasFlutes();
        if (fit) window.docking().guideFits().start(drum);
        auto* docked = new QMetaObject::Connection;
        auto dock = [&window, drum, piece, docked] {
            window.document().setDockingDrum(drum);
            window.sceneDock().selectFragment(piece);
            window.docking().gizmo()->setEnabled(true);
            QObject::disconnect(*docked);
            delete docked;
        };
        // The drum frame needs the flutes: dock once they are in (at once when they were already).
        if (fit)
            *docked = QObject::connect(&window.document(), &widgets::SceneDocument::fragmentChanged, &window,
                                       [drum, dock, hasFlutes](quint64 id) {
                                           if (id == drum && hasFlutes()) dock();
                                       });
        else
            dock();
        grabWhenReady(window, path, timeoutMs);
    });
}

void grabAnnotationWhenReady(MainWindow& window, const QString& path, int timeoutMs)
{
    window.setErrorDialogsEnabled(false);
    whenReady(window, timeoutMs, [&window, path, timeoutMs] {
        widgets::ViewportWidget* view = window.viewport();
        const auto& fragments = window.document().scene().fragments();
        if (fragments.empty() || !view) {
            std::fprintf(stderr, "stylos: --annotation needs a fragment and the 3D view\n");
            QApplication::exit(1);
            return;
        }
        const auto id = fragments.front().id;
        window.sceneDock().selectFragment(id);
        window.viewportSync()->pushNow(); // the selection reaches the view: fit it, seen from the front, a little above
        view->setStandardView(core::view::StandardView::Front);
        core::view::Camera camera = view->camera();
        camera.orbit(0.0, 0.35);
        view->setCamera(camera, false);
        view->fitToSelection();
        // The fragment's bounds on screen; the regions are drawn over them as fractions.
        Eigen::AlignedBox2d screen;
        const Eigen::AlignedBox3d box = core::view::sceneBounds(
            [&] {
                auto f = view->fragments();
                std::erase_if(f, [id](const core::view::ViewFragment& v) { return v.id != id; });
                return f;
            }());
        for (int corner = 0; corner < 8; ++corner)
            if (const auto p = view->camera().project(box.corner(Eigen::AlignedBox3d::CornerType(corner))))
                screen.extend(p->head<2>());
        auto at = [&](double u, double v) { return Eigen::Vector2d(screen.min() + Eigen::Vector2d(u, v).cwiseProduct(screen.sizes())); };
        const std::vector<std::pair<int, std::vector<Eigen::Vector2d>>> regions{
            {1, {at(0.15, 0.2), at(0.5, 0.15), at(0.55, 0.45), at(0.2, 0.5)}},
            {2, {at(0.55, 0.3), at(0.85, 0.35), at(0.8, 0.6), at(0.6, 0.55)}},
            {3, {at(0.25, 0.6), at(0.7, 0.62), at(0.65, 0.85), at(0.3, 0.8)}}};
        AnnotationActions& annotation = window.annotation();
        for (const auto& [classId, polygon] : regions) {
            annotation.classBox()->setCurrentIndex(annotation.classBox()->findData(classId));
            annotation.applyLasso(core::view::lassoVisibleLeaves(view->fragments(), view->camera(), {id}, polygon), false);
        }
        view->setShading(widgets::PointRenderer::Shading::Annotation);
        window.actions().syncShading();
        if (auto* display = window.propertiesDock().displaySettings()) display->syncFromViewport();
        grabWhenReady(window, path, timeoutMs);
    });
}

namespace {

/** Once ready: fits the first fragment's drum guides (unless it has flute guides), makes it the docking drum, selects
 *  the second fragment and docks it to the flutes; @p then(piece) once docked. Exit 1 on failure. */
void dockSecondFragment(MainWindow& window, int timeoutMs, std::function<void(quint64)> then)
{
    window.setErrorDialogsEnabled(false);
    whenReady(window, timeoutMs, [&window, then] {
        const auto& fragments = window.document().scene().fragments();
        if (fragments.size() < 2) {
            std::fprintf(stderr, "stylos: --dock needs two fragments\n");
            QApplication::exit(1);
            return;
        }
        const auto drum = fragments[0].id, piece = fragments[1].id;
        DockingActions& docking = window.docking();
        const auto hasFlutes = [&window, drum] {
            const auto& guides = window.document().fragment(drum)->guides;
            return std::any_of(guides.begin(), guides.end(),
                               [](const core::scene::Guide& g) { return g.kind == core::scene::GuideKind::Groove; });
        };
        QObject::connect(&docking.docker(), &widgets::DockRunner::docked, &window, [then, piece] { then(piece); });
        const auto dockEnded = [](quint64, const QString& message) {
            std::fprintf(stderr, "stylos: %s\n", qPrintable(message));
            QApplication::exit(1);
        };
        QObject::connect(&docking.docker(), &widgets::DockRunner::failed, &window, dockEnded);
        QObject::connect(&docking.docker(), &widgets::DockRunner::cancelled, &window, dockEnded);
        auto dock = [&window, &docking, drum, piece] {
            window.document().setDockingDrum(drum);
            window.sceneDock().selectFragment(piece);
            if (!docking.docker().start(piece)) {
                std::fprintf(stderr, "stylos: --dock could not start docking the second fragment\n");
                QApplication::exit(1);
            }
        };
        if (hasFlutes()) {
            dock();
            return;
        }
        // A fit that fails (no flutes found) or is cancelled ends the run with its message, as a failed dock does.
        const auto endWith = [drum](quint64 id, const QString& message) {
            if (id != drum) return;
            std::fprintf(stderr, "stylos: %s\n", qPrintable(message));
            QApplication::exit(1);
        };
        QObject::connect(&window.docking().guideFits(), &widgets::GuideFitRunner::failed, &window, endWith);
        QObject::connect(&window.docking().guideFits(), &widgets::GuideFitRunner::cancelled, &window, endWith);
        if (!window.docking().guideFits().start(drum)) {
            std::fprintf(stderr, "stylos: --dock could not start fitting the guides of the first fragment\n");
            QApplication::exit(1);
            return;
        }
        auto* fitted = new QMetaObject::Connection;
        *fitted = QObject::connect(&window.document(), &widgets::SceneDocument::fragmentChanged, &window,
                                   [drum, dock, hasFlutes, fitted](quint64 id) {
            if (id != drum || !hasFlutes()) return;
            QObject::disconnect(*fitted);
            delete fitted;
            dock();
        });
    });
}

} // namespace

void grabDockWhenReady(MainWindow& window, const QString& path, int timeoutMs)
{
    window.resize(1400, 900);
    dockSecondFragment(window, timeoutMs, [&window, path, timeoutMs](quint64) {
        DockingActions& docking = window.docking();
        // Once the contact readout of the docked fragment is in: the picture.
        auto* waiting = new QMetaObject::Connection;
        *waiting = QObject::connect(&docking.contact(), &widgets::ContactMonitor::changed, &window,
                                    [&window, &docking, path, timeoutMs, waiting] {
            if (docking.contact().state() != widgets::ContactMonitor::State::Ready) return;
            QObject::disconnect(*waiting);
            delete waiting;
            // The picture: the readout in view, the log's line of the dock under the 3D view.
            if (auto* developpee = window.findChild<QDockWidget*>(QStringLiteral("developpeeDock"))) developpee->hide();
            window.logDock().raise();
            window.resizeDocks({&window.logDock()}, {140}, Qt::Vertical);
            if (window.viewport()) window.viewport()->fitToSelection();
            QTimer::singleShot(300, &window, [&window, path, timeoutMs] {
                window.propertiesDock().showContactReadout();
                grabWhenReady(window, path, timeoutMs);
            });
        });
    });
}

namespace {

/** Paints @p pixels with @p classId of @p layer as one stroke, the way the view's tools do. */
void paintStroke(MainWindow& window, widgets::DeveloppeeView& view, core::annotation::AnnotationLayer layer,
                 std::uint8_t classId, const std::vector<std::uint32_t>& pixels)
{
    window.annotator().setActive(layer, classId);
    Q_EMIT view.strokeStarted();
    Q_EMIT view.pixelsPainted(pixels, classId);
    Q_EMIT view.strokeFinished();
}

/** The demo's regions, in fractions of the image. */
void paintDemoRegions(MainWindow& window, widgets::DeveloppeeView& view)
{
    using core::annotation::AnnotationLayer;
    using core::annotation::GridPoint;
    const int w = view.image().width(), h = view.image().height();
    const auto polygon = [w, h](std::initializer_list<std::pair<double, double>> corners) {
        std::vector<GridPoint> points;
        for (const auto& [x, y] : corners) points.push_back({x * w, y * h});
        return core::annotation::polygonPixels(points, w, h);
    };
    paintStroke(window, view, AnnotationLayer::Toolmark, 3, polygon({{0.08, 0.15}, {0.3, 0.12}, {0.32, 0.7}, {0.1, 0.75}}));
    paintStroke(window, view, AnnotationLayer::Material, 1,
                polygon({{0.02, 0.05}, {0.55, 0.05}, {0.6, 0.5}, {0.52, 0.95}, {0.02, 0.95}}));
    paintStroke(window, view, AnnotationLayer::Material, 3,
                polygon({{0.66, 0.18}, {0.88, 0.1}, {0.95, 0.55}, {0.8, 0.88}, {0.64, 0.7}}));
    std::vector<std::uint32_t> band; // a crack of fractured marble, brushed from the top to the bottom
    const double radius = std::max(1.0, 0.012 * w);
    for (int i = 0; i < 8; ++i) {
        const GridPoint a{(0.38 + 0.03 * std::sin(i)) * w, i / 8.0 * h}, b{(0.38 + 0.03 * std::sin(i + 1)) * w, (i + 1) / 8.0 * h};
        for (std::uint32_t p : core::annotation::brushPixels(a, b, radius, w, h)) band.push_back(p);
    }
    std::sort(band.begin(), band.end());
    band.erase(std::unique(band.begin(), band.end()), band.end());
    paintStroke(window, view, AnnotationLayer::Material, 2, band);
    window.annotator().setActive(AnnotationLayer::Material, 1);
    view.setTool(widgets::PaintTool::Brush);
}

} // namespace

void grabPaintWhenReady(MainWindow& window, const QString& path, int timeoutMs)
{
    window.setErrorDialogsEnabled(false);
    window.resize(1500, 950);
    whenReady(window, timeoutMs, [&window, path, timeoutMs] {
        const auto& fragments = window.document().scene().fragments();
        if (fragments.empty()) {
            std::fprintf(stderr, "stylos: --paint needs a fragment\n");
            QApplication::exit(1);
            return;
        }
        const auto id = fragments[0].id;
        widgets::DeveloppeeView& view = *window.developpeePanel().view();
        auto* shown = new QMetaObject::Connection;
        *shown = QObject::connect(&view, &widgets::DeveloppeeView::developpeeChanged, &window,
                                  [&window, &view, id, shown, path, timeoutMs] {
            if (view.fragmentId() != id || !view.hasDeveloppee()) return;
            QObject::disconnect(*shown);
            delete shown;
            if (!view.canPaint()) {
                std::fprintf(stderr, "stylos: --paint: the développée of the first fragment cannot be painted\n");
                QApplication::exit(1);
                return;
            }
            paintDemoRegions(window, view);
            window.legendDock().raise();
            grabWhenReady(window, path, timeoutMs);
        });
        window.sceneDock().selectFragment(id);
        window.developpeeLink().compute();
    });
}

void grabAssemblyPaintWhenReady(MainWindow& window, const QString& path, int timeoutMs)
{
    window.resize(1500, 950);
    dockSecondFragment(window, timeoutMs, [&window, path, timeoutMs](quint64 piece) {
        const core::scene::Fragment* fragment = window.document().fragment(piece);
        if (!fragment || !window.document().assembly(fragment->assembly)) {
            std::fprintf(stderr, "stylos: --dock --paint: the second fragment is in no assembly\n");
            QApplication::exit(1);
            return;
        }
        widgets::DeveloppeeView& view = *window.developpeePanel().view();
        auto* shown = new QMetaObject::Connection;
        *shown = QObject::connect(&view, &widgets::DeveloppeeView::developpeeChanged, &window,
                                  [&window, &view, piece, shown, path, timeoutMs] {
            if (!view.assemblyIndex()) return; // the fragment's own, or the index not yet set
            QObject::disconnect(*shown);
            delete shown;
            // The fragment's box in the image; marble over its left part and the drum beside it, plaster across its
            // right part onto the drum on the other side.
            using core::annotation::AnnotationLayer;
            using core::annotation::GridPoint;
            const int w = view.image().width(), h = view.image().height();
            int left = w, right = -1, top = h, bottom = -1;
            for (int r = 0; r < h; ++r)
                for (int c = 0; c < w; ++c)
                    if (view.pieceAt(c, r) == piece) left = std::min(left, c), right = std::max(right, c),
                                                     top = std::min(top, r), bottom = std::max(bottom, r);
            if (right < 0) {
                std::fprintf(stderr, "stylos: --dock --paint: the fragment does not show in its assembly's développée\n");
                QApplication::exit(1);
                return;
            }
            const double fw = right - left, fh = bottom - top;
            const auto polygon = [w, h](std::initializer_list<std::pair<double, double>> corners) {
                std::vector<GridPoint> points;
                for (const auto& [x, y] : corners) points.push_back({x, y});
                return core::annotation::polygonPixels(points, w, h);
            };
            paintStroke(window, view, AnnotationLayer::Material, 1,
                        polygon({{left - 0.6 * fw, top + 0.1 * fh}, {left + 0.45 * fw, top + 0.05 * fh},
                                 {left + 0.5 * fw, bottom - 0.1 * fh}, {left - 0.5 * fw, bottom + 0.05 * fh}}));
            paintStroke(window, view, AnnotationLayer::Material, 3,
                        polygon({{left + 0.6 * fw, top + 0.3 * fh}, {right + 0.6 * fw, top + 0.25 * fh},
                                 {right + 0.55 * fw, top + 0.65 * fh}, {left + 0.62 * fw, top + 0.7 * fh}}));
            window.annotator().setActive(AnnotationLayer::Material, 1);
            view.setTool(widgets::PaintTool::Brush);
            // Zoomed on the fragment and its surroundings.
            const double zoom = std::min(view.width() / (2.6 * fw), view.height() / (1.6 * fh));
            view.setTransform(zoom, QPointF(view.width() / 2.0, view.height() / 2.0) -
                                        zoom * QPointF(0.5 * (left + right), 0.5 * (top + bottom)));
            window.legendDock().raise();
            grabWhenReady(window, path, timeoutMs);
        });
        if (!window.developpeeLink().computeAssembly(fragment->assembly)) {
            std::fprintf(stderr, "stylos: --dock --paint: the assembly's développée cannot start\n");
            QApplication::exit(1);
        }
    });
}

namespace {

/** The demo plate: the first fragment's développée with its material layer in colour, and its front view with the
 *  same layer in black-and-white hatches, at the first scale of a short list at which both fit A4 landscape. */
core::plate::PlateSpec demoPlate(MainWindow& window)
{
    namespace cp = core::plate;
    const auto sources = PlateActions::sourcesOf(window.document());
    cp::PlateSpec spec;
    spec.landscape = true;
    spec.dpi = 300;
    const std::string name = window.document().scene().fragments().front().name;
    // The caption is the plate's text, in the window's language (the plate keeps it as it was written).
    spec.caption = QCoreApplication::translate(
                       "stylos::app::Automation",
                       "Demo drum (%1): A, développée under the skydome, material and condition in colour; B, front "
                       "view lit from the viewer, the same classes as black-and-white hatches. Generated scan; the "
                       "painted regions are an illustration.")
                       .arg(QString::fromStdString(name))
                       .toStdString();
    cp::PanelSpec dev;
    dev.layer = core::annotation::AnnotationLayer::Material;
    dev.fragment = name;
    cp::PanelSpec front = dev;
    front.view = cp::PanelView::Front;
    front.shading = cp::PanelShading::Headlight;
    front.hatches = true;
    for (const double scale : {5.0, 10.0, 20.0, 25.0, 50.0, 100.0}) {
        dev.scale = front.scale = scale;
        spec.panels = {dev, front};
        cp::PlateSpec quick = spec;
        quick.dpi = 72;
        if (plate::composePlate(*sources, quick, {})) break;
    }
    return spec;
}

} // namespace

void grabPlateWhenReady(MainWindow& window, const QString& path, const QString& base, int timeoutMs)
{
    window.setErrorDialogsEnabled(false);
    window.resize(1500, 950);
    whenReady(window, timeoutMs, [&window, path, base, timeoutMs] {
        const auto& fragments = window.document().scene().fragments();
        if (fragments.empty()) {
            std::fprintf(stderr, "stylos: --plate needs a fragment\n");
            QApplication::exit(1);
            return;
        }
        const auto id = fragments[0].id;
        widgets::DeveloppeeView& view = *window.developpeePanel().view();
        auto* shown = new QMetaObject::Connection;
        *shown = QObject::connect(&view, &widgets::DeveloppeeView::developpeeChanged, &window,
                                  [&window, &view, id, shown, path, base] {
            if (view.fragmentId() != id || !view.hasDeveloppee() || !view.canPaint()) return;
            QObject::disconnect(*shown);
            delete shown;
            paintDemoRegions(window, view);
            const core::plate::PlateSpec spec = demoPlate(window);
            window.document().setPlate(spec);
            PlateActions& plates = window.plateActions();
            auto* step = new int(0);
            QObject::connect(&plates, &PlateActions::plateFinished, &window, [&window, &plates, spec, step, path, base](bool written) {
                if (!written) {
                    std::fprintf(stderr, "stylos: --plate: the plate could not be drawn\n");
                    QApplication::exit(1);
                    return;
                }
                if (++*step == 1) {
                    core::plate::PlateSpec png = spec;
                    png.dpi = 200;
                    plates.exportPlate(png, base + QStringLiteral(".png"));
                    return;
                }
                // Both files written: the dialog with its preview, grabbed.
                auto* dialog = new widgets::PlateDialog(PlateActions::sourcesOf(window.document()), spec, &window);
                dialog->setAttribute(Qt::WA_DeleteOnClose);
                QObject::connect(dialog, &widgets::PlateDialog::previewUpdated, &window, [dialog, path] {
                    if (dialog->previewPending()) return;
                    const bool saved = dialog->grab().toImage().save(path, "PNG");
                    if (!saved) std::fprintf(stderr, "stylos: %s: could not write the image\n", qPrintable(path));
                    QApplication::exit(saved ? 0 : 1);
                });
                dialog->show();
            });
            plates.exportPlate(spec, base + QStringLiteral(".pdf"));
        });
        window.sceneDock().selectFragment(id);
        window.developpeeLink().compute();
    });
}

void orbitWhenReady(MainWindow& window, int frames, int timeoutMs)
{
    benchmarkWhenReady(window, "--orbit-benchmark", timeoutMs, [frames](widgets::ViewportWidget& viewport) {
        widgets::OrbitBenchmark::Options options;
        options.frames = frames;
        return new widgets::OrbitBenchmark(viewport, options);
    });
}

void poseWhenReady(MainWindow& window, int frames, int timeoutMs)
{
    benchmarkWhenReady(window, "--pose-benchmark", timeoutMs, [&window, frames](widgets::ViewportWidget& viewport) {
        widgets::PoseBenchmark::Options options;
        options.frames = frames;
        auto continuing = std::make_shared<bool>(false);
        options.setPose = [&window, continuing](std::uint64_t id, const Eigen::Matrix4d& pose) {
            window.document().setFragmentPose(id, core::scene::poseFromEigen(pose), *continuing); // one undo step
            *continuing = true;
            window.viewportSync()->pushNow(); // what the next turn of the event loop would push
        };
        return new widgets::PoseBenchmark(viewport, std::move(options));
    });
}

} // namespace stylos::app
