// stylos_ao_truth: the 3D skydome of a generated scan against the ANALYTIC reference — the visible sky of
// true surface points over their true normals, rays marched against the exact solid (synth/
// AnalyticSkydome.h) — per point and per part of the shape (issue 17, docs/benchmarks.md).
//
//   stylos_ao_truth [--kind drum|fragment] [--spacing M] [--noise M] [--seed K] [--depth D] [--level L]
//                   [--directions N] [--method depthmap|slices] [--bias B] [--points P] [--point-seed S]
//                   [--threads T] [--step M] [--dir WORK] [--csv OUT.csv] [--receivers leaves|cells]
//                   [--one-sided] [--smoothing S] [--pcv OUT_PCV.ply] [--discs J [--disc-normals true|estimated]]
//   - The scan: generateScan(kind, spacing (default 2 mm), noise (0.33 mm), seed (1)), random pose, as
//     `stylos-cli generate` writes it; its octree as `stylos-cli ao` builds it (depth 12, normals
//     estimated); both cached in WORK (default /tmp/stylos-ao-truth).
//   - The method: computeLeafSkydome (what `stylos-cli ao` writes: level L, default the closed-surface
//     level), timed; --one-sided: leaves measured on their normal's side only (before AoOptions::twoSided);
//     --smoothing S: SkydomeLayerOptions::smoothing (default 1.5 cell edges of the level; 0: the raw values).
//   - P true surface points (default 2000, seed S): a patch by area, a uniform (a, b) on it, its position
//     and normal without noise. Each point's analytic value over the method's directions (turned into
//     the object frame) and the value of the leaf nearest to the posed point; also the cell reference
//     (ReferenceAo: DDA rays against the level's occupied cells) of the level-L cell holding that leaf.
//   - Parts (object frame; "a few cells" = 3 level-L edges): bed faces away from edges, bed faces near an
//     edge, flute bottoms (|φ| < half width / 2), flute walls, fillets (|φ| > half width), the claw band,
//     the broken cavity's core (q < 0.5), the fracture faces (fragment), other (near a bed, the cavity's rim).
//   - --discs J: what the samples themselves can tell — each true point's sky ray-cast against the scan's
//     POINTS as discs (ao/DiscSkydome.h; centres projected onto the plane of their J nearest, 0 = raw),
//     from the posed true point along its true normal (one-sided), discs within 2 spacings skipped: no
//     cells. --disc-normals estimated: along the nearest disc's estimated normal instead (PCA, k = 16,
//     as the octree's), what the samples tell of the orientation. Relief finer than the sampling, or
//     under the noise, is lost to any method that works from these samples; the two runs show how much
//     of what remains is the occluders' and how much the receivers' normals.
//   - --pcv: CloudCompare's PCV output of the very same scan (the PLY above: `stylos-cli generate KIND
//     --spacing M --noise M --seed K` writes it byte for byte; scripts/bench-pcv-truth.sh runs it): its
//     point count must be the scan's; each posed true point takes the value of the nearest PCV point
//     (within 4 spacings), compared with the same analytic truth, overall and per part, in PCV's
//     definition (visible / all directions of the sphere, no normals: the truth and the method times
//     F(n), the share of the directions in front of the true normal; on a closed solid the back half sees
//     nothing) and in ours (PCV ÷ F(n), at most 1, against the truth; "pcvUnclipped" without the bound,
//     where PCV leaks through a sparse cloud; the method as above). PcvCloud.h.
// One JSON document goes to stdout; progress to stderr.
#include "stylos/core/ao/AoCells.h"
#include "stylos/core/ao/Directions.h"
#include "stylos/core/ao/DiscSkydome.h"
#include "stylos/core/cloud/LoadPointCloud.h"
#include "stylos/core/ao/ReferenceAo.h"
#include "stylos/core/ao/SkydomeLayer.h"
#include "stylos/core/io/PointFileFormat.h"
#include "stylos/core/io/PointReader.h"
#include "stylos/core/octree/OctreeBuild.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/synth/AnalyticSkydome.h"
#include "stylos/core/synth/DrumShape.h"
#include "stylos/core/synth/FragmentShape.h"
#include "stylos/core/synth/SyntheticScan.h"

#include "BenchmarkClock.h"
#include "LeafGrid.h"
#include "PcvCloud.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <numbers>
#include <numeric>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <unordered_map>
#include <vector>

namespace fs = std::filesystem;
namespace ao = stylos::core::ao;
namespace oct = stylos::core::octree;
namespace synth = stylos::core::synth;
using nlohmann::json;

namespace {

struct Settings {
    synth::SyntheticKind kind = synth::SyntheticKind::Drum;
    std::string kindName = "drum";
    synth::SyntheticOptions scan;
    int depth = 12;
    int level = -1;
    ao::AoOptions ao;
    std::size_t points = 2000;
    std::uint64_t pointSeed = 7;
    unsigned threads = 2;
    double step = 1e-4;
    fs::path dir = "/tmp/stylos-ao-truth";
    fs::path csv;
    fs::path pcv;
    std::optional<bool> leafReceivers; ///< default: computeLeafSkydome's
    std::optional<double> smoothing;   ///< default: computeLeafSkydome's
    std::optional<std::size_t> discs;  ///< --discs J: the disc reference, J projection neighbours
    bool discNormalsEstimated = false; ///< --disc-normals estimated: the nearest disc's normal, not the true one
};

[[noreturn]] void fail(const std::string& message)
{
    std::cerr << "stylos_ao_truth: " << message << "\n";
    std::exit(1);
}

using stylos::bench::loadAverage;
using stylos::bench::now;

Settings parse(int argc, char** argv)
{
    Settings s;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() -> std::string {
            if (i + 1 >= argc) fail(a + " needs a value");
            return argv[++i];
        };
        if (a == "--kind") {
            s.kindName = next();
            const auto k = synth::syntheticKindFromName(s.kindName);
            if (!k || *k == synth::SyntheticKind::Omphalos) fail("--kind must be drum or fragment");
            s.kind = *k;
        } else if (a == "--spacing") s.scan.spacing = std::stod(next());
        else if (a == "--noise") s.scan.noise = std::stod(next());
        else if (a == "--seed") s.scan.seed = std::stoull(next());
        else if (a == "--depth") s.depth = std::stoi(next());
        else if (a == "--level") s.level = std::stoi(next());
        else if (a == "--directions") s.ao.directions = std::stoi(next());
        else if (a == "--bias") s.ao.bias = s.ao.receiverBias = std::stod(next());
        else if (a == "--method") {
            const auto m = ao::aoMethodFromName(next());
            if (!m) fail("unknown method");
            s.ao.method = *m;
        } else if (a == "--points") s.points = std::stoull(next());
        else if (a == "--point-seed") s.pointSeed = std::stoull(next());
        else if (a == "--threads") s.threads = unsigned(std::stoul(next()));
        else if (a == "--step") s.step = std::stod(next());
        else if (a == "--dir") s.dir = next();
        else if (a == "--csv") s.csv = next();
        else if (a == "--one-sided") s.ao.twoSided = false;
        else if (a == "--smoothing") s.smoothing = std::stod(next());
        else if (a == "--discs") s.discs = std::stoul(next());
        else if (a == "--disc-normals") {
            const std::string v = next();
            if (v != "true" && v != "estimated") fail("--disc-normals must be true or estimated");
            s.discNormalsEstimated = v == "estimated";
        }
        else if (a == "--pcv") s.pcv = next();
        else if (a == "--receivers") {
            const std::string r = next();
            if (r != "leaves" && r != "cells") fail("--receivers must be leaves or cells");
            s.leafReceivers = r == "leaves";
        }
        else fail("unknown option " + a + " (see the source's header)");
    }
    s.ao.threads = s.threads;
    if (s.discNormalsEstimated && !s.discs) fail("--disc-normals needs --discs J");
    return s;
}

/** Pearson's r and the mean absolute error of @p a against the truth @p b, and both sides' statistics. */
json agreement(const std::vector<double>& a, const std::vector<double>& b)
{
    const std::size_t n = a.size();
    if (n == 0) return json{{"n", 0}};
    double ma = 0, mb = 0, mae = 0, bias = 0;
    for (std::size_t i = 0; i < n; ++i) ma += a[i], mb += b[i], mae += std::fabs(a[i] - b[i]), bias += a[i] - b[i];
    ma /= double(n);
    mb /= double(n);
    double sab = 0, saa = 0, sbb = 0;
    for (std::size_t i = 0; i < n; ++i) {
        sab += (a[i] - ma) * (b[i] - mb);
        saa += (a[i] - ma) * (a[i] - ma);
        sbb += (b[i] - mb) * (b[i] - mb);
    }
    const double r = saa > 0 && sbb > 0 ? sab / std::sqrt(saa * sbb) : 0.0;
    return json{{"n", n},
                {"r", r},
                {"mae", mae / double(n)},
                {"mean", ma},
                {"truthMean", mb},
                {"sd", std::sqrt(saa / double(n))},
                {"truthSd", std::sqrt(sbb / double(n))}};
}

json lowTail(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    if (v.empty()) return json{};
    auto at = [&](double q) { return v[std::min(v.size() - 1, std::size_t(q * double(v.size())))]; };
    const auto below = std::count_if(v.begin(), v.end(), [](double x) { return x < 0.95; });
    return json{{"min", v.front()}, {"p1", at(0.01)}, {"p5", at(0.05)}, {"p50", at(0.5)},
                {"below0.95", double(below) / double(v.size())}};
}

// ---------------------------------------------------------------------------------------------------
// True surface points.

struct TruePoint {
    Eigen::Vector3d p, n; ///< object frame
    std::string part;
};

/** The drum a part is classified against: the object itself or the fragment's parent. */
const synth::DrumShape& drumOf(const synth::SyntheticObject& object)
{
    if (const auto* f = dynamic_cast<const synth::FragmentShape*>(&object)) return f->drum();
    return dynamic_cast<const synth::DrumShape&>(object);
}

std::string classify(const synth::SyntheticObject& object, std::size_t patch, const Eigen::Vector3d& p, double cell)
{
    const synth::DrumShape& drum = drumOf(object);
    const auto& d = drum.parameters();
    const auto* fragment = dynamic_cast<const synth::FragmentShape*>(&object);
    const double rho = std::hypot(p.x(), p.y()), theta = std::atan2(p.y(), p.x()), margin = 3.0 * cell;
    // Distance to the fragment's fracture faces' nominal surfaces (infinite for a drum).
    double fractureDistance = 1e9;
    if (fragment) {
        const auto& f = fragment->parameters();
        const double dTheta = synth::wrapAngle(theta - f.thetaCentre);
        fractureDistance = std::min({(f.halfAngle - std::fabs(dTheta)) * rho, rho - fragment->innerRadius(),
                                     p.z() - f.zMin}) - fragment->fractureBound();
    }
    const bool lateral = patch == 0;
    const bool bed = patch == 1 || (patch == 2 && !fragment);
    if (!lateral && !bed) return "fracture";
    if (bed) {
        const bool nearEdge = rho > d.radius - drum.maxLateralDepth() - margin || fractureDistance < margin;
        return nearEdge ? "bedNearEdge" : "bed";
    }
    if (p.z() < margin || p.z() > d.height - margin || fractureDistance < margin) return "other";
    if (d.broken) {
        const double qa = synth::wrapAngle(theta - d.brokenCentre) / d.brokenHalfAngle;
        const double qz = (p.z() - 0.5 * (d.brokenZMin + d.brokenZMax)) / (0.5 * (d.brokenZMax - d.brokenZMin));
        const double q = qa * qa + qz * qz;
        if (q < 0.5) return "cavity";
        if (q < 1.5) return "other";
    }
    if (d.clawBand && p.z() > d.clawMin - margin && p.z() < d.clawMax + margin) return "claw";
    if (d.grooves == 0) return "fillet";
    const double pitch = 2.0 * std::numbers::pi / d.grooves;
    const double halfWidth = 0.5 * pitch * (1.0 - d.filletFraction);
    const double phi = std::fabs(std::remainder(theta - d.groovePhase, pitch));
    return phi < 0.5 * halfWidth ? "flute" : phi > halfWidth ? "fillet" : "wall";
}

std::vector<TruePoint> sampleSurface(const synth::SyntheticObject& object, std::size_t count, std::uint64_t seed,
                                     double cell)
{
    const auto patches = object.patches();
    // Area of each patch ≈ ∫ |columns(b)| db (a and b are about arc lengths), and the longest row.
    std::vector<double> area(patches.size()), longest(patches.size());
    for (std::size_t k = 0; k < patches.size(); ++k) {
        const auto rows = patches[k]->rows();
        constexpr int kRows = 400;
        for (int i = 0; i < kRows; ++i) {
            const double len = patches[k]->columns(rows.min + (i + 0.5) * rows.length() / kRows).length();
            area[k] += len * rows.length() / kRows;
            longest[k] = std::max(longest[k], len);
        }
    }
    std::mt19937_64 random(seed);
    std::discrete_distribution<std::size_t> pick(area.begin(), area.end());
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<TruePoint> out;
    while (out.size() < count) {
        const std::size_t k = pick(random);
        const auto* patch = patches[k];
        const auto rows = patch->rows();
        const double b = rows.min + unit(random) * rows.length();
        const auto columns = patch->columns(b);
        if (unit(random) * longest[k] > columns.length()) continue; // rows weighted by their length
        const double a = columns.min + unit(random) * columns.length();
        const Eigen::Vector3d p = patch->position(a, b);
        if (!patch->contains(a, b, p)) continue;
        out.push_back({p, patch->normal(a, b).normalized(), classify(object, k, p, cell)});
    }
    return out;
}

using stylos::bench::LeafGrid;

/** The level-L cell holding each leaf (cells' leaf ranges are consecutive and sorted). */
std::size_t cellOfLeaf(const ao::AoCells& cells, std::uint64_t leaf)
{
    return std::size_t(std::upper_bound(cells.leafBegin.begin(), cells.leafBegin.end(), leaf) - cells.leafBegin.begin()) - 1;
}

/** CloudCompare's output of @p ply (refused, before any work, when its point count is not the scan's). */
stylos::bench::PcvCloud readPcvOf(const fs::path& pcvPath, const fs::path& ply)
{
    auto read = stylos::bench::readPcvCloud(pcvPath);
    if (!read) fail(read.error().message);
    auto scan = stylos::core::io::openPointReader(ply);
    if (!scan) fail(scan.error().message);
    const auto scanPoints = scan.value()->header().declaredPoints.value_or(0);
    if (read->positions.size() != scanPoints)
        fail(pcvPath.string() + ": " + std::to_string(read->positions.size()) + " points, the scan " + ply.string() +
             " has " + std::to_string(scanPoints) + ": not CloudCompare's output of this scan");
    return std::move(read).value();
}

/**
 * CloudCompare's PCV at the true points (the nearest PCV point to each posed one) against the analytic
 * truth, per part, in PCV's definition and in ours, beside the method in both; @p points in the object
 * frame, @p directions the method's turned into it.
 */
json pcvReport(const Settings& s, const stylos::bench::PcvCloud& pcv, const std::vector<TruePoint>& points,
               const Eigen::Affine3d& pose, const std::vector<std::array<double, 3>>& directions,
               const std::vector<double>& truth, const std::vector<double>& method)
{
    const double radius = 4.0 * s.scan.spacing;
    const stylos::bench::PointGrid grid(pcv.positions, radius);
    std::vector<double> value(points.size()), distance(points.size()), front(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        const Eigen::Vector3d q = pose * points[i].p;
        const std::size_t k = grid.nearest(q);
        if (k == SIZE_MAX)
            fail(s.pcv.string() + ": no point within " + std::to_string(radius) + " m of a true point: not this scan");
        const auto& c = pcv.positions[k];
        distance[i] = (Eigen::Vector3d(c[0], c[1], c[2]) - q).norm();
        value[i] = pcv.values[k];
        const Eigen::Vector3d& n = points[i].n;
        front[i] = stylos::bench::frontFraction(directions, {float(n.x()), float(n.y()), float(n.z())});
    }
    std::vector<double> sortedDistance = distance, all = pcv.values;
    std::sort(sortedDistance.begin(), sortedDistance.end());
    std::sort(all.begin(), all.end());
    const auto at = [&](double q) { return all[std::min(all.size() - 1, std::size_t(q * double(all.size())))]; };
    json out{{"file", s.pcv.string()}, {"field", pcv.field}, {"points", pcv.positions.size()},
             {"matchRadius", radius}, {"pointDistanceMedian", sortedDistance[sortedDistance.size() / 2]},
             {"pointDistanceMax", sortedDistance.back()},
             {"percentiles", {{"5", at(0.05)}, {"50", at(0.5)}, {"95", at(0.95)}}}};
    std::map<std::string, std::vector<std::size_t>> parts;
    for (std::size_t i = 0; i < points.size(); ++i) parts[points[i].part].push_back(i), parts["all"].push_back(i);
    for (const auto& [part, ids] : parts) {
        std::vector<double> pcvOwn, pcvOurs, pcvRatio, truthOwn, truthOurs, methodOwn, methodOurs, f;
        for (const std::size_t i : ids) {
            pcvOwn.push_back(value[i]);
            pcvRatio.push_back(front[i] > 0 ? value[i] / front[i] : 0.0);
            pcvOurs.push_back(std::min(1.0, pcvRatio.back()));
            truthOwn.push_back(truth[i] * front[i]);
            truthOurs.push_back(truth[i]);
            methodOwn.push_back(method[i] * front[i]);
            methodOurs.push_back(method[i]);
            f.push_back(front[i]);
        }
        json& o = out["parts"][part];
        o["pcvDefinition"]["pcv"] = agreement(pcvOwn, truthOwn);
        o["pcvDefinition"]["method"] = agreement(methodOwn, truthOwn);
        o["stylosDefinition"]["pcv"] = agreement(pcvOurs, truthOurs);
        o["stylosDefinition"]["pcvUnclipped"] = agreement(pcvRatio, truthOurs); // PCV leaks: above 1
        o["stylosDefinition"]["method"] = agreement(methodOurs, truthOurs);
        o["meanFrontFraction"] = std::accumulate(f.begin(), f.end(), 0.0) / double(f.size());
    }
    const auto meanOf = [&](const char* part) {
        return out["parts"].contains(part) ? out["parts"][part]["stylosDefinition"]["pcvUnclipped"]["mean"].get<double>() : -1.0;
    };
    out["flutesDarkerThanFillets"] = meanOf("flute") < meanOf("fillet");
    return out;
}

/** --discs: the sky of each posed true point against the scan's points as discs (see the header). */
std::vector<double> discReference(const fs::path& ply, const Settings& s, const std::vector<TruePoint>& points,
                                  const Eigen::Affine3d& pose, std::size_t projection)
{
    auto cloud = stylos::core::cloud::loadPointCloud(ply);
    if (!cloud) fail(cloud.error().message);
    std::vector<double> xyz(3 * cloud->size());
    for (std::size_t i = 0; i < cloud->size(); ++i) {
        const Eigen::Vector3d w = cloud->world(i);
        for (int a = 0; a < 3; ++a) xyz[3 * i + std::size_t(a)] = w[a];
    }
    ao::DiscCloudOptions options;
    options.threads = s.threads;
    options.projectionNeighbours = projection;
    auto discs = ao::discsFromPoints(xyz, options);
    if (!discs) fail(discs.error().message);
    const ao::DiscGrid grid(*discs);
    const stylos::bench::PointGrid nearest(discs->centres, 4.0 * s.scan.spacing);
    std::vector<std::array<double, 3>> directions;
    for (const auto& d : ao::fibonacciDirections(s.ao.directions, s.ao.upperHemisphere)) directions.push_back({d[0], d[1], d[2]});
    std::vector<double> values(points.size());
    std::vector<std::thread> workers;
    const unsigned threads = std::max(1u, s.threads);
    for (unsigned w = 0; w < threads; ++w)
        workers.emplace_back([&, w] {
            for (std::size_t i = w; i < points.size(); i += threads) {
                const Eigen::Vector3d q = pose * points[i].p;
                Eigen::Vector3d n = pose.linear() * points[i].n;
                if (s.discNormalsEstimated) { // the nearest disc's estimated normal, on the true normal's side
                    const std::size_t k = nearest.nearest(q);
                    if (k == SIZE_MAX) fail("no disc near a true point");
                    const Eigen::Vector3d e(discs->normals[k][0], discs->normals[k][1], discs->normals[k][2]);
                    n = e.dot(n) < 0 ? Eigen::Vector3d(-e) : e;
                }
                values[i] = ao::discSkydome(grid, {q.x(), q.y(), q.z()}, {n.x(), n.y(), n.z()}, directions,
                                            2.0 * s.scan.spacing, false);
            }
        });
    for (auto& t : workers) t.join();
    return values;
}

} // namespace

int main(int argc, char** argv)
{
    const Settings s = parse(argc, argv);
    json out;
    out["loadBefore"] = loadAverage();
    fs::create_directories(s.dir);
    std::ostringstream stem;
    stem << s.kindName << "-s" << s.scan.spacing * 1000 << "mm-n" << s.scan.noise * 1000 << "mm-seed" << s.scan.seed;
    const fs::path ply = s.dir / (stem.str() + ".ply");
    const fs::path poct = s.dir / (stem.str() + "-d" + std::to_string(s.depth) + ".poct");
    if (!fs::exists(ply)) {
        std::cerr << "generating " << ply << "...\n";
        auto made = synth::generateScan(s.kind, s.scan, ply);
        if (!made) fail(made.error().message);
    }
    std::optional<stylos::bench::PcvCloud> pcv;
    if (!s.pcv.empty()) pcv = readPcvOf(s.pcv, ply);
    if (!fs::exists(poct)) {
        std::cerr << "building " << poct << "...\n";
        oct::BuildOptions build;
        build.depth = s.depth;
        auto built = oct::buildOctreeFile(ply.string(), poct, build);
        if (!built) fail(built.error().message);
    }
    auto opened = oct::PackedOctree::open(poct);
    if (!opened) fail(opened.error().message);
    const oct::PackedOctree& octree = opened.value();

    // The method, as stylos-cli ao runs it.
    ao::SkydomeLayerOptions layer;
    layer.ao = s.ao;
    if (s.level >= 0) layer.level = s.level;
    if (s.leafReceivers) layer.leafReceivers = *s.leafReceivers;
    if (s.smoothing) layer.smoothing = *s.smoothing;
    ao::SkydomeLayerReport report;
    double start = now();
    auto values = ao::computeLeafSkydome(octree, layer, nullptr, &report);
    if (!values) fail(values.error().message);
    const double methodSeconds = now() - start;
    std::cerr << "method: level " << report.level << ", " << report.cells << " cells, " << report.leaves
              << " leaves, " << methodSeconds << " s\n";
    auto cellsResult = ao::cellsAtLevel(octree, report.level);
    auto leavesResult = ao::cellsAtLevel(octree, octree.depth());
    if (!cellsResult || !leavesResult) fail("cannot read the cells");
    const ao::AoCells& cells = *cellsResult;
    const ao::AoCells& leaves = *leavesResult;

    // True points, their analytic values, their leaves.
    const auto object = synth::makeSyntheticObject(s.kind, s.scan);
    const Eigen::Affine3d pose = synth::syntheticPose(s.scan);
    const auto solid = synth::analyticSolid(*object);
    const auto points = sampleSurface(*object, s.points, s.pointSeed, cells.edge);
    std::vector<std::array<double, 3>> directions;
    for (const auto& d : ao::fibonacciDirections(s.ao.directions, s.ao.upperHemisphere)) {
        const Eigen::Vector3d local = pose.linear().transpose() * Eigen::Vector3d(d[0], d[1], d[2]);
        directions.push_back({local.x(), local.y(), local.z()});
    }
    start = now();
    std::vector<double> truth(points.size());
    {
        synth::AnalyticSkydomeOptions options;
        options.step = s.step;
        std::vector<std::thread> workers;
        for (unsigned w = 0; w < std::max(1u, s.threads); ++w)
            workers.emplace_back([&, w] {
                for (std::size_t i = w; i < points.size(); i += std::max(1u, s.threads))
                    truth[i] = synth::analyticSkydome(*solid, points[i].p, points[i].n, directions, options).value();
            });
        for (auto& t : workers) t.join();
    }
    const double analyticSeconds = now() - start;
    std::cerr << "analytic reference on " << points.size() << " points: " << analyticSeconds << " s\n";

    const LeafGrid grid(leaves, std::max(4.0 * s.scan.spacing, 2.0 * cells.edge));
    std::vector<double> method(points.size()), distance(points.size());
    std::vector<std::size_t> cellIds(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        const Eigen::Vector3d q = pose * points[i].p;
        const std::size_t leaf = grid.nearest(q);
        if (leaf == SIZE_MAX) fail("no leaf near a true point: the octree is not of this scan");
        const auto c = leaves.centre(leaf);
        distance[i] = (Eigen::Vector3d(c[0], c[1], c[2]) - q).norm();
        method[i] = (*values)[leaf];
        cellIds[i] = cellOfLeaf(cells, leaf);
    }
    start = now();
    auto cellRef = ao::referenceAmbientOcclusion(cells, cellIds, s.ao);
    if (!cellRef) fail(cellRef.error().message);
    const double referenceSeconds = now() - start;

    out["scan"] = {{"kind", s.kindName}, {"file", ply.string()}, {"spacing", s.scan.spacing},
                   {"noise", s.scan.noise}, {"seed", s.scan.seed}, {"depth", octree.depth()}};
    out["method"] = {{"name", ao::aoMethodName(s.ao.method)}, {"level", report.level}, {"cells", report.cells},
                     {"edgeMetres", cells.edge}, {"leaves", report.leaves}, {"bias", layer.leafReceivers ? s.ao.receiverBias : s.ao.bias},
                     {"directions", s.ao.directions}, {"seconds", methodSeconds},
                     {"receivers", layer.leafReceivers && s.ao.method == ao::AoMethod::DepthMap ? "leaves" : "cells"},
                     {"skydomeSeconds", report.aoSeconds}, {"twoSided", s.ao.twoSided},
                     {"smoothingRadius", report.smoothingRadius}, {"smoothingSeconds", report.smoothSeconds}};
    out["points"] = {{"count", points.size()}, {"seed", s.pointSeed}, {"analyticSeconds", analyticSeconds},
                     {"cellReferenceSeconds", referenceSeconds}, {"step", s.step}};
    std::vector<double> sortedDistance = distance;
    std::sort(sortedDistance.begin(), sortedDistance.end());
    out["points"]["leafDistanceMedian"] = sortedDistance[sortedDistance.size() / 2];
    out["points"]["leafDistanceMax"] = sortedDistance.back();

    std::vector<double> discValues;
    if (s.discs) {
        start = now();
        discValues = discReference(ply, s, points, pose, *s.discs);
        out["discs"] = {{"projectionNeighbours", *s.discs}, {"skip", 2.0 * s.scan.spacing}, {"seconds", now() - start},
                        {"receiverNormals", s.discNormalsEstimated ? "estimated" : "true"}};
    }
    std::map<std::string, std::vector<std::size_t>> parts;
    for (std::size_t i = 0; i < points.size(); ++i) parts[points[i].part].push_back(i);
    parts["all"].resize(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) parts["all"][i] = i;
    for (const auto& [part, ids] : parts) {
        std::vector<double> m, t, r;
        for (const std::size_t i : ids) m.push_back(method[i]), t.push_back(truth[i]), r.push_back((*cellRef)[i]);
        out["parts"][part] = agreement(m, t);
        out["parts"][part]["cellReference"] = agreement(r, t);
        if (!discValues.empty()) {
            std::vector<double> d;
            for (const std::size_t i : ids) d.push_back(discValues[i]);
            out["parts"][part]["discs"] = agreement(d, t);
        }
        if (part == "bed" || part == "bedNearEdge") out["parts"][part]["low"] = lowTail(m);
    }
    const auto meanOf = [&](const char* part) { return out["parts"].contains(part) ? out["parts"][part]["mean"].get<double>() : -1.0; };
    out["flutesDarkerThanFillets"] = meanOf("flute") < meanOf("fillet");
    if (pcv) out["pcv"] = pcvReport(s, *pcv, points, pose, directions, truth, method);
    if (!s.csv.empty()) {
        std::ofstream csv(s.csv);
        csv << "part,truth,method,cellReference,leafDistance,x,y,z,nx,ny,nz\n";
        for (std::size_t i = 0; i < points.size(); ++i)
            csv << points[i].part << "," << truth[i] << "," << method[i] << "," << (*cellRef)[i] << "," << distance[i]
                << "," << points[i].p.x() << "," << points[i].p.y() << "," << points[i].p.z() << "," << points[i].n.x()
                << "," << points[i].n.y() << "," << points[i].n.z() << "\n";
    }
    out["loadAfter"] = loadAverage();
    std::cout << out.dump(2) << "\n";
    return 0;
}
