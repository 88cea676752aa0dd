// stylos_ao_quality: how well the 3D skydome's methods agree with the brute-force reference, what they
// cost, and (with --pcv) how CloudCompare's PCV compares on the same points (issue 5, docs/benchmarks.md).
//
//   stylos_ao_quality IN.poct|IN.ply [--level L] [--depth D] [--directions N] [--samples S] [--seed K]
//                     [--methods slices,depthmap] [--upper-hemisphere] [--cosine] [--bias B] [--threads T]
//                     [--truth T.json] [--class-samples C] [--pcv OUT_PCV.ply] [--pcv-points P]
//                     [--pcv-seconds SEC]
//   - IN: a .poct, or a point file built into a temporary .poct (octree::buildOctreeFile, depth D,
//     default 12; normals estimated when the file has none).
//   - Level L: default the deepest level whose cells still grow like a surface (≥ 3× the level above),
//     where the cells are coarser than the sampling and the surface is closed.
//   - Every method on all cells of level L (computeAmbientOcclusion, timed), then the reference on S
//     random cells (default 2000): per method, the seconds, Pearson's correlation and the mean absolute
//     error against the reference.
//   - A generated drum (its truth sidecar, IN.truth.json beside a point file, or --truth): the lateral
//     cells are classified in the drum's own frame by azimuth phase relative to the flutes (truth:
//     pose, groove count, phase, pitch, half width) — groove bottoms (|φ| < half width / 2), fillets
//     (|φ| > half width), and the broken cavity's core (q < 0.5 in its (θ, z) ellipse); the class
//     means of every method (all cells of the class) and of the reference (C random cells of each,
//     default 300), and whether grooves < fillets and cavity < grooves.
//   - --pcv: CloudCompare's output of the same cloud (x y z and its "Illuminance (PCV)" scalar field,
//     read by PcvCloud.h). P random points (default 2000) go to the level-L cell containing them; PCV is
//     compared with the reference and each method with the reference. PCV's value is (rays that see the
//     point) / (all rays), from the whole sphere (or, with -180, its upper half), without normals;
//     Stylos's is over the directions in front of the normal. So both are also put in PCV's definition:
//     a value times F(n) = (directions of the set with n·d > 0) / (all directions); "stylosDefinition"
//     divides PCV by F(n) instead. "twoSided" compares PCV with the reference counted from both sides of the tangent
//     plane: ref(n)·F(n) + ref(−n)·F(−n), ref(−n) being the reference with the normal flipped (the bias
//     then below the plane) — what PCV measures on an open surface (a single-sided scan), which it sees
//     from behind as well.
// One JSON document goes to stdout; progress lines to stderr.
#include "stylos/core/ao/AmbientOcclusion.h"
#include "stylos/core/ao/Directions.h"
#include "stylos/core/ao/ReferenceAo.h"
#include "stylos/core/octree/OctreeBuild.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/synth/SyntheticScan.h"

#include "BenchmarkClock.h"
#include "PcvCloud.h"

#include <nlohmann/json.hpp>

#include <Eigen/Geometry>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

namespace fs = std::filesystem;
namespace ao = stylos::core::ao;
namespace oct = stylos::core::octree;
using nlohmann::json;

namespace {

struct Settings {
    fs::path input;
    int level = -1;
    int depth = 12;
    ao::AoOptions options;
    std::vector<ao::AoMethod> methods{ao::AoMethod::Slices, ao::AoMethod::DepthMap};
    std::size_t samples = 2000;
    std::size_t classSamples = 300;
    std::uint64_t seed = 1;
    fs::path truth;
    fs::path pcv;
    std::size_t pcvPoints = 2000;
    double pcvSeconds = -1.0;
};

[[noreturn]] void fail(const std::string& message)
{
    std::cerr << "stylos_ao_quality: " << message << "\n";
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
        if (a == "--level") s.level = std::stoi(next());
        else if (a == "--depth") s.depth = std::stoi(next());
        else if (a == "--directions") s.options.directions = std::stoi(next());
        else if (a == "--samples") s.samples = std::stoull(next());
        else if (a == "--class-samples") s.classSamples = std::stoull(next());
        else if (a == "--seed") s.seed = std::stoull(next());
        else if (a == "--upper-hemisphere") s.options.upperHemisphere = true;
        else if (a == "--cosine") s.options.cosineWeighted = true;
        else if (a == "--bias") s.options.bias = std::stod(next());
        else if (a == "--threads") s.options.threads = unsigned(std::stoul(next()));
        else if (a == "--truth") s.truth = next();
        else if (a == "--pcv") s.pcv = next();
        else if (a == "--pcv-points") s.pcvPoints = std::stoull(next());
        else if (a == "--pcv-seconds") s.pcvSeconds = std::stod(next());
        else if (a == "--methods") {
            s.methods.clear();
            std::stringstream list(next());
            for (std::string name; std::getline(list, name, ',');) {
                const auto m = ao::aoMethodFromName(name);
                if (!m) fail("unknown method " + name);
                s.methods.push_back(*m);
            }
        } else if (!a.empty() && a[0] == '-') fail("unknown option " + a);
        else s.input = a;
    }
    if (s.input.empty()) fail("usage: stylos_ao_quality IN.poct|IN.ply [options] (see the source's header)");
    if (s.truth.empty() && s.input.extension() != ".poct" && fs::exists(stylos::core::synth::truthPathFor(s.input)))
        s.truth = stylos::core::synth::truthPathFor(s.input);
    return s;
}

/** Pearson's correlation and the mean absolute error of @p a against @p b. */
json agreement(const std::vector<double>& a, const std::vector<double>& b)
{
    const std::size_t n = a.size();
    if (n == 0) return json{{"n", 0}};
    double ma = 0, mb = 0, mae = 0;
    for (std::size_t i = 0; i < n; ++i) {
        ma += a[i];
        mb += b[i];
        mae += std::fabs(a[i] - b[i]);
    }
    ma /= double(n);
    mb /= double(n);
    double sab = 0, saa = 0, sbb = 0;
    for (std::size_t i = 0; i < n; ++i) {
        sab += (a[i] - ma) * (b[i] - mb);
        saa += (a[i] - ma) * (a[i] - ma);
        sbb += (b[i] - mb) * (b[i] - mb);
    }
    const double r = saa > 0 && sbb > 0 ? sab / std::sqrt(saa * sbb) : 0.0;
    return json{{"n", n}, {"correlation", r}, {"mae", mae / double(n)}, {"mean", ma}, {"referenceMean", mb}};
}

double mean(const std::vector<double>& v)
{
    double s = 0;
    for (double x : v) s += x;
    return v.empty() ? 0.0 : s / double(v.size());
}

/** @p count distinct indices of [0, size) (all of them when size ≤ count), in increasing order. */
std::vector<std::size_t> randomSubset(std::size_t size, std::size_t count, std::mt19937_64& random)
{
    std::vector<std::size_t> all(size);
    for (std::size_t i = 0; i < size; ++i) all[i] = i;
    if (count < size) {
        for (std::size_t i = 0; i < count; ++i)
            std::swap(all[i], all[i + std::uniform_int_distribution<std::size_t>(0, size - 1 - i)(random)]);
        all.resize(count);
    }
    std::sort(all.begin(), all.end());
    return all;
}

std::vector<float> runReference(const ao::AoCells& cells, const std::vector<std::size_t>& samples,
                                const ao::AoOptions& options, double* seconds = nullptr)
{
    const double start = now();
    auto values = ao::referenceAmbientOcclusion(cells, samples, options);
    if (!values) fail(values.error().message);
    if (seconds) *seconds = now() - start;
    return std::move(values).value();
}

/** The deepest level whose cell count is at least 3× that of the level above (at least 1). */
int surfaceLevel(const oct::PackedOctree& octree)
{
    int level = 1;
    for (int l = 1; l <= octree.depth(); ++l)
        if (double(octree.cellCount(l)) >= 3.0 * double(octree.cellCount(l - 1))) level = l;
    return level;
}

// ---------------------------------------------------------------------------------------------------
// The generated drum: classes of lateral cells from the truth.

enum class DrumClass { Other, Groove, Fillet, Cavity };

std::vector<DrumClass> classifyDrum(const ao::AoCells& cells, const json& truth)
{
    Eigen::Matrix4d pose;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) pose(r, c) = truth["pose"][r * 4 + c].get<double>();
    const Eigen::Affine3d toDrum(pose.inverse());
    const double radius = truth["radius"], height = truth["height"];
    const auto& g = truth["grooves"];
    const double phase = g["phase"], pitch = g["pitch"], halfWidth = g["halfWidth"], depth = g["depth"];
    const auto& b = truth["broken"];
    const double bCentre = b["thetaCentre"], bHalf = b["halfAngle"], bzMin = b["zMin"], bzMax = b["zMax"];
    const double margin = 2.0 * cells.edge;
    std::vector<DrumClass> classes(cells.size(), DrumClass::Other);
    for (std::size_t i = 0; i < cells.size(); ++i) {
        const auto c = cells.centre(i);
        const Eigen::Vector3d p = toDrum * Eigen::Vector3d(c[0], c[1], c[2]);
        const double rho = std::hypot(p.x(), p.y()), theta = std::atan2(p.y(), p.x()), z = p.z();
        const double qa = std::remainder(theta - bCentre, 2.0 * std::numbers::pi) / bHalf;
        const double qz = (z - 0.5 * (bzMin + bzMax)) / (0.5 * (bzMax - bzMin));
        const double q = qa * qa + qz * qz;
        if (q < 0.5 && rho > radius - 0.2 && z > margin && z < height - margin) {
            classes[i] = DrumClass::Cavity;
            continue;
        }
        // Lateral, clear of the beds, the claw band (above 0.84 H) and the cavity's rim.
        if (q < 1.5 || z < 0.1 * height || z > 0.8 * height) continue;
        if (rho < radius - depth - margin || rho > radius + margin) continue;
        const double phi = std::remainder(theta - phase, pitch);
        if (std::fabs(phi) < 0.5 * halfWidth) classes[i] = DrumClass::Groove;
        else if (std::fabs(phi) > halfWidth) classes[i] = DrumClass::Fillet;
    }
    return classes;
}

json drumReport(const ao::AoCells& cells, const std::vector<DrumClass>& classes,
                const std::vector<std::pair<std::string, std::vector<float>>>& methods, const Settings& s,
                std::mt19937_64& random)
{
    const std::pair<DrumClass, const char*> names[] = {
        {DrumClass::Groove, "grooves"}, {DrumClass::Fillet, "fillets"}, {DrumClass::Cavity, "cavity"}};
    json out;
    std::map<std::string, std::map<std::string, double>> means; // source → class → mean
    for (const auto& [cls, name] : names) {
        std::vector<std::size_t> members;
        for (std::size_t i = 0; i < cells.size(); ++i)
            if (classes[i] == cls) members.push_back(i);
        out[name]["cells"] = members.size();
        if (members.empty()) continue;
        for (const auto& [method, values] : methods) {
            double sum = 0;
            for (const std::size_t i : members) sum += values[i];
            means[method][name] = sum / double(members.size());
        }
        std::vector<std::size_t> picked;
        for (const std::size_t k : randomSubset(members.size(), s.classSamples, random)) picked.push_back(members[k]);
        const auto ref = runReference(cells, picked, s.options);
        means["reference"][name] = mean(std::vector<double>(ref.begin(), ref.end()));
        out[name]["referenceSamples"] = picked.size();
    }
    for (auto& [source, m] : means) {
        out["means"][source] = m;
        if (m.count("grooves") && m.count("fillets") && m.count("cavity")) {
            out["groovesDarkerThanFillets"][source] = m["grooves"] < m["fillets"];
            out["cavityDarkest"][source] = m["cavity"] < m["grooves"] && m["cavity"] < m["fillets"];
        }
    }
    return out;
}

// ---------------------------------------------------------------------------------------------------
// CloudCompare's PCV output compared on the same points.

using MethodValues = std::vector<std::pair<std::string, std::vector<float>>>;

using stylos::bench::frontFraction;
using stylos::bench::PcvCloud;

PcvCloud readPcv(const fs::path& path)
{
    auto cloud = stylos::bench::readPcvCloud(path);
    if (!cloud) fail(cloud.error().message);
    return std::move(cloud).value();
}

/**
 * The level-L cell of every point (SIZE_MAX if none): its coordinates, or the nearest occupied of the 26
 * neighbours (the PLY holds float coordinates, which may fall just across a cell face).
 */
std::vector<std::size_t> cellsOfPoints(const ao::AoCells& cells, const std::vector<std::array<double, 3>>& points)
{
    const auto key = [](std::int64_t x, std::int64_t y, std::int64_t z) {
        return (std::uint64_t(x) << 42) | (std::uint64_t(y) << 21) | std::uint64_t(z);
    };
    std::unordered_map<std::uint64_t, std::size_t> index;
    index.reserve(cells.size() * 2);
    for (std::size_t i = 0; i < cells.size(); ++i) index[key(cells.coords[i][0], cells.coords[i][1], cells.coords[i][2])] = i;
    const std::int64_t top = (std::int64_t{1} << cells.level) - 1;
    std::vector<std::size_t> cellOf(points.size(), SIZE_MAX);
    for (std::size_t p = 0; p < points.size(); ++p) {
        std::array<double, 3> u{};
        std::array<std::int64_t, 3> c{};
        for (int a = 0; a < 3; ++a) {
            u[a] = (points[p][a] - cells.origin[a]) / cells.edge;
            c[a] = std::clamp<std::int64_t>(std::int64_t(std::floor(u[a])), 0, top);
        }
        if (const auto it = index.find(key(c[0], c[1], c[2])); it != index.end()) {
            cellOf[p] = it->second;
            continue;
        }
        double best = 1e300;
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const std::int64_t x = c[0] + dx, y = c[1] + dy, z = c[2] + dz;
                    if (x < 0 || y < 0 || z < 0 || x > top || y > top || z > top) continue;
                    const auto it = index.find(key(x, y, z));
                    if (it == index.end()) continue;
                    const double d2 = (x + 0.5 - u[0]) * (x + 0.5 - u[0]) + (y + 0.5 - u[1]) * (y + 0.5 - u[1]) +
                                      (z + 0.5 - u[2]) * (z + 0.5 - u[2]);
                    if (d2 < best) best = d2, cellOf[p] = it->second;
                }
    }
    return cellOf;
}

json percentiles(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    json out;
    for (const int q : {5, 25, 50, 75, 95})
        out[std::to_string(q)] = v.empty() ? 0.0 : v[std::min(v.size() - 1, std::size_t(q * 0.01 * double(v.size())))];
    return out;
}

/**
 * PCV against the reference on P random points (each with its cell's reference value), in PCV's and in
 * Stylos's definition, and the same for each method; then per cell (the mean PCV of the cell's points);
 * the drum's class means of PCV when @p classes is not empty.
 */
json pcvReport(const ao::AoCells& cells, const MethodValues& methods, const std::vector<DrumClass>& classes,
               const Settings& s, std::mt19937_64& random)
{
    const PcvCloud pcv = readPcv(s.pcv);
    const std::vector<std::size_t> cellOf = cellsOfPoints(cells, pcv.positions);
    const auto directions = ao::fibonacciDirections(s.options.directions, s.options.upperHemisphere);
    std::vector<double> cellSum(cells.size(), 0.0);
    std::vector<std::uint32_t> cellPoints(cells.size(), 0);
    std::size_t unmatched = 0;
    for (std::size_t p = 0; p < cellOf.size(); ++p) {
        if (cellOf[p] == SIZE_MAX) {
            ++unmatched;
            continue;
        }
        cellSum[cellOf[p]] += pcv.values[p];
        ++cellPoints[cellOf[p]];
    }

    std::vector<std::size_t> pointIds;
    for (const std::size_t p : randomSubset(pcv.positions.size(), s.pcvPoints, random))
        if (cellOf[p] != SIZE_MAX) pointIds.push_back(p);
    std::vector<std::size_t> unique;
    for (const std::size_t p : pointIds) unique.push_back(cellOf[p]);
    std::sort(unique.begin(), unique.end());
    unique.erase(std::unique(unique.begin(), unique.end()), unique.end());
    double refSeconds = 0;
    const auto refUnique = runReference(cells, unique, s.options, &refSeconds);
    // The other side: the same cells with flipped normals (the directions behind the tangent plane, with
    // the bias below it): PCV, without normals, also counts the rays that reach a point from behind.
    ao::AoCells flipped = cells;
    for (auto& n : flipped.normals) n = {-n[0], -n[1], -n[2]};
    const auto refBackUnique = runReference(flipped, unique, s.options);
    const auto slot = [&](std::size_t cell) {
        return std::size_t(std::lower_bound(unique.begin(), unique.end(), cell) - unique.begin());
    };
    const auto refOf = [&](std::size_t cell) { return double(refUnique[slot(cell)]); };
    const auto refBackOf = [&](std::size_t cell) { return double(refBackUnique[slot(cell)]); };

    // Per point (sampled), then per cell (the sampled points' cells, PCV averaged over all their points).
    json out{{"file", s.pcv.string()}, {"points", pcv.positions.size()}, {"sampledPoints", pointIds.size()},
             {"unmatchedPoints", unmatched}, {"referenceCells", unique.size()}, {"referenceSeconds", refSeconds},
             {"pcvPercentiles", percentiles(pcv.values)}};
    for (const bool perCell : {false, true}) {
        std::vector<double> pcvValues, pcvInStylos, refStylos, refPcv, refTwoSided, front;
        std::vector<std::size_t> cellIds;
        const std::size_t count = perCell ? unique.size() : pointIds.size();
        for (std::size_t k = 0; k < count; ++k) {
            const std::size_t cell = perCell ? unique[k] : cellOf[pointIds[k]];
            const double value = perCell ? cellSum[cell] / cellPoints[cell] : pcv.values[pointIds[k]];
            const double f = frontFraction(directions, cells.normals[cell]);
            const double r = refOf(cell);
            cellIds.push_back(cell);
            front.push_back(f);
            pcvValues.push_back(value);
            pcvInStylos.push_back(f > 0 ? std::min(1.0, value / f) : 0.0);
            refStylos.push_back(r);
            refPcv.push_back(r * f);
            const auto& n = cells.normals[cell];
            refTwoSided.push_back(r * f + refBackOf(cell) * frontFraction(directions, {-n[0], -n[1], -n[2]}));
        }
        json& o = perCell ? out["perCell"] : out["perPoint"];
        o["meanFrontFraction"] = mean(front);
        o["pcvDefinition"]["pcv"] = agreement(pcvValues, refPcv);
        o["twoSided"]["pcv"] = agreement(pcvValues, refTwoSided);
        o["stylosDefinition"]["pcv"] = agreement(pcvInStylos, refStylos);
        for (const auto& [name, values] : methods) {
            std::vector<double> m, mPcv;
            for (std::size_t k = 0; k < cellIds.size(); ++k) {
                m.push_back(values[cellIds[k]]);
                mPcv.push_back(values[cellIds[k]] * front[k]);
            }
            o["stylosDefinition"][name] = agreement(m, refStylos);
            o["pcvDefinition"][name] = agreement(mPcv, refPcv);
        }
    }
    if (!classes.empty()) {
        const std::pair<DrumClass, const char*> names[] = {
            {DrumClass::Groove, "grooves"}, {DrumClass::Fillet, "fillets"}, {DrumClass::Cavity, "cavity"}};
        for (const auto& [cls, name] : names) {
            std::vector<double> v;
            for (std::size_t p = 0; p < cellOf.size(); ++p)
                if (cellOf[p] != SIZE_MAX && classes[cellOf[p]] == cls) v.push_back(pcv.values[p]);
            out["drumClassMeans"][name] = mean(v);
        }
    }
    if (s.pcvSeconds >= 0) out["pcvSeconds"] = s.pcvSeconds;
    return out;
}

} // namespace

int main(int argc, char** argv)
{
    Settings s = parse(argc, argv);
    json out;
    out["input"] = s.input.string();
    out["loadBefore"] = loadAverage();
    fs::path poct = s.input;
    fs::path temp;
    if (s.input.extension() != ".poct") {
        temp = fs::temp_directory_path() / ("stylos_ao_quality_" + std::to_string(::getpid()));
        fs::create_directories(temp);
        poct = temp / "cloud.poct";
        oct::BuildOptions build;
        build.depth = s.depth;
        std::cerr << "building the octree of " << s.input << " at depth " << s.depth << "...\n";
        const double start = now();
        auto report = oct::buildOctreeFile(s.input, poct, build);
        if (!report) fail(report.error().message);
        out["build"] = {{"seconds", now() - start}, {"points", report->points}, {"depth", report->depth},
                        {"normalsEstimated", report->normalsEstimated}};
    }
    auto opened = oct::PackedOctree::open(poct);
    if (!opened) fail(opened.error().message);
    const oct::PackedOctree& octree = opened.value();
    const int level = s.level >= 0 ? s.level : surfaceLevel(octree);
    double start = now();
    auto cellsResult = ao::cellsAtLevel(octree, level);
    if (!cellsResult) fail(cellsResult.error().message);
    const ao::AoCells cells = std::move(cellsResult).value();
    out["level"] = level;
    out["edgeMetres"] = cells.edge;
    out["cells"] = cells.size();
    out["leaves"] = octree.cellCount(octree.depth());
    out["cellsSeconds"] = now() - start;
    out["directions"] = s.options.directions;
    out["upperHemisphere"] = s.options.upperHemisphere;
    out["cosineWeighted"] = s.options.cosineWeighted;
    out["bias"] = s.options.bias;
    std::cerr << "level " << level << ": " << cells.size() << " cells of " << cells.edge * 1000 << " mm\n";

    std::vector<std::pair<std::string, std::vector<float>>> methods;
    for (const ao::AoMethod m : s.methods) {
        ao::AoOptions o = s.options;
        o.method = m;
        start = now();
        auto values = ao::computeAmbientOcclusion(cells, o);
        const double seconds = now() - start;
        if (!values) {
            out["methods"][ao::aoMethodName(m)]["error"] = values.error().message;
            continue;
        }
        std::cerr << ao::aoMethodName(m) << ": " << seconds << " s\n";
        out["methods"][ao::aoMethodName(m)]["seconds"] = seconds;
        methods.emplace_back(ao::aoMethodName(m), std::move(values).value());
    }

    std::mt19937_64 random(s.seed);
    const auto samples = randomSubset(cells.size(), s.samples, random);
    double refSeconds = 0;
    const auto ref = runReference(cells, samples, s.options, &refSeconds);
    std::cerr << "reference on " << samples.size() << " cells: " << refSeconds << " s\n";
    const std::vector<double> refValues(ref.begin(), ref.end());
    out["reference"] = {{"samples", samples.size()}, {"seconds", refSeconds}, {"mean", mean(refValues)}};
    for (const auto& [name, values] : methods) {
        std::vector<double> v;
        for (const std::size_t i : samples) v.push_back(values[i]);
        out["methods"][name].update(agreement(v, refValues));
    }

    std::vector<DrumClass> classes;
    if (!s.truth.empty()) {
        std::ifstream in(s.truth);
        const json truth = json::parse(in);
        if (truth.value("kind", "") == "drum") {
            classes = classifyDrum(cells, truth);
            out["drum"] = drumReport(cells, classes, methods, s, random);
        }
    }
    if (!s.pcv.empty()) out["pcv"] = pcvReport(cells, methods, classes, s, random);
    out["loadAfter"] = loadAverage();
    if (!temp.empty()) fs::remove_all(temp);
    std::cout << out.dump(2) << "\n";
    return 0;
}
