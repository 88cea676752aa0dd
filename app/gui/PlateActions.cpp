// File › Export plate… and Export développée image…
#include "PlateActions.h"

#include "stylos/core/scene/SceneEigen.h"
#include "stylos/core/util/SubProgress.h"

#include "stylos/core/image/ImageWriter.h"
#include "stylos/plate/PlateComposer.h"
#include "stylos/plate/PlateWriter.h"
#include "stylos/widgets/annotation/LabelStore.h"
#include "stylos/widgets/developpee/DeveloppeeJob.h"
#include "stylos/widgets/developpee/DeveloppeeView.h"
#include "stylos/widgets/document/SceneDocument.h"
#include "stylos/widgets/plate/PlateDialog.h"
#include "stylos/widgets/plate/PlateTexts.h"
#include "stylos/widgets/tasks/TaskManager.h"

#include <QAction>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QInputDialog>
#include <QMenu>

namespace stylos::app {

namespace cp = core::plate;

PlateActions::PlateActions(widgets::SceneDocument& document, widgets::DeveloppeeView& developpee, QWidget& window)
    : QObject(&window), m_document(document), m_view(developpee), m_window(window), m_plate(new QAction(this)),
      m_developpee(new QAction(this)), m_viewImage(new QAction(this))
{
    connect(m_viewImage, &QAction::triggered, this, &PlateActions::chooseViewImage);
    connect(m_plate, &QAction::triggered, this, &PlateActions::choosePlate);
    connect(m_developpee, &QAction::triggered, this, &PlateActions::chooseDeveloppee);
    connect(&m_document, &widgets::SceneDocument::fragmentAdded, this, &PlateActions::updateEnabled);
    connect(&m_document, &widgets::SceneDocument::fragmentRemoved, this, &PlateActions::updateEnabled);
    connect(&m_document, &widgets::SceneDocument::sceneReset, this, &PlateActions::updateEnabled);
    retranslateUi();
    updateEnabled();
}

void PlateActions::populate(QMenu& menu, QAction* before)
{
    menu.insertAction(before, m_plate);
    menu.insertAction(before, m_developpee);
    menu.insertAction(before, m_viewImage);
    menu.insertSeparator(before);
}

void PlateActions::retranslateUi()
{
    m_plate->setText(tr("Export &plate…"));
    m_plate->setStatusTip(tr("A publication plate at an exact scale: développées and orthographic views at 1:N with "
                             "scale bars, legend and caption, as PDF, SVG, TIFF or PNG"));
    m_developpee->setText(tr("Export &développée image…"));
    m_developpee->setStatusTip(tr("The développée on show as PNG or TIFF with its pixel size, and its map (.json) beside it"));
    m_viewImage->setText(tr("Export &view image…"));
    m_viewImage->setStatusTip(tr("The visible fragments seen along the 3D view's direction, orthographic, every cell drawn, "
                                 "at a width you choose, as PNG or TIFF"));
}

void PlateActions::updateEnabled()
{
    m_plate->setEnabled(!m_document.scene().empty());
    m_viewImage->setEnabled(!m_document.scene().empty());
}

std::shared_ptr<const cp::PlateSources> PlateActions::sourcesOf(const widgets::SceneDocument& document)
{
    auto sources = std::make_shared<cp::PlateSources>();
    const core::scene::Scene& scene = document.scene();
    sources->source = document.projectPath().isEmpty() ? std::string("the project") : document.projectPath().toStdString();
    sources->isProject = true;
    sources->legend = scene.legend();
    for (const core::scene::Fragment& f : scene.fragments()) {
        cp::PlateFragment p;
        p.name = f.name;
        p.path = f.octreePath;
        p.missing = f.octreeMissing;
        p.pose = scene.worldPose(f.id);
        p.visible = f.visible;
        p.labels[0] = document.labels().labels(f.id, core::annotation::AnnotationLayer::Material);
        p.labels[1] = document.labels().labels(f.id, core::annotation::AnnotationLayer::Toolmark);
        // Its développée as the Développée dock last showed it (the axis guide, the drum guides' radius, the dock's
        // settings): the plate's angles and cut are the dock's — unless the axis it was unrolled about is no longer
        // the fragment's (docked, moved or given another guide since). Else about its axis guide or its drum's.
        const auto axis = core::scene::unrollAxis(scene, f.id, document.drumFor(f.id));
        const auto shown = document.developpee(f.id);
        const auto sameAxis = [&axis](const core::unroll::Axis& used) {
            return axis && (used.point - axis->origin).norm() <= 1e-9 && (used.direction - axis->direction).norm() <= 1e-9;
        };
        if (shown && shown->ok() && !shown->pieceAt && shown->octreePath == QString::fromStdString(f.octreePath.string()) &&
            (!shown->settings.axis || sameAxis(*shown->settings.axis))) {
            p.unrolling = shown->settings.options();
        } else {
            cp::unrollAsTheDock(p, scene, f.id, document.drumFor(f.id));
        }
        sources->fragments.push_back(std::move(p));
    }
    return sources;
}

void PlateActions::choosePlate()
{
    const auto sources = sourcesOf(m_document);
    const auto kept = m_document.scene().plate();
    // Without a kept plate, the current fragment's développée (else the first visible one's), sized by its octree
    // (the one the document holds open), with the layer painted on it.
    std::optional<std::size_t> current; // its place in the sources: they follow the scene's fragments
    if (m_fragment) {
        const auto& fragments = m_document.scene().fragments();
        const core::scene::FragmentId id = m_fragment();
        for (std::size_t i = 0; i < fragments.size(); ++i)
            if (fragments[i].id == id) current = i;
    }
    const cp::PlateSpec start = kept ? *kept : widgets::PlateDialog::defaultSpec(*sources, [this](const cp::PlateFragment& f) {
        for (const core::scene::Fragment& g : m_document.scene().fragments())
            if (g.octreePath == f.path) return m_document.octree(g.id);
        return std::shared_ptr<const core::octree::PackedOctree>();
    }, current);
    widgets::PlateDialog dialog(sources, cp::PlateSpec{}, &m_window);
    if (m_camera) dialog.setCurrentCamera(m_camera());
    dialog.setSpec(start);
    if (dialog.exec() != QDialog::Accepted) return;
    const cp::PlateSpec spec = dialog.spec();
    m_document.setPlate(spec);
    const QString path = QFileDialog::getSaveFileName(
        &m_window, tr("Export plate"), QString(),
        tr("PDF (*.pdf);;SVG (*.svg);;TIFF (*.tif *.tiff);;PNG (*.png)"));
    if (path.isEmpty()) return;
    exportPlate(spec, path);
}

void PlateActions::exportPlate(const cp::PlateSpec& spec, const QString& path)
{
    const auto sources = sourcesOf(m_document);
    struct Outcome {
        QString error;
        bool cancelled = false;
    };
    const QString name = QFileInfo(path).fileName();
    auto* watcher = m_document.tasks().start<Outcome>(
        tr("Drawing the plate %1").arg(name),
        [sources, spec, file = path.toStdString(), texts = widgets::PlateTexts::translated(sources->legend)](
            QPromise<Outcome>& promise, core::ProgressSink& progress) {
            Outcome out;
            // Drawing the panels, then writing the page (a large PDF takes seconds): the bar stops short of 100 %
            // until the file is in place.
            core::SubProgress drawing(&progress, 0.0, 0.9);
            auto plate = plate::composePlate(*sources, spec, {}, &drawing, texts);
            if (!plate) {
                out.error = QString::fromStdString(plate.error().message);
                out.cancelled = plate.error().code == core::ErrorCode::Cancelled;
            } else if (auto s = plate::writePlate(*plate, file, &progress); !s) {
                out.error = QString::fromStdString(s.error().message);
                out.cancelled = s.error().code == core::ErrorCode::Cancelled; // an existing file left as it was
            } else {
                progress.update(1.0);
            }
            promise.addResult(out);
        });
    connect(watcher, &QFutureWatcher<Outcome>::finished, this, [this, watcher, path] {
        if (watcher->isCanceled() || watcher->future().resultCount() == 0 || watcher->result().cancelled) {
            Q_EMIT reported(tr("Drawing the plate was cancelled"), false);
            Q_EMIT plateFinished(false);
            return;
        }
        const Outcome o = watcher->result();
        if (o.error.isEmpty()) Q_EMIT reported(tr("Wrote the plate %1").arg(QDir::toNativeSeparators(path)), false);
        else Q_EMIT reported(tr("Could not draw the plate: %1").arg(o.error), true);
        Q_EMIT plateFinished(o.error.isEmpty());
    });
}

void PlateActions::chooseViewImage()
{
    bool ok = false;
    const int width = QInputDialog::getInt(&m_window, tr("Export view image"),
                                           tr("Width in pixels (the whole image at most %L1 million pixels)")
                                               .arg(cp::PanelRenderOptions{}.maxPixels / 1000000),
                                           4000, 16, 100000, 100, &ok);
    if (!ok) return;
    const QString path = QFileDialog::getSaveFileName(&m_window, tr("Export view image"), QString(),
                                                      tr("PNG (*.png);;TIFF (*.tif *.tiff)"));
    if (!path.isEmpty()) exportViewImage(width, path);
}

void PlateActions::exportViewImage(int widthPx, const QString& path)
{
    const auto camera = m_camera ? m_camera() : std::nullopt;
    if (!camera) {
        Q_EMIT reported(tr("There is no 3D view to export"), true);
        Q_EMIT plateFinished(false);
        return;
    }
    cp::PanelSpec panel;
    panel.view = cp::PanelView::Camera;
    panel.camera = camera;
    panel.shading = cp::PanelShading::Skydome;
    const auto sources = sourcesOf(m_document);
    struct Outcome {
        QString error;
        bool cancelled = false;
    };
    auto* watcher = m_document.tasks().start<Outcome>(
        tr("Rendering the view %1").arg(QFileInfo(path).fileName()),
        [sources, panel, widthPx, file = path.toStdString()](QPromise<Outcome>& promise, core::ProgressSink& progress) mutable {
            Outcome out;
            auto image = cp::renderViewImage(*sources, panel, widthPx, {}, &progress);
            if (!image && image.error().message.find("\"ambient\"") != std::string::npos) {
                panel.shading = cp::PanelShading::Headlight; // not every octree has its skydome
                image = cp::renderViewImage(*sources, panel, widthPx, {}, &progress);
            }
            if (!image) {
                out.error = QString::fromStdString(image.error().message);
                out.cancelled = image.error().code == core::ErrorCode::Cancelled;
            } else if (auto s = plate::writePanelImage(image->image, file, 8, &progress); !s) {
                out.error = QString::fromStdString(s.error().message);
                out.cancelled = s.error().code == core::ErrorCode::Cancelled;
            }
            promise.addResult(out);
        });
    connect(watcher, &QFutureWatcher<Outcome>::finished, this, [this, watcher, path] {
        if (watcher->isCanceled() || watcher->future().resultCount() == 0 || watcher->result().cancelled) {
            Q_EMIT reported(tr("Rendering the view image %1 was cancelled").arg(QDir::toNativeSeparators(path)), false);
            Q_EMIT plateFinished(false);
            return;
        }
        const Outcome o = watcher->result();
        if (o.error.isEmpty()) Q_EMIT reported(tr("Wrote the view image %1").arg(QDir::toNativeSeparators(path)), false);
        else Q_EMIT reported(tr("Could not render the view image %1: %2").arg(QDir::toNativeSeparators(path), o.error), true);
        Q_EMIT plateFinished(o.error.isEmpty());
    });
}

void PlateActions::chooseDeveloppee()
{
    if (!m_view.hasDeveloppee()) {
        Q_EMIT reported(tr("There is no développée to export: compute one first (Tools › Développée)"), true);
        return;
    }
    const QString path = QFileDialog::getSaveFileName(&m_window, tr("Export développée image"), QString(),
                                                      tr("PNG (*.png);;TIFF (*.tif *.tiff)"));
    if (!path.isEmpty()) exportDeveloppee(path);
}

bool PlateActions::exportDeveloppee(const QString& path)
{
    if (!m_view.hasDeveloppee()) return false;
    const QImage image = m_view.image().convertToFormat(QImage::Format_ARGB32);
    core::shading::ShadedImage shaded;
    shaded.width = image.width();
    shaded.height = image.height();
    shaded.pixelSize = m_view.map()->pixelSize();
    shaded.values.resize(std::size_t(shaded.width) * std::size_t(shaded.height));
    shaded.coverage.resize(shaded.values.size());
    for (int y = 0; y < image.height(); ++y) {
        const QRgb* line = reinterpret_cast<const QRgb*>(image.constScanLine(y));
        for (int x = 0; x < image.width(); ++x) {
            const std::size_t k = std::size_t(y) * std::size_t(shaded.width) + std::size_t(x);
            shaded.coverage[k] = qAlpha(line[x]) > 0;
            shaded.values[k] = shaded.coverage[k] ? float(qGray(line[x])) / 255.0f : 0.0f;
        }
    }
    core::image::ImageWriteOptions options;
    options.metadata = {{"stylos:source", QFileInfo(path).fileName().toStdString()}};
    if (auto s = core::image::writeShadedImage(shaded, path.toStdString(), options); !s) {
        Q_EMIT reported(tr("Could not export the développée: %1").arg(QString::fromStdString(s.error().message)), true);
        return false;
    }
    if (auto s = m_view.map()->writeSidecar((path + QStringLiteral(".json")).toStdString()); !s) {
        Q_EMIT reported(tr("Could not write the développée's map: %1").arg(QString::fromStdString(s.error().message)), true);
        return false;
    }
    Q_EMIT reported(tr("Wrote the développée %1 and its map").arg(QDir::toNativeSeparators(path)), false);
    return true;
}

} // namespace stylos::app
