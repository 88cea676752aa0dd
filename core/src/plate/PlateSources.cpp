// What a plate is made from (a project, an octree or a point file), and each panel's picture.
#include "stylos/core/plate/PlateSources.h"
#include "stylos/core/util/TextCase.h"

#include "stylos/core/annotation/LabelRaster.h"
#include "stylos/core/annotation/LeafLabels.h"
#include "stylos/core/annotation/PixelLeafIndex.h"
#include "stylos/core/cloud/LoadPointCloud.h"
#include "stylos/core/developpee/Developpee.h"
#include "stylos/core/octree/OctreeBuild.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/plate/OrthoRender.h"
#include "stylos/core/scene/ProjectFile.h"
#include "stylos/core/scene/SceneEigen.h"
#include "stylos/core/util/SubProgress.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>
#include <thread>

namespace stylos::core::plate {

namespace {

namespace fs = std::filesystem;
namespace oct = octree;

/** The fragments a panel shows: the named one, or (empty name) the first (développée) / every visible one (3D). */
Result<std::vector<const PlateFragment*>> pick(const PlateSources& sources, const PanelSpec& panel)
{
    std::vector<const PlateFragment*> out;
    for (const PlateFragment& f : sources.fragments) {
        if (!panel.fragment.empty()) {
            if (f.name == panel.fragment) out.push_back(&f);
        } else if (f.visible || sources.fragments.size() == 1) {
            out.push_back(&f);
            if (panel.view == PanelView::Developpee) break;
        }
    }
    if (out.empty())
        return Error{ErrorCode::InvalidArgument,
                     panel.fragment.empty() ? sources.source + ": has no visible fragment to draw"
                                            : sources.source + ": no fragment is called \"" + panel.fragment + "\""};
    for (const PlateFragment* f : out)
        if (f->missing)
            return Error{ErrorCode::InvalidArgument, sources.source + ": the octree of fragment \"" + f->name + "\" (" +
                                                         f->path.string() + ") is missing"};
    return out;
}

/** The octree of @p f: its own, or one built from its point file into the scratch folder (once). */
Result<fs::path> octreeOf(const PlateFragment& f, const PanelRenderOptions& options, ProgressSink* progress)
{
    if (f.isOctree) return f.path;
    if (options.scratch.empty())
        return Error{ErrorCode::InvalidArgument, f.path.string() + ": a 3D panel of a point file needs a scratch folder"};
    const fs::path built = options.scratch / (f.path.stem().string() + ".poct");
    std::error_code error;
    if (fs::exists(built, error)) return built;
    oct::BuildOptions build;
    build.threads = options.threads > 0 ? options.threads : std::max(1u, std::thread::hardware_concurrency());
    auto report = oct::buildOctreeFile(f.path, built, build, progress);
    if (!report) return report.error();
    return built;
}


/** The fragment's labels of @p layer: those held in memory, else the octree's layer (zeros when absent). */
Result<std::vector<std::uint8_t>> labelsOf(const PlateFragment& f, const oct::PackedOctree& octree,
                                           annotation::AnnotationLayer layer)
{
    const auto& held = f.labels[layer == annotation::AnnotationLayer::Material ? 0 : 1];
    if (held) {
        if (held->size() != octree.cellCount(octree.depth()))
            return Error{ErrorCode::InvalidArgument, f.path.string() + ": the labels held for \"" + f.name +
                                                         "\" do not match its octree's leaves"};
        return *held;
    }
    return annotation::readLeafLabels(octree, layer);
}

Result<RenderedPanel> renderDeveloppee(const PlateSources& sources, const PlateFragment& f, const PanelSpec& panel,
                                       const PanelRenderOptions& options, ProgressSink* progress)
{
    developpee::DeveloppeeOptions d = f.unrolling.value_or(developpee::DeveloppeeOptions{});
    d.shading = panel.shading == PanelShading::Light    ? developpee::Shading::Light
                : panel.shading == PanelShading::Height ? developpee::Shading::Height
                                                        : developpee::Shading::Skydome;
    d.threads = options.threads;
    if (d.axis && !d.radius && f.drumGuides) {
        // The drum guides' leading radius and taper, fitted as the workbench fits them (DrumGuidesCache).
        SubProgress fitting(progress, 0.0, 0.2);
        cloud::CloudLoadOptions load;
        load.keepNormals = true;
        auto drum = cloud::loadPointCloud(f.drumGuides->octree, load, &fitting);
        if (!drum) return drum.error();
        drum->source = f.drumGuides->octree.string();
        dock::GuideOptions guideOptions = f.drumGuides->options;
        guideOptions.threads = options.threads;
        if (const auto guides = dock::fitDrumGuides(*drum, guideOptions)) {
            d.radius = guides->radius;
            d.radiusSlope = guides->slope;
        } else if (guides.error().code == ErrorCode::Cancelled) {
            return guides.error();
        }
    }
    SubProgress computing(progress, 0.2, 0.8);
    auto made = developpee::computeDeveloppee(f.path, d, &computing);
    if (!made) return made.error();
    const developpee::Developpee& dev = *made;
    GreyField field;
    field.width = dev.shaded.width;
    field.height = dev.shaded.height;
    field.values = dev.shaded.values;
    field.coverage = dev.shaded.coverage;
    if (panel.layer) {
        if (!f.isOctree)
            return Error{ErrorCode::InvalidArgument, f.path.string() + ": a point file has no annotation layers; draw the "
                                                                       "plate of its octree or of a project"};
        auto octree = oct::PackedOctree::open(f.path);
        if (!octree) return octree.error();
        auto labels = labelsOf(f, *octree, *panel.layer);
        if (!labels) return labels.error();
        // The classes of the surface the développée shows, as painting labels it (annotation::paintDepth).
        auto pixels = annotation::leafPixels(*octree, dev.map, nullptr, annotation::paintDepth(dev.map.pixelSize()));
        if (!pixels) return pixels.error();
        // Each pixel shows its leaves' class, a filled pixel its nearest leaves' (as the Développée dock shows them).
        auto index = annotation::PixelLeafIndex::build(*pixels, field.width, field.height);
        if (dev.field.states().size() == index.pixelCount()) index.lendLeaves(dev.field.states());
        field.classes = index.majorityLabels(*labels);
    }
    const double natural = dev.map.pixelSize();
    const double p = printPixelSize(panel.scale, options.dpi);
    // The whole turn (periodic across the seam), or a fragment's arc (UnrollOptions::cropToPoints).
    const bool wholeTurn = dev.unroll.arc >= 2.0 * std::numbers::pi;
    const double arcLength = dev.unroll.arc * dev.map.surface().referenceRadius(); // metres along the surface
    const double heightM = double(field.height) * natural;
    const double w = std::round(arcLength / p), h = std::round(heightM / p);
    if (w * h > double(options.maxPixels) || w > 1e6 || h > 1e6) {
        char text[220];
        std::snprintf(text, sizeof text, "%s: the développée at 1:%g and %d dpi would be %.0f × %.0f pixels (%.0f Mpx), over "
                      "the %.0f Mpx limit", f.path.string().c_str(), panel.scale, options.dpi, w, h, w * h / 1e6,
                      double(options.maxPixels) / 1e6);
        return Error{ErrorCode::OutOfBudget, text};
    }
    RenderedPanel out;
    out.image = resampleField(field, arcLength / natural, wholeTurn, std::max(1, int(w)), std::max(1, int(h)));
    out.image.pixelSizeM = p;
    out.pixelSizeM = p;
    out.naturalPixelM = natural;
    out.arcDegrees = wholeTurn ? 360.0 : dev.unroll.arc * 180.0 / std::numbers::pi;
    out.imageMm = {arcLength * 1000.0 / panel.scale, heightM * 1000.0 / panel.scale};
    if (panel.layer && !panel.hatches) tintByClass(out.image, sources.legend, *panel.layer);
    if (progress) progress->update(1.0);
    return out;
}

/** @p widthPx > 0: the pixel size that makes the frame that many pixels wide; else the plate's (1:N at D dpi). */
Result<RenderedPanel> render3d(const PlateSources& sources, const std::vector<const PlateFragment*>& fragments,
                               const PanelSpec& panel, const PanelRenderOptions& options, int widthPx,
                               ProgressSink* progress)
{
    std::vector<oct::PackedOctree> octrees;
    std::vector<OrthoSource> list;
    SubProgress building(progress, 0.0, 0.3);
    for (const PlateFragment* f : fragments) {
        auto path = octreeOf(*f, options, &building);
        if (!path) return path.error();
        auto octree = oct::PackedOctree::open(*path);
        if (!octree) return octree.error();
        octrees.push_back(std::move(octree).value());
    }
    for (std::size_t i = 0; i < fragments.size(); ++i) {
        OrthoSource s;
        s.octree = &octrees[i];
        s.pose = fragments[i]->pose;
        if (panel.layer) {
            auto labels = labelsOf(*fragments[i], octrees[i], *panel.layer);
            if (!labels) return labels.error();
            s.labels = std::move(labels).value();
        }
        list.push_back(std::move(s));
    }
    OrthoOptions o;
    o.orientation = panelOrientation(panel);
    o.pixelSizeM = printPixelSize(panel.scale, options.dpi);
    if (widthPx > 0) {
        o.pixelSizeM = 0.001;
        auto frame = measureOrtho(list, o);
        if (!frame) return frame.error();
        o.pixelSizeM = frame->extentM[0] / double(widthPx);
    }
    o.shading = panel.shading;
    o.keepClasses = panel.layer.has_value();
    o.maxPixels = options.maxPixels;
    SubProgress rendering(progress, 0.3, 1.0);
    auto rendered = renderOrtho(list, o, &rendering);
    if (!rendered) {
        Error e = rendered.error();
        if (e.code == ErrorCode::OutOfBudget || e.code == ErrorCode::InvalidArgument) e.message = sources.source + ": " + e.message;
        return e;
    }
    RenderedPanel out;
    out.image = std::move(rendered->image);
    out.pixelSizeM = o.pixelSizeM;
    out.leaves = rendered->leaves;
    out.imageMm = {rendered->extentM[0] * 1000.0 / panel.scale, rendered->extentM[1] * 1000.0 / panel.scale};
    if (panel.layer && !panel.hatches) tintByClass(out.image, sources.legend, *panel.layer);
    return out;
}

} // namespace

void unrollAsTheDock(PlateFragment& out, const scene::Scene& scene, scene::FragmentId fragment, scene::FragmentId drum)
{
    const auto axis = scene::unrollAxis(scene, fragment, drum);
    if (!axis) return;
    out.unrolling.emplace();
    out.unrolling->axis = unroll::Axis{axis->origin, axis->direction};
    const scene::Fragment* owner = scene.find(scene::unrollAxisOwner(scene, fragment, drum));
    if (const auto options = owner ? dock::guideOptionsFor(*owner) : std::nullopt)
        out.drumGuides = PlateFragment::DrumGuidesSource{owner->octreePath, *options};
}

Result<PlateSources> readPlateSources(const fs::path& path)
{
    PlateSources out;
    out.source = path.string();
    std::error_code error;
    if (!fs::exists(path, error)) return Error::at(ErrorCode::NotFound, path.string(), {}, "no such file");
    if (lowerExtension(path) == scene::ProjectExtension) {
        auto loaded = scene::ProjectFile::load(path);
        if (!loaded) return loaded.error();
        const scene::Scene& s = loaded->scene;
        out.isProject = true;
        out.legend = s.legend();
        for (const scene::Fragment& f : s.fragments()) {
            out.fragments.push_back({f.name, f.octreePath, true, f.octreeMissing, s.worldPose(f.id), f.visible, {}, {}, {}});
            unrollAsTheDock(out.fragments.back(), s, f.id, scene::drumFor(s, f.id)); // the saved docking drum too
        }
        if (out.fragments.empty()) return Error::at(ErrorCode::InvalidArgument, path.string(), {}, "the project has no fragment");
        return out;
    }
    const bool octree = cloud::isPoctPath(path);
    out.fragments.push_back({path.stem().string(), path, octree, false, scene::Pose(), true, {}, {}, {}});
    return out;
}

Result<RenderedPanel> renderPanel(const PlateSources& sources, const PanelSpec& panel, const PanelRenderOptions& options,
                                  ProgressSink* progress)
{
    auto fragments = pick(sources, panel);
    if (!fragments) return fragments.error();
    if (panel.view == PanelView::Developpee) return renderDeveloppee(sources, *fragments->front(), panel, options, progress);
    return render3d(sources, *fragments, panel, options, 0, progress);
}

Result<RenderedPanel> renderViewImage(const PlateSources& sources, const PanelSpec& panel, int widthPx,
                                      const PanelRenderOptions& options, ProgressSink* progress)
{
    if (panel.view == PanelView::Developpee)
        return Error{ErrorCode::InvalidArgument, "a view image is a 3D view, not a développée"};
    if (widthPx < 16 || widthPx > 100000) return Error{ErrorCode::InvalidArgument, "a view image is 16..100000 pixels wide"};
    auto fragments = pick(sources, panel);
    if (!fragments) return fragments.error();
    return render3d(sources, *fragments, panel, options, widthPx, progress);
}

} // namespace stylos::core::plate
