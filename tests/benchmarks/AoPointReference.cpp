// stylos_ao_pointref: the 3D skydome of a real scan against a reference ray-cast against its POINTS as
// discs (ao/DiscSkydome.h), not cells: the Happy Buddha's benchmark of issue 17 (docs/benchmarks.md).
//
//   stylos_ao_pointref [--ply FILE] [--depth D] [--level L] [--directions N] [--points P] [--seed S]
//                      [--skip K] [--radius-scale F] [--project J] [--threads T] [--dir WORK] [--csv OUT.csv]
//                      [--one-sided] [--reference-one-sided] [--smoothing S]
//   - The octree: buildOctreeFile(FILE) at depth D (default 12, normals estimated), as `stylos-cli ao`
//     builds it, cached in WORK (default /tmp/stylos-ao-pointref).
//   - The method: computeLeafSkydome (what `stylos-cli ao` writes: level L, default the closed-surface
//     level; two-sided unless --one-sided), timed.
//   - The reference: every point of FILE a disc (estimated normal, radius = F × the mean distance to its 8
//     nearest, F default 1; each centre projected onto the plane through its J nearest, default 16, 0 = the
//     raw points: DiscSkydome.h); P sampled points (default 2000, seed S) as receivers with their disc's normal,
//     discs within K radii (default 2: about 2 spacings) of the receiver skipped, the method's directions
//     (Fibonacci, all N, d·n > 0), two-sided (the scan has no normals; the estimated ones' sign is a
//     guess) unless --reference-one-sided. Compared with the value of the leaf nearest to each receiver.
// One JSON document goes to stdout; progress to stderr.
#include "stylos/core/ao/AoCells.h"
#include "stylos/core/ao/Directions.h"
#include "stylos/core/ao/DiscSkydome.h"
#include "stylos/core/ao/SkydomeLayer.h"
#include "stylos/core/cloud/LoadPointCloud.h"
#include "stylos/core/octree/OctreeBuild.h"
#include "stylos/core/octree/PackedOctree.h"

#include "BenchmarkClock.h"
#include "LeafGrid.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace fs = std::filesystem;
namespace ao = stylos::core::ao;
namespace oct = stylos::core::octree;
using nlohmann::json;
using stylos::bench::loadAverage;
using stylos::bench::now;

namespace {

struct Settings {
    fs::path ply = "/work/shared/data/scans/happy_buddha_1.1M.ply";
    int depth = 12;
    int level = -1;
    double smoothing = -1.0; ///< < 0: computeLeafSkydome's default (SkydomeLayerOptions::smoothing)
    ao::AoOptions ao;
    std::size_t points = 2000;
    std::uint64_t seed = 7;
    double skip = 2.0;
    double radiusScale = 1.0;
    std::size_t project = 16;
    unsigned threads = 2;
    bool referenceTwoSided = true;
    fs::path dir = "/tmp/stylos-ao-pointref";
    fs::path csv;
};

[[noreturn]] void fail(const std::string& message)
{
    std::cerr << "stylos_ao_pointref: " << message << "\n";
    std::exit(1);
}

Settings parse(int argc, char** argv)
{
    Settings s;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() -> std::string {
            if (i + 1 >= argc) fail(a + " needs a value");
            return argv[++i];
        };
        if (a == "--ply") s.ply = next();
        else if (a == "--depth") s.depth = std::stoi(next());
        else if (a == "--level") s.level = std::stoi(next());
        else if (a == "--directions") s.ao.directions = std::stoi(next());
        else if (a == "--points") s.points = std::stoull(next());
        else if (a == "--seed") s.seed = std::stoull(next());
        else if (a == "--skip") s.skip = std::stod(next());
        else if (a == "--radius-scale") s.radiusScale = std::stod(next());
        else if (a == "--project") s.project = std::stoull(next());
        else if (a == "--threads") s.threads = unsigned(std::stoul(next()));
        else if (a == "--dir") s.dir = next();
        else if (a == "--csv") s.csv = next();
        else if (a == "--one-sided") s.ao.twoSided = false;
        else if (a == "--smoothing") s.smoothing = std::stod(next());
        else if (a == "--reference-one-sided") s.referenceTwoSided = false;
        else fail("unknown option " + a + " (see the source's header)");
    }
    s.ao.threads = s.threads;
    return s;
}

json agreement(const std::vector<double>& a, const std::vector<double>& b)
{
    const std::size_t n = a.size();
    double ma = 0, mb = 0, mae = 0;
    for (std::size_t i = 0; i < n; ++i) ma += a[i], mb += b[i], mae += std::fabs(a[i] - b[i]);
    ma /= double(n);
    mb /= double(n);
    double sab = 0, saa = 0, sbb = 0;
    for (std::size_t i = 0; i < n; ++i) {
        sab += (a[i] - ma) * (b[i] - mb);
        saa += (a[i] - ma) * (a[i] - ma);
        sbb += (b[i] - mb) * (b[i] - mb);
    }
    return json{{"n", n}, {"r", saa > 0 && sbb > 0 ? sab / std::sqrt(saa * sbb) : 0.0}, {"mae", mae / double(n)},
                {"mean", ma}, {"referenceMean", mb}, {"sd", std::sqrt(saa / double(n))},
                {"referenceSd", std::sqrt(sbb / double(n))}};
}

} // namespace

int main(int argc, char** argv)
{
    const Settings s = parse(argc, argv);
    if (s.points == 0 || s.ao.directions < 1) fail("--points and --directions must be positive");
    json out;
    out["loadBefore"] = loadAverage();
    fs::create_directories(s.dir);
    const fs::path poct = s.dir / (s.ply.stem().string() + "-d" + std::to_string(s.depth) + ".poct");
    if (!fs::exists(poct)) {
        std::cerr << "building " << poct << "...\n";
        oct::BuildOptions build;
        build.depth = s.depth;
        auto built = oct::buildOctreeFile(s.ply.string(), poct, build);
        if (!built) fail(built.error().message);
    }
    auto opened = oct::PackedOctree::open(poct);
    if (!opened) fail(opened.error().message);
    const oct::PackedOctree& octree = opened.value();

    // The method, as stylos-cli ao runs it.
    ao::SkydomeLayerOptions layer;
    layer.ao = s.ao;
    if (s.level >= 0) layer.level = s.level;
    if (s.smoothing >= 0.0) layer.smoothing = s.smoothing;
    ao::SkydomeLayerReport report;
    double start = now();
    auto values = ao::computeLeafSkydome(octree, layer, nullptr, &report);
    if (!values) fail(values.error().message);
    const double methodSeconds = now() - start;
    std::cerr << "method: level " << report.level << ", " << report.cells << " cells, " << report.leaves << " leaves, "
              << methodSeconds << " s\n";
    auto leavesResult = ao::cellsAtLevel(octree, octree.depth());
    if (!leavesResult) fail("cannot read the leaves");
    const ao::AoCells& leaves = *leavesResult;

    // The points as discs.
    start = now();
    auto cloud = stylos::core::cloud::loadPointCloud(s.ply);
    if (!cloud) fail(cloud.error().message);
    std::vector<double> xyz(cloud->positions.size());
    for (std::size_t i = 0; i < cloud->size(); ++i) {
        const Eigen::Vector3d w = cloud->world(i);
        for (int a = 0; a < 3; ++a) xyz[3 * i + std::size_t(a)] = w[a];
    }
    ao::DiscCloudOptions discOptions;
    discOptions.radiusScale = s.radiusScale;
    discOptions.threads = s.threads;
    discOptions.projectionNeighbours = s.project;
    auto discs = ao::discsFromPoints(xyz, discOptions);
    if (!discs) fail(discs.error().message);
    const ao::DiscGrid grid(*discs);
    const double discSeconds = now() - start;
    std::vector<float> radii = discs->radii;
    std::nth_element(radii.begin(), radii.begin() + std::ptrdiff_t(radii.size() / 2), radii.end());
    const double medianRadius = radii[radii.size() / 2];
    std::cerr << "discs: " << discs->size() << ", median radius " << medianRadius << ", grid " << grid.dimensions()[0]
              << "×" << grid.dimensions()[1] << "×" << grid.dimensions()[2] << ", " << discSeconds << " s\n";

    // Receivers and the reference.
    std::mt19937_64 random(s.seed);
    std::uniform_int_distribution<std::size_t> pick(0, discs->size() - 1);
    std::vector<std::size_t> receivers(s.points);
    for (auto& r : receivers) r = pick(random);
    std::vector<std::array<double, 3>> directions;
    for (const auto& d : ao::fibonacciDirections(s.ao.directions, false)) directions.push_back({d[0], d[1], d[2]});
    std::vector<double> reference(receivers.size());
    start = now();
    {
        std::vector<std::thread> workers;
        const unsigned threads = std::max(1u, s.threads);
        for (unsigned w = 0; w < threads; ++w)
            workers.emplace_back([&, w] {
                for (std::size_t k = w; k < receivers.size(); k += threads) {
                    const std::size_t i = receivers[k];
                    const auto& n = discs->normals[i];
                    reference[k] = ao::discSkydome(grid, discs->centres[i], {n[0], n[1], n[2]}, directions,
                                                   s.skip * discs->radii[i], s.referenceTwoSided);
                }
            });
        for (auto& t : workers) t.join();
    }
    const double referenceSeconds = now() - start;
    std::cerr << "reference on " << receivers.size() << " points: " << referenceSeconds << " s\n";

    const stylos::bench::LeafGrid leafGrid(leaves, std::max(4.0 * medianRadius, 2.0 * leaves.edge));
    std::vector<double> method(receivers.size()), distance(receivers.size());
    for (std::size_t k = 0; k < receivers.size(); ++k) {
        const auto& c = discs->centres[receivers[k]];
        const Eigen::Vector3d q(c[0], c[1], c[2]);
        const std::size_t leaf = leafGrid.nearest(q);
        if (leaf == SIZE_MAX) fail("no leaf near a point: the octree is not of this scan");
        const auto l = leaves.centre(leaf);
        distance[k] = (Eigen::Vector3d(l[0], l[1], l[2]) - q).norm();
        method[k] = (*values)[leaf];
    }
    std::vector<double> sortedDistance = distance;
    std::sort(sortedDistance.begin(), sortedDistance.end());

    out["scan"] = {{"file", s.ply.string()}, {"points", discs->size()}, {"depth", octree.depth()},
                   {"leafEdge", leaves.edge}};
    out["method"] = {{"level", report.level}, {"cells", report.cells}, {"leaves", report.leaves},
                     {"directions", s.ao.directions}, {"bias", s.ao.receiverBias}, {"twoSided", s.ao.twoSided},
                     {"seconds", methodSeconds}, {"skydomeSeconds", report.aoSeconds},
                     {"smoothingRadius", report.smoothingRadius}, {"smoothingSeconds", report.smoothSeconds}};
    out["reference"] = {{"receivers", receivers.size()}, {"seed", s.seed}, {"medianRadius", medianRadius},
                        {"skipRadii", s.skip}, {"radiusScale", s.radiusScale}, {"projectionNeighbours", s.project}, {"twoSided", s.referenceTwoSided},
                        {"discSeconds", discSeconds}, {"seconds", referenceSeconds},
                        {"grid", {grid.dimensions()[0], grid.dimensions()[1], grid.dimensions()[2]}},
                        {"leafDistanceMedian", sortedDistance[sortedDistance.size() / 2]},
                        {"leafDistanceMax", sortedDistance.back()}};
    out["agreement"] = agreement(method, reference);
    if (!s.csv.empty()) {
        std::ofstream csv(s.csv);
        csv << "reference,method,leafDistance,x,y,z,nx,ny,nz\n";
        for (std::size_t k = 0; k < receivers.size(); ++k) {
            const auto& c = discs->centres[receivers[k]];
            const auto& n = discs->normals[receivers[k]];
            csv << reference[k] << "," << method[k] << "," << distance[k] << "," << c[0] << "," << c[1] << "," << c[2]
                << "," << n[0] << "," << n[1] << "," << n[2] << "\n";
        }
    }
    out["loadAfter"] = loadAverage();
    std::cout << out.dump(2) << "\n";
    return 0;
}
