#include "stylos/core/synth/DemoProject.h"

#include "stylos/core/annotation/LeafLabels.h"
#include "stylos/core/ao/SkydomeLayer.h"
#include "stylos/core/io/PlyWriter.h"
#include "stylos/core/octree/OctreeBuild.h"
#include "stylos/core/scene/ProjectFile.h"
#include "stylos/core/synth/DrumShape.h"
#include "stylos/core/synth/FragmentShape.h"
#include "stylos/core/synth/OmphalosShape.h"
#include "stylos/core/synth/Random.h"
#include "stylos/core/synth/ScanSimulator.h"
#include "stylos/core/util/AtomicTextFile.h"
#include "stylos/core/util/ScratchFolder.h"
#include "stylos/core/util/SubProgress.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <limits>
#include <memory>
#include <numbers>

namespace stylos::core::synth {

namespace {

namespace fs = std::filesystem;
using scene::Pose;

constexpr double kPi = std::numbers::pi;
constexpr double kDegree = kPi / 180.0;

/** An item's synthetic object, in its own frame, and the azimuth the layout needs. */
struct DemoObject {
    std::unique_ptr<SyntheticObject> object;
    double azimuth = 0.0; ///< drum: centre of its broken region; fragment: centre of its sector (radians)
};

/** The same objects generateScan() makes for this kind, seed and design seed (same random draws, same order). */
DemoObject makeObject(SyntheticKind kind, const SyntheticOptions& options)
{
    Random random(options.seed);
    std::optional<Random> design;
    if (options.designSeed) design.emplace(*options.designSeed);
    Random& drumRandom = design ? *design : random;
    DemoObject made;
    switch (kind) {
    case SyntheticKind::Drum: {
        const DrumParameters drum = DrumParameters::fromOptions(options, drumRandom);
        made.azimuth = drum.brokenCentre;
        made.object = std::make_unique<DrumShape>(drum);
        break;
    }
    case SyntheticKind::Fragment: {
        const DrumParameters drum = DrumParameters::fromOptions(options, drumRandom);
        const FragmentParameters fragment = FragmentParameters::random(drum, random);
        made.azimuth = fragment.thetaCentre;
        made.object = std::make_unique<FragmentShape>(drum, fragment);
        break;
    }
    case SyntheticKind::Omphalos:
        made.object = std::make_unique<OmphalosShape>(OmphalosParameters::random(random));
        break;
    }
    return made;
}

/** Simulates the scans of @p object (object frame, true normals) into the PLY @p path. */
Result<std::uint64_t> simulateScan(const SyntheticObject& object, const SyntheticOptions& options, const fs::path& path,
                                   ProgressSink& progress)
{
    io::PointSchema schema;
    schema.hasNormals = true;
    schema.scalarNames = {"scan_id"};
    io::PlyWriterOptions plyOptions;
    plyOptions.scalarTypes = {io::PlyScalarType::UInt8};
    plyOptions.positionType = io::PlyScalarType::Float32; // object frame, metres: float is plenty
    auto writer = io::PlyWriter::create(path, schema, plyOptions);
    if (!writer) return writer.error();
    ScanSimulator simulator(object, options, Eigen::Affine3d::Identity(), options.seed);
    auto points = simulator.run(*writer, &progress);
    if (!points) return points.error();
    if (auto finished = writer->finish(); !finished) return finished.error();
    return points;
}

Pose rotation(double x, double y, double z)
{
    scene::TranslationAngles value;
    value.angles = {x, y, z};
    return Pose::fromTranslationAngles(value);
}

/** @p rotation with the translation that puts the octree's lowest leaf on z = 0 and the middle of its
 *  leaves' footprint at (@p x, @p y). */
Pose placeOnGround(const octree::PackedOctree& octree, const Pose& rotation, double x, double y)
{
    constexpr double inf = std::numeric_limits<double>::infinity();
    std::array<double, 3> lo{inf, inf, inf}, hi{-inf, -inf, -inf};
    octree.forEachCell(octree.depth(), [&](const octree::CellView& cell) {
        const std::array<double, 3> p = rotation.apply(cell.centre);
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], p[k]);
            hi[k] = std::max(hi[k], p[k]);
        }
        return true;
    });
    return rotation.withTranslation({x - 0.5 * (lo[0] + hi[0]), y - 0.5 * (lo[1] + hi[1]), -lo[2]});
}

/** Relative time each item takes (measured), to share the progress bar. */
double itemWeight(SyntheticKind kind)
{
    switch (kind) {
    case SyntheticKind::Drum: return 10.0;
    case SyntheticKind::Omphalos: return 8.4;
    case SyntheticKind::Fragment: return 1.6;
    }
    return 1.0;
}

void removeFiles(const std::vector<fs::path>& files)
{
    std::error_code ignored;
    for (const fs::path& file : files) fs::remove(file, ignored);
}

/**
 * The demo drum's annotation, drawn from its design so the workbench opens on a recorded drum: material —
 * fractured marble (2) over the broken region and a margin of 2°, 1 cm; plaster / restoration (3) on a patch
 * opposite it (±12°, 3–15 cm up); preserved marble (1) everywhere else — and tool marks — claw chisel (3) on the
 * claw band. Leaf centres are in the drum's own frame (axis +Z, bed at z = 0).
 */
Status annotateDemoDrum(const DrumParameters& p, const fs::path& octreePath)
{
    auto opened = octree::PackedOctree::open(octreePath);
    if (!opened) return opened.error();
    const std::uint64_t leaves = annotation::leafCount(*opened);
    std::vector<std::uint8_t> material(leaves, 1), toolmark(leaves, 0);
    auto angleFrom = [](double a, double centre) { return std::remainder(a - centre, 2.0 * kPi); };
    opened->forEachCell(opened->depth(), [&](const octree::CellView& c) {
        const double x = c.centre[0], y = c.centre[1], z = c.centre[2];
        const double r = std::hypot(x, y), theta = std::atan2(y, x);
        const bool lateral = r > p.radius - p.brokenDepth - 0.02 && z > 0.002 && z < p.height - 0.002;
        if (!lateral) return true;
        if (p.broken && std::abs(angleFrom(theta, p.brokenCentre)) < p.brokenHalfAngle + 2.0 * kDegree &&
            z > p.brokenZMin - 0.01 && z < p.brokenZMax + 0.01)
            material[c.index] = 2;
        else if (std::abs(angleFrom(theta, p.brokenCentre + kPi)) < 12.0 * kDegree && z > 0.03 && z < 0.15)
            material[c.index] = 3;
        if (p.clawBand && z >= p.clawMin && z <= p.clawMax) toolmark[c.index] = 3;
        return true;
    });
    std::vector<octree::AttributeLayer> layers{annotation::labelAttribute(annotation::AnnotationLayer::Material, material),
                                               annotation::labelAttribute(annotation::AnnotationLayer::Toolmark, toolmark)};
    if (auto written = annotation::writeAttributesPoct(*opened, std::move(layers), octreePath); !written)
        return written.error();
    return {};
}

} // namespace

int demoOctreeDepth(const SyntheticObject& object, double spacing)
{
    const double size = std::max(2.0 * object.extent(), object.height());
    return std::clamp(static_cast<int>(std::lround(std::log2(size / spacing))), 4, 14);
}

Pose demoLayout(std::size_t index, double azimuth, const octree::PackedOctree& octree)
{
    switch (index) {
    case 0: return rotation(0, 0, -100 * kDegree - azimuth);
    case 1: return placeOnGround(octree, rotation(0, 0, -65 * kDegree - azimuth), 1.15, -0.3);
    case 2: {
        // Sector centre to +x, then outward (+x) up (+z), then a turn about the vertical.
        const Pose lying = rotation(0, 0, 25 * kDegree) * rotation(0, -kPi / 2, 0) * rotation(0, 0, -azimuth);
        return placeOnGround(octree, lying, 1.2, 0.55);
    }
    default: return Pose::translation({-1.4, 0.1, 0.0});
    }
}

std::optional<DemoFailure> generateDemoProject(const DemoRequest& request, ProgressSink& progress)
{
    const fs::path& folder = request.folder;
    std::vector<fs::path> written; // removed again unless the project is written
    const auto fail = [&](Error error, const std::string& file) {
        removeFiles(written);
        return DemoFailure{std::move(error), file};
    };
    const auto cancelled = [&](const std::string& file) {
        return fail(Error::at(ErrorCode::Cancelled, folder.string(), {}, "cancelled"), file);
    };
    ScratchFolder scratch;
    if (auto s = scratch.create(folder / "demo", "scans"); !s) return fail(s.error(), folder.string());

    double total = 0.0;
    for (const DemoItem& item : request.items) total += itemWeight(item.kind);
    double done = 0.0;
    scene::Scene project;
    const auto drumIt = std::find_if(request.items.begin(), request.items.end(),
                                     [](const DemoItem& item) { return item.kind == SyntheticKind::Drum; });
    const DemoItem* drumItem = drumIt != request.items.end() ? &*drumIt : nullptr;
    scene::FragmentId drumId = scene::NoFragment, firstFragmentId = scene::NoFragment;
    for (std::size_t i = 0; i < request.items.size(); ++i) {
        const DemoItem& item = request.items[i];
        const double from = done / total, share = itemWeight(item.kind) / total;
        done += itemWeight(item.kind);
        const auto step = [&](double a, double b) { return SubProgress(&progress, from + a * share, from + b * share); };
        const fs::path ply = scratch.path() / (item.fileName + ".ply");
        const fs::path built = scratch.path() / item.fileName;
        const fs::path output = folder / item.fileName;

        SyntheticOptions options;
        options.spacing = request.spacing;
        options.seed = item.seed;
        options.writeNormals = true;
        // The fragments come from the demo's drum design, so they dock against its flutes.
        if (item.kind == SyntheticKind::Fragment && drumItem) options.designSeed = drumItem->seed;
        const DemoObject made = makeObject(item.kind, options);
        {
            SubProgress sink = step(0.0, 0.5);
            if (auto scanned = simulateScan(*made.object, options, ply, sink); !scanned)
                return fail(scanned.error(), item.fileName);
        }
        octree::BuildOptions build;
        build.depth = demoOctreeDepth(*made.object, request.spacing);
        {
            SubProgress sink = step(0.5, 0.8);
            auto report = octree::buildOctreeFile(ply, built, build, &sink);
            std::error_code ignored;
            fs::remove(ply, ignored);
            if (!report) return fail(report.error(), item.fileName);
        }
        auto opened = octree::PackedOctree::open(built);
        if (!opened) return fail(opened.error(), item.fileName);

        // The 3D skydome at the level where the cells still close the surface, spread to the leaves.
        ao::SkydomeLayerOptions sky;
        sky.ao.directions = request.skyDirections;
        {
            SubProgress sink = step(0.8, 1.0);
            written.push_back(output);
            if (auto stored = ao::computeSkydomeLayer(*opened, output, sky, &sink); !stored)
                return fail(stored.error(), item.fileName);
        }

        if (item.kind == SyntheticKind::Drum)
            if (auto s = annotateDemoDrum(static_cast<const DrumShape&>(*made.object).parameters(), output); !s)
                return fail(s.error(), item.fileName);

        scene::Fragment fragment;
        fragment.name = item.name;
        fragment.octreePath = output;
        fragment.pose = demoLayout(i, made.azimuth, *opened);
        fragment.colour = scene::defaultFragmentColour(i);
        if (item.kind == SyntheticKind::Drum) {
            // The drum's guides as designed: its axis, and each flute's bottom line (a fragment is docked
            // against them; `stylos-cli guides` or "Fit drum guides" find the same from the points).
            fragment.guides.push_back({request.axisName, scene::GuideKind::Axis, {0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}});
            const DrumParameters& p = static_cast<const DrumShape&>(*made.object).parameters();
            for (int k = 0; k < p.grooves; ++k) {
                const double a = p.groovePhase + k * 2.0 * kPi / p.grooves, bottom = p.radius - p.grooveDepth;
                fragment.guides.push_back({request.fluteName + " " + std::to_string(k + 1), scene::GuideKind::Groove,
                                           {bottom * std::cos(a), bottom * std::sin(a), 0.0}, {0.0, 0.0, 1.0}});
            }
        }
        const scene::FragmentId added = project.add(std::move(fragment));
        if (item.kind == SyntheticKind::Drum && drumId == scene::NoFragment) drumId = added;
        if (item.kind == SyntheticKind::Fragment && firstFragmentId == scene::NoFragment) firstFragmentId = added;
        if (progress.isCancelRequested()) return cancelled(item.fileName);
    }
    // The first fragment in an assembly docking against the drum: ready for the Move tool's drum frame and
    // Dock to flutes. Its frame is the fragment's, so the fragment stays where the layout put it.
    if (drumId != scene::NoFragment && firstFragmentId != scene::NoFragment && !request.assemblyName.empty()) {
        scene::Assembly assembly;
        assembly.name = request.assemblyName;
        assembly.pose = project.worldPose(firstFragmentId);
        assembly.drum = drumId;
        project.moveToAssembly(firstFragmentId, project.addAssembly(assembly));
    }

    // The stamp, then the project: the project file's existence is what makes the folder complete.
    const fs::path stampPath = folder / "demo.version";
    const fs::path projectPath = folder / "demo.stylos";
    written.push_back(stampPath);
    if (auto s = writeTextFileAtomically(stampPath, request.stamp); !s) return fail(s.error(), "demo.version");
    if (progress.isCancelRequested()) return cancelled({});
    if (auto s = scene::ProjectFile::save(project, projectPath); !s) return fail(s.error(), "demo.stylos");
    progress.update(1.0);
    return std::nullopt;
}

} // namespace stylos::core::synth
