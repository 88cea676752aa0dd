// stylos-cli ao: a flat open floor sees the whole sky (ambient 1 exactly, whatever the method or the
// side its normals face), and none of it above the horizon when it faces down; a drum's octree gets the
// "ambient" layer (new file or in place, the cells unchanged) with the values of the PLY export; --level
// spreads a cell's value to its leaves; usage errors exit 2, bad inputs exit 1, and neither leaves a file.
#include "CliRunner.h"
#include "TestSupport.h"

#include "stylos/core/ao/AmbientOcclusion.h"
#include "stylos/core/ao/AoCells.h"
#include "stylos/core/io/PointFileFormat.h"
#include "stylos/core/octree/OctreeBuild.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/synth/SyntheticScan.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstring>
#include <set>

using stylos::test::runCli;
using stylos::test::TempDir;
namespace fs = std::filesystem;
namespace oct = stylos::core::octree;

namespace {

std::set<std::string> entriesIn(const fs::path& dir)
{
    std::set<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
    return names;
}

/** A 16 × 16 grid of points 1 cm apart at z = 0, ascii PLY, with normal (0, 0, @p nz) unless nz is 0. */
fs::path writeFloor(const TempDir& dir, const std::string& name, int nz)
{
    std::string text = "ply\nformat ascii 1.0\nelement vertex 256\nproperty float x\nproperty float y\nproperty float z\n";
    if (nz != 0) text += "property float nx\nproperty float ny\nproperty float nz\n";
    text += "end_header\n";
    for (int i = 0; i < 16; ++i)
        for (int k = 0; k < 16; ++k)
            text += std::to_string(i * 0.01) + " " + std::to_string(k * 0.01) + " 0" +
                    (nz != 0 ? " 0 0 " + std::to_string(nz) : std::string()) + "\n";
    stylos::test::writeText(dir / name, text);
    return dir / name;
}

/** The points of a PLY written by ao: positions and the "ambient" column. */
stylos::core::io::PointBatch readAoPly(const fs::path& path)
{
    auto reader = stylos::core::io::openPointReader(path);
    EXPECT_TRUE(reader.ok()) << (reader.ok() ? "" : reader.error().message);
    if (!reader.ok()) return {};
    EXPECT_EQ((*reader)->header().schema.scalarNames, std::vector<std::string>{"ambient"});
    auto all = stylos::test::readAllPoints(**reader, 1 << 16);
    EXPECT_TRUE(all.ok());
    return all.ok() ? std::move(all).value() : stylos::core::io::PointBatch{};
}

/** The Float32 "ambient" layer of a .poct as floats (empty, with a failure, when absent or of another type). */
std::vector<float> ambientLayer(const oct::PackedOctree& octree)
{
    const auto layer = octree.attribute("ambient");
    EXPECT_TRUE(layer.has_value());
    if (!layer) return {};
    EXPECT_EQ(layer->type, oct::AttributeType::Float32);
    EXPECT_EQ(layer->components, 1);
    std::vector<float> values(layer->bytes.size() / 4);
    std::memcpy(values.data(), layer->bytes.data(), values.size() * 4);
    return values;
}

oct::PackedOctree openPoct(const fs::path& path)
{
    auto opened = oct::PackedOctree::open(path);
    EXPECT_TRUE(opened.ok()) << (opened.ok() ? "" : opened.error().message);
    return std::move(opened).value();
}

/** The octree of @p points at @p depth, built through the core (fixtures need no process). */
fs::path buildPoct(const fs::path& points, const fs::path& poct, int depth)
{
    oct::BuildOptions options;
    options.depth = depth;
    const auto built = oct::buildOctreeFile(points, poct, options);
    EXPECT_TRUE(built.ok()) << (built.ok() ? "" : built.error().message);
    return poct;
}

/** A generated drum (2 cm spacing) with its true normals, built into an octree of depth 6. */
fs::path drumOctree(const TempDir& dir)
{
    namespace synth = stylos::core::synth;
    synth::SyntheticOptions options;
    options.spacing = 0.02;
    options.writeNormals = true;
    const auto generated = synth::generateScan(synth::SyntheticKind::Drum, options, dir / "drum.ply");
    EXPECT_TRUE(generated.ok()) << (generated.ok() ? "" : generated.error().message);
    return buildPoct(dir / "drum.ply", dir / "drum.poct", 6);
}

void expectSameCells(const oct::PackedOctree& a, const oct::PackedOctree& b)
{
    ASSERT_EQ(a.description(), b.description());
    for (int l = 0; l <= a.depth(); ++l) {
        const auto ma = a.levelMasks(l), mb = b.levelMasks(l);
        const auto na = a.levelNormalCodes(l), nb = b.levelNormalCodes(l);
        EXPECT_TRUE(std::equal(ma.begin(), ma.end(), mb.begin(), mb.end())) << "masks of level " << l;
        EXPECT_TRUE(std::equal(na.begin(), na.end(), nb.begin(), nb.end())) << "normals of level " << l;
    }
}

} // namespace

TEST(CliAo, FlatFloorSeesTheWholeSkyWithEitherMethod)
{
    TempDir dir;
    const auto floor = writeFloor(dir, "floor.ply", 1);
    for (const std::string method : {"", "slices", "depthmap"}) {
        const auto out = dir / ("floor-ao" + method + ".ply");
        std::vector<std::string> args{"ao", floor.string(), "-o", out.string(), "--depth", "5", "--json"};
        if (!method.empty()) args.insert(args.end(), {"--method", method});
        const auto run = runCli(args);
        ASSERT_EQ(run.exitCode, 0) << run.err;
        const auto j = nlohmann::json::parse(run.out);
        for (const char* key : {"directions", "cells", "method", "seconds", "level", "leaves", "mean_ambient"})
            EXPECT_TRUE(j.contains(key)) << key;
        EXPECT_EQ(j["directions"], 256);
        const std::string defaultMethod = stylos::core::ao::aoMethodName(stylos::core::ao::AoOptions{}.method);
        EXPECT_EQ(j["method"], method.empty() ? defaultMethod : method);
        // Points 1 cm apart, leaves of 5 mm: the default level is the last closed one, 4 (1 cm cells).
        EXPECT_EQ(j["level"], 4);
        EXPECT_EQ(j["depth"], 5);
        EXPECT_EQ(j["octree_built"], true);
        EXPECT_EQ(j["normals_estimated"], false);
        EXPECT_EQ(j["mean_ambient"], 1.0);
        const auto points = readAoPly(out);
        EXPECT_EQ(points.size(), j["leaves"].get<std::size_t>());
        for (std::size_t i = 0; i < points.size(); ++i) {
            ASSERT_EQ(points.scalars[0][i], 1.0) << method << " leaf " << i;
            EXPECT_NEAR(points.positions[3 * i + 2], 0.0, 0.01); // a leaf centre, within a leaf of the floor
        }
    }
    // The input and the three outputs; no octree or normals folder left behind.
    EXPECT_EQ(entriesIn(dir.path()).size(), 4u);
}

TEST(CliAo, FloorFacingDownSeesNothingAboveTheHorizon)
{
    TempDir dir;
    const auto floor = writeFloor(dir, "ceiling.ply", -1);
    const auto up = dir / "up.ply", all = dir / "all.ply";
    const auto run = runCli({"ao", floor.string(), "-o", up.string(), "--depth", "5", "--upper-hemisphere",
                             "--cosine", "--directions", "64", "--json"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const auto j = nlohmann::json::parse(run.out);
    EXPECT_EQ(j["directions"], 64);
    EXPECT_EQ(j["upper_hemisphere"], true);
    EXPECT_EQ(j["cosine"], true);
    const auto above = readAoPly(up);
    ASSERT_EQ(above.size(), j["leaves"].get<std::size_t>());
    for (double v : above.scalars[0]) ASSERT_EQ(v, 0.0); // no direction in front of it: 0 by definition
    ASSERT_EQ(runCli({"ao", floor.string(), "-o", all.string(), "--depth", "5"}).exitCode, 0);
    const auto whole = readAoPly(all);
    ASSERT_EQ(whole.size(), above.size());
    for (double v : whole.scalars[0]) ASSERT_EQ(v, 1.0);
}

TEST(CliAo, PointFileWithoutNormalsIsEstimatedAndSaysSo)
{
    TempDir dir;
    const auto floor = writeFloor(dir, "bare.ply", 0);
    const auto out = dir / "bare-ao.ply";
    const auto run = runCli({"ao", floor.string(), "-o", out.string(), "--depth", "5", "--directions", "32"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("built the octree of " + floor.string()), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("normals estimated"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("32 directions"), std::string::npos) << run.out;
    // Estimated normals face up or down (a plane has no inside); a flat floor sees its whole half sky either way.
    const auto points = readAoPly(out);
    ASSERT_GT(points.size(), 100u);
    for (double v : points.scalars[0]) ASSERT_EQ(v, 1.0);
    EXPECT_EQ(entriesIn(dir.path()).size(), 2u);
}

TEST(CliAo, PoctOutputCarriesTheLayerWithThePlyValues)
{
    TempDir dir;
    const auto poct = drumOctree(dir);
    const auto ply = dir / "drum-ao.ply", withLayer = dir / "drum-ao.poct";
    const std::vector<std::string> options{"--directions", "48", "--threads", "2"};
    auto args = std::vector<std::string>{"ao", poct.string(), "-o", ply.string()};
    args.insert(args.end(), options.begin(), options.end());
    ASSERT_EQ(runCli(args).exitCode, 0);
    args = {"ao", poct.string(), "-o", withLayer.string(), "--json"};
    args.insert(args.end(), options.begin(), options.end());
    const auto run = runCli(args);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(nlohmann::json::parse(run.out)["in_place"], false);

    const auto source = openPoct(poct), result = openPoct(withLayer);
    EXPECT_FALSE(source.attribute("ambient").has_value()); // the input is untouched
    expectSameCells(source, result);
    const auto layer = ambientLayer(result);
    const auto points = readAoPly(ply);
    ASSERT_EQ(layer.size(), result.cellCount(result.depth()));
    ASSERT_EQ(points.size(), layer.size());
    std::size_t dark = 0;
    for (std::size_t i = 0; i < layer.size(); ++i) {
        ASSERT_EQ(double(layer[i]), points.scalars[0][i]) << "leaf " << i;
        ASSERT_GE(layer[i], 0.0f);
        ASSERT_LE(layer[i], 1.0f);
        dark += layer[i] < 0.9f;
    }
    EXPECT_GT(dark, 0u); // the flutes and the bed faces' edges hide some of the sky
    // The PLY's vertices are the leaf centres, in leaf order.
    std::size_t i = 0;
    result.forEachCell(result.depth(), [&](const oct::CellView& cell) {
        for (int a = 0; a < 3; ++a) EXPECT_EQ(points.positions[3 * i + a], cell.centre[a]);
        return ++i < 8;
    });
}

TEST(CliAo, InPlaceKeepsTheCellsAndReplacesTheLayer)
{
    TempDir dir;
    const auto poct = drumOctree(dir);
    const auto copy = dir / "copy.poct";
    fs::copy_file(poct, copy);
    const auto first = runCli({"ao", copy.string(), "-o", copy.string(), "--directions", "16", "--json"});
    ASSERT_EQ(first.exitCode, 0) << first.err;
    EXPECT_EQ(nlohmann::json::parse(first.out)["in_place"], true);
    const auto second = runCli({"ao", copy.string(), "-o", copy.string(), "--directions", "40", "--upper-hemisphere"});
    ASSERT_EQ(second.exitCode, 0) << second.err;
    EXPECT_NE(second.out.find("(in place)"), std::string::npos) << second.out;

    const auto source = openPoct(poct), updated = openPoct(copy);
    expectSameCells(source, updated);
    std::vector<std::string> names;
    for (const auto& a : updated.attributes()) names.push_back(a.name);
    std::vector<std::string> expected;
    for (const auto& a : source.attributes()) expected.push_back(a.name);
    expected.push_back("ambient");
    EXPECT_EQ(names, expected); // one "ambient" layer, after the others

    // The layer is the second run's: the same as a PLY export with its options.
    const auto ply = dir / "check.ply";
    ASSERT_EQ(runCli({"ao", poct.string(), "-o", ply.string(), "--directions", "40", "--upper-hemisphere"}).exitCode, 0);
    const auto layer = ambientLayer(updated);
    const auto points = readAoPly(ply);
    ASSERT_EQ(points.size(), layer.size());
    for (std::size_t i = 0; i < layer.size(); ++i) ASSERT_EQ(double(layer[i]), points.scalars[0][i]) << i;
    EXPECT_EQ(entriesIn(dir.path()), (std::set<std::string>{"drum.ply", "drum.truth.json", "drum.poct", "copy.poct",
                                                            "check.ply"}));
}

TEST(CliAo, LevelSpreadsEachCellsValueToItsLeaves)
{
    // With --receivers cells (before issue 17 the only way): each cell's value goes to all its leaves.
    TempDir dir;
    const auto poct = drumOctree(dir);
    const auto out = dir / "l3.ply";
    const auto run = runCli({"ao", poct.string(), "-o", out.string(), "--level", "3", "--directions", "32", "--json",
                             "--receivers", "cells"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const auto j = nlohmann::json::parse(run.out);
    EXPECT_EQ(j["receivers"], "cells");
    EXPECT_EQ(j["bias"], 1.0);
    const auto octree = openPoct(poct);
    EXPECT_EQ(j["level"], 3);
    EXPECT_EQ(j["cells"], octree.cellCount(3));
    EXPECT_EQ(j["leaves"], octree.cellCount(octree.depth()));
    const auto cells = stylos::core::ao::cellsAtLevel(octree, 3);
    ASSERT_TRUE(cells.ok());
    const auto values = readAoPly(out).scalars[0];
    ASSERT_EQ(values.size(), cells->leafBegin.back());
    for (std::size_t c = 0; c < cells->size(); ++c)
        for (auto leaf = cells->leafBegin[c]; leaf < cells->leafBegin[c + 1]; ++leaf)
            ASSERT_EQ(values[leaf], values[cells->leafBegin[c]]) << "cell " << c;
}

TEST(CliAo, LeafReceiversByDefaultGiveLeavesTheirOwnValues)
{
    // The default: every leaf measured at its own centre and normal against the level's cells, so the
    // leaves of one cell may differ (they do on a drum at level 3: cells of an eighth of its box).
    TempDir dir;
    const auto poct = drumOctree(dir);
    const auto out = dir / "l3.ply";
    const auto run = runCli({"ao", poct.string(), "-o", out.string(), "--level", "3", "--directions", "32", "--json"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const auto j = nlohmann::json::parse(run.out);
    EXPECT_EQ(j["receivers"], "leaves");
    EXPECT_EQ(j["bias"], 0.5);
    const auto octree = openPoct(poct);
    const auto cells = stylos::core::ao::cellsAtLevel(octree, 3);
    ASSERT_TRUE(cells.ok());
    const auto values = readAoPly(out).scalars[0];
    ASSERT_EQ(values.size(), cells->leafBegin.back());
    std::size_t varied = 0;
    for (std::size_t c = 0; c < cells->size(); ++c)
        for (auto leaf = cells->leafBegin[c]; leaf < cells->leafBegin[c + 1]; ++leaf)
            varied += values[leaf] != values[cells->leafBegin[c]];
    EXPECT_GT(varied, 0u);
    for (const float v : values) ASSERT_TRUE(v >= 0.0f && v <= 1.0f);
    const auto bad = runCli({"ao", poct.string(), "-o", out.string(), "--receivers", "points"});
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.err.find("--receivers"), std::string::npos) << bad.err;
}

TEST(CliAo, SmoothingIsReportedAndZeroGivesTheRawLeafValues)
{
    // The default smooths each leaf's value with its neighbours' within 1.5 edges of the level's cells (at most 8
    // sampling spacings); --smoothing
    // gives the radius in metres, 0 the raw values. On the drum at level 3 the smoothed values vary less between neighbouring leaves.
    TempDir dir;
    const auto poct = drumOctree(dir);
    const auto smooth = dir / "smooth.ply", raw = dir / "raw.ply";
    const auto a = runCli({"ao", poct.string(), "-o", smooth.string(), "--level", "3", "--directions", "32", "--json"});
    const auto b = runCli({"ao", poct.string(), "-o", raw.string(), "--level", "3", "--directions", "32", "--json",
                           "--smoothing", "0"});
    ASSERT_EQ(a.exitCode, 0) << a.err;
    ASSERT_EQ(b.exitCode, 0) << b.err;
    const auto ja = nlohmann::json::parse(a.out), jb = nlohmann::json::parse(b.out);
    const auto octree = openPoct(poct);
    const auto cells = stylos::core::ao::cellsAtLevel(octree, 3);
    ASSERT_TRUE(cells.ok());
    // The radius used, metres: 1.5 edges of level 3's cells (0.22 m) would span a sixth of the drum, so the
    // default stops at 8 sampling spacings (the generator's 2 cm; the leaves' median spacing is within 10 % of it).
    EXPECT_LT(ja["smoothing"].get<double>(), 1.5 * cells->edge);
    EXPECT_NEAR(ja["smoothing"].get<double>(), 8 * 0.02, 8 * 0.002);
    EXPECT_EQ(jb["smoothing"], 0.0);
    // At level 5 the cells' 1.5 edges are within 8 spacings: they stand.
    const auto fine = runCli({"ao", poct.string(), "-o", (dir / "fine.ply").string(), "--level", "5", "--directions",
                              "8", "--json"});
    ASSERT_EQ(fine.exitCode, 0) << fine.err;
    const auto cells5 = stylos::core::ao::cellsAtLevel(octree, 5);
    ASSERT_TRUE(cells5.ok());
    EXPECT_DOUBLE_EQ(nlohmann::json::parse(fine.out)["smoothing"].get<double>(), 1.5 * cells5->edge);
    // A radius given in metres is used as given.
    const auto c = runCli({"ao", poct.string(), "-o", (dir / "c.ply").string(), "--level", "3", "--directions", "32",
                           "--json", "--smoothing", "0.05"});
    ASSERT_EQ(c.exitCode, 0) << c.err;
    EXPECT_EQ(nlohmann::json::parse(c.out)["smoothing"], 0.05);
    // Wider than 16 edges of the level's cells: refused, naming the octree, nothing written.
    const auto wide = dir / "wide.ply";
    const auto d = runCli({"ao", poct.string(), "-o", wide.string(), "--level", "6", "--directions", "8",
                           "--smoothing", "0.9"});
    EXPECT_EQ(d.exitCode, 1);
    EXPECT_NE(d.err.find("more than 16 edges of the level's cells"), std::string::npos) << d.err;
    EXPECT_NE(d.err.find(poct.string()), std::string::npos) << d.err;
    EXPECT_FALSE(fs::exists(wide));
    const auto smoothed = readAoPly(smooth).scalars[0], values = readAoPly(raw).scalars[0];
    ASSERT_EQ(smoothed.size(), values.size());
    double stepsSmoothed = 0, stepsRaw = 0; // between consecutive leaves (neighbours in octree order, mostly)
    std::size_t changed = 0;
    for (std::size_t i = 1; i < values.size(); ++i) {
        stepsSmoothed += std::abs(smoothed[i] - smoothed[i - 1]);
        stepsRaw += std::abs(values[i] - values[i - 1]);
        changed += smoothed[i] != values[i];
    }
    EXPECT_GT(changed, values.size() / 4); // (the open faces read 1 everywhere: unchanged)
    EXPECT_LT(stepsSmoothed, stepsRaw);
    for (const float v : smoothed) ASSERT_TRUE(v >= 0.0f && v <= 1.0f);
}

TEST(CliAo, NormalsTurnedIntoAClosedBoxReadAsIfRightUnlessOneSided)
{
    // The six faces of a 32 cm cube sampled every 1 cm, every normal pointing INTO the cube (as the
    // centroid orientation does on a recess): one-sided, the faces see the cube's inside (dark); by
    // default both sides are measured and the outside is kept: the middle of every face sees its whole
    // hemisphere.
    TempDir dir;
    std::string body;
    std::size_t count = 0;
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side)
            for (int i = 0; i <= 32; ++i)
                for (int k = 0; k <= 32; ++k) {
                    double p[3], n[3] = {0, 0, 0};
                    p[axis] = side * 0.32;
                    p[(axis + 1) % 3] = i * 0.01;
                    p[(axis + 2) % 3] = k * 0.01;
                    n[axis] = side ? -1.0 : 1.0; // inward
                    for (double v : p) body += std::to_string(v) + " ";
                    for (double v : n) body += std::to_string(v) + " ";
                    body += "\n";
                    ++count;
                }
    stylos::test::writeText(dir / "box.ply", "ply\nformat ascii 1.0\nelement vertex " + std::to_string(count) +
                                                 "\nproperty float x\nproperty float y\nproperty float z\n"
                                                 "property float nx\nproperty float ny\nproperty float nz\n"
                                                 "end_header\n" + body);
    const auto both = dir / "both.ply", one = dir / "one.ply";
    const auto run = runCli({"ao", (dir / "box.ply").string(), "-o", both.string(), "--depth", "6", "--json"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(nlohmann::json::parse(run.out)["two_sided"], true);
    const auto oneRun = runCli({"ao", (dir / "box.ply").string(), "-o", one.string(), "--depth", "6", "--one-sided", "--json"});
    ASSERT_EQ(oneRun.exitCode, 0) << oneRun.err;
    EXPECT_EQ(nlohmann::json::parse(oneRun.out)["two_sided"], false);
    const auto a = readAoPly(both), b = readAoPly(one);
    ASSERT_EQ(a.size(), b.size());
    // Leaves in the middle of a face (farther than 4 cm from every edge of the cube).
    std::size_t middle = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        int inner = 0;
        for (int c = 0; c < 3; ++c) {
            const double x = a.positions[3 * i + std::size_t(c)];
            inner += x > 0.04 && x < 0.28;
        }
        if (inner != 2) continue;
        ++middle;
        EXPECT_EQ(a.scalars[0][i], 1.0) << "leaf " << i;
        EXPECT_LT(b.scalars[0][i], 0.3) << "leaf " << i; // the inside, but for grazing directions (measured ≤ 0.22)
    }
    EXPECT_GT(middle, 1000u);
}

/** Runs each case: exit 2, the message (with @p needle) and the usage on stderr, nothing on stdout. */
void expectUsageErrors(const std::vector<std::pair<std::vector<std::string>, std::string>>& cases)
{
    for (const auto& [args, needle] : cases) {
        const auto run = runCli(args);
        EXPECT_EQ(run.exitCode, 2) << args.back() << ": " << run.err;
        EXPECT_EQ(run.err.rfind("stylos-cli: ", 0), 0u) << run.err;
        EXPECT_NE(run.err.find(needle), std::string::npos) << needle << " in " << run.err;
        EXPECT_NE(run.err.find("usage: stylos-cli ao"), std::string::npos) << run.err;
        EXPECT_TRUE(run.out.empty()) << run.out;
    }
}

TEST(CliAo, BadOptionsExitTwoAndWriteNothing)
{
    TempDir dir;
    const auto floor = writeFloor(dir, "floor.ply", 1).string();
    const auto out = (dir / "out.ply").string();
    expectUsageErrors({
        {{"ao", floor}, "needs -o"},
        {{"ao", "-o", out}, "one input"},
        {{"ao", floor, floor, "-o", out}, "one input"},
        {{"ao", floor, "-o", (dir / "out.png").string()}, "out.png"},
        {{"ao", floor, "-o", out, "--directions", "0"}, "--directions"},
        {{"ao", floor, "-o", out, "--directions", "65537"}, "--directions"},
        {{"ao", floor, "-o", out, "--method", "raytrace"}, "raytrace"},
        {{"ao", floor, "-o", out, "--bias", "-1"}, "--bias"},
        {{"ao", floor, "-o", out, "--smoothing", "-1"}, "--smoothing"},
        {{"ao", floor, "-o", out, "--smoothing", "1.5"}, "--smoothing"},
        {{"ao", floor, "-o", out, "--smoothing", "wide"}, "--smoothing"},
        {{"ao", floor, "-o", out, "--smoothing", "0.01", "--receivers", "cells"}, "--smoothing applies to leaf receivers"},
        {{"ao", floor, "-o", out, "--smoothing", "0.01", "--method", "slices"}, "--smoothing applies to leaf receivers"},
        {{"ao", floor, "-o", out, "--upper"}, "--upper"},
    });
    EXPECT_EQ(entriesIn(dir.path()), (std::set<std::string>{"floor.ply"}));
}

TEST(CliAo, OptionsThatDoNotFitTheInputExitTwoAndWriteNothing)
{
    TempDir dir;
    const auto floor = writeFloor(dir, "floor.ply", 1).string();
    const auto poct = buildPoct(floor, dir / "floor.poct", 4).string();
    const auto out = (dir / "out.ply").string();
    expectUsageErrors({
        {{"ao", floor, "-o", out, "--threads", "-2"}, "--threads"},
        {{"ao", floor, "-o", out, "--depth", "0"}, "--depth"},
        {{"ao", floor, "-o", out, "--depth", "4", "--level", "5"}, "--level"},
        {{"ao", floor, "-o", out, "--level", "-1"}, "--level"},
        {{"ao", poct, "-o", out, "--depth", "5"}, "--depth"},
        {{"ao", poct, "-o", out, "--level", "5"}, "levels 0..4 of " + poct},
        {{"ao", floor, "-o", floor}, "replace the input"},
    });
    EXPECT_EQ(entriesIn(dir.path()), (std::set<std::string>{"floor.ply", "floor.poct"}));
}

TEST(CliAo, UnreadableInputsExitOneNamingTheFileAndLeaveNothing)
{
    TempDir dir;
    const auto poct = buildPoct(writeFloor(dir, "floor.ply", 1), dir / "floor.poct", 4);
    stylos::test::writeText(dir / "garbage.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nend_header\n1\n");
    stylos::test::writeText(dir / "empty.xyz", "");
    stylos::test::writeText(dir / "noise.poct", "this is not an octree at all, only text\n");
    auto bytes = stylos::test::readBytes(poct);
    bytes.resize(bytes.size() / 2);
    stylos::test::writeBytes(dir / "half.poct", bytes);
    const auto before = entriesIn(dir.path());

    // Point files go through the octree build (in a folder beside OUT), octrees straight to the reader.
    const std::vector<std::pair<std::string, std::string>> inputs{
        {"missing.ply", ".poct"}, {"garbage.ply", ".ply"}, {"empty.xyz", ".poct"},
        {"noise.poct", ".ply"},   {"half.poct", ".poct"},
    };
    for (const auto& [name, ext] : inputs) {
        const auto run = runCli({"ao", (dir / name).string(), "-o", (dir / ("out" + ext)).string()});
        EXPECT_EQ(run.exitCode, 1) << name << ": " << run.err;
        EXPECT_EQ(run.err.rfind("stylos-cli: " + (dir / name).string(), 0), 0u) << run.err;
        EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
        EXPECT_TRUE(run.out.empty()) << run.out;
    }
    EXPECT_EQ(entriesIn(dir.path()), before);
}

TEST(CliAo, UnwritableOutputExitsOneAndLeavesNothing)
{
    TempDir dir;
    const auto floor = writeFloor(dir, "floor.ply", 1);
    const auto poct = buildPoct(floor, dir / "floor.poct", 4);
    // A folder that does not exist: from a point file (no room for its octree) and from an octree.
    for (const auto& [input, ext] : {std::pair{floor, ".poct"}, std::pair{poct, ".ply"}}) {
        const auto run = runCli({"ao", input.string(), "-o", (dir / "nowhere" / (std::string("out") + ext)).string()});
        EXPECT_EQ(run.exitCode, 1) << run.err;
        EXPECT_NE(run.err.find("nowhere"), std::string::npos) << run.err;
        EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    }
    EXPECT_EQ(entriesIn(dir.path()), (std::set<std::string>{"floor.ply", "floor.poct"}));
}
