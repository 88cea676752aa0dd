// stylos-cli annotate and export on a generated plain drum: the --json keys of the contract, labels in the
// output octree (new file and in place), the PLY properties; bad raster size, unknown class id, missing map,
// bad legend → exit 1 naming the file and nothing written; usage errors → exit 2.
#include "../core/AnnotationTestSupport.h"
#include "CliRunner.h"

#include "stylos/core/annotation/LabelRaster.h"
#include "stylos/core/annotation/LeafLabels.h"
#include "stylos/core/io/PointFileFormat.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>

using stylos::test::runCli;
using stylos::test::TempDir;
namespace ann = stylos::core::annotation;
namespace oct = stylos::core::octree;
namespace fs = std::filesystem;

namespace {

fs::path paint(const TempDir& dir, const ann::LabelRaster& raster, const std::string& name = "labels.png")
{
    EXPECT_TRUE(ann::writeLabelRaster(raster, dir / name, 0.001).ok());
    return dir / name;
}

std::vector<std::string> annotateArgs(const fs::path& in, const fs::path& raster, const fs::path& map, const fs::path& out)
{
    return {"annotate", in.string(), "--layer", "material", "--raster", raster.string(), "--map", map.string(), "-o", out.string(), "--json"};
}

std::vector<std::uint8_t> labelsOf(const fs::path& poct, ann::AnnotationLayer layer)
{
    auto octree = oct::PackedOctree::open(poct);
    EXPECT_TRUE(octree.ok());
    return octree.ok() ? ann::readLeafLabels(*octree, layer).value() : std::vector<std::uint8_t>{};
}

} // namespace

TEST(CliAnnotate, LabelsTheRectangleAndReportsTheContractKeys)
{
    const auto& d = stylos::test::annotatedDrum();
    TempDir dir;
    const auto raster = paint(dir, d.rectangle(2));
    const auto run = runCli(annotateArgs(d.poct, raster, d.sidecar, dir / "out.poct"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const auto j = nlohmann::json::parse(run.out);
    ASSERT_TRUE(j.contains("classes"));
    ASSERT_EQ(j["classes"].size(), 4u);
    for (const auto& c : j["classes"]) {
        std::set<std::string> keys;
        for (auto it = c.begin(); it != c.end(); ++it) keys.insert(it.key());
        EXPECT_EQ(keys, (std::set<std::string>{"id", "name", "cells", "area_m2"}));
    }
    EXPECT_EQ(j["classes"][1]["id"], 2);
    EXPECT_EQ(j["classes"][1]["name"], "fractured marble");
    const auto labels = labelsOf(dir / "out.poct", ann::AnnotationLayer::Material);
    const auto twos = std::uint64_t(std::count(labels.begin(), labels.end(), 2));
    EXPECT_GT(twos, 500u);
    EXPECT_EQ(j["classes"][1]["cells"].get<std::uint64_t>(), twos);
    EXPECT_EQ(j["classes"][0]["cells"], 0);
    EXPECT_NEAR(j["classes"][1]["area_m2"].get<double>() / d.rectangleArea(), 1.0, 0.02);
    EXPECT_EQ(j["changed"].get<std::uint64_t>(), twos);
    EXPECT_EQ(run.err.find("warning"), std::string::npos) << run.err; // the drum's own map: nothing to say
    // A map made elsewhere (the same drum's, moved 2 m along x: another object's) is said to be one.
    nlohmann::json moved = nlohmann::json::parse(std::ifstream(d.sidecar));
    moved["surface"]["axis_point"][0] = moved["surface"]["axis_point"][0].get<double>() + 2.0;
    std::ofstream(dir / "moved.json") << moved.dump();
    const auto other = runCli(annotateArgs(d.poct, raster, dir / "moved.json", dir / "other.poct"));
    ASSERT_EQ(other.exitCode, 0) << other.err;
    EXPECT_NE(other.err.find("warning: only 16 of the 144 painted pixels"), std::string::npos) << other.err;
    EXPECT_NE(other.err.find("was " + (dir / "moved.json").string() + " made from this octree's développée?"),
              std::string::npos) << other.err;
    // The input is untouched.
    const auto before = labelsOf(d.poct, ann::AnnotationLayer::Material);
    EXPECT_EQ(std::count(before.begin(), before.end(), 0), std::ptrdiff_t(before.size()));

    // A plate of the labelled octree draws its classes; of one without the layer, it says it shows none.
    const std::string note = "has no material layer: the plate shows no classes";
    const auto labelled = runCli({"plate", (dir / "out.poct").string(), "-o", (dir / "l.png").string(), "--scale", "20",
                                  "--dpi", "72", "--layer", "material"});
    ASSERT_EQ(labelled.exitCode, 0) << labelled.err;
    EXPECT_EQ(labelled.err.find(note), std::string::npos) << labelled.err;
    const auto bare = runCli({"plate", d.poct.string(), "-o", (dir / "b.png").string(), "--scale", "20", "--dpi", "72",
                              "--layer", "material"});
    ASSERT_EQ(bare.exitCode, 0) << bare.err;
    EXPECT_NE(bare.err.find(d.poct.filename().string() + " " + note), std::string::npos) << bare.err;
}

TEST(CliAnnotate, InPlaceAddsToEarlierLabels)
{
    const auto& d = stylos::test::annotatedDrum();
    TempDir dir;
    fs::copy_file(d.poct, dir / "drum.poct");
    ASSERT_EQ(runCli(annotateArgs(dir / "drum.poct", paint(dir, d.rectangle(2)), d.sidecar, dir / "drum.poct")).exitCode, 0);
    ann::LabelRaster second(d.map->width(), d.map->height());
    second.at(0, d.r0) = 3;
    const auto run = runCli(annotateArgs(dir / "drum.poct", paint(dir, second, "b.tif"), d.sidecar, dir / "drum.poct"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const auto labels = labelsOf(dir / "drum.poct", ann::AnnotationLayer::Material);
    EXPECT_GT(std::count(labels.begin(), labels.end(), 2), 500);
    EXPECT_GT(std::count(labels.begin(), labels.end(), 3), 0);
    EXPECT_EQ(fs::directory_iterator(dir.path()) == fs::directory_iterator(), false);
}

TEST(CliAnnotate, BadInputExitsOneAndWritesNothing)
{
    const auto& d = stylos::test::annotatedDrum();
    TempDir dir;
    const auto out = dir / "out.poct";
    auto expectFailure = [&](const std::vector<std::string>& args, const std::string& named) {
        const auto run = runCli(args);
        EXPECT_EQ(run.exitCode, 1) << run.err;
        EXPECT_NE(run.err.find(named), std::string::npos) << run.err;
        EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
        EXPECT_FALSE(fs::exists(out));
    };
    expectFailure(annotateArgs(d.poct, paint(dir, ann::LabelRaster(d.map->width() + 1, d.map->height()), "wide.png"), d.sidecar, out),
                  "wide.png");
    ann::LabelRaster unknown = d.rectangle(2);
    unknown.at(1, 1) = 9;
    expectFailure(annotateArgs(d.poct, paint(dir, unknown, "nine.png"), d.sidecar, out), "nine.png: pixel (1, 1): class id 9");
    expectFailure(annotateArgs(d.poct, paint(dir, d.rectangle(2)), dir / "missing.png.json", out), "missing.png.json");
    stylos::test::writeText(dir / "bad.json", "{}");
    expectFailure(annotateArgs(d.poct, paint(dir, d.rectangle(2)), dir / "bad.json", out), "bad.json");
    auto withLegend = annotateArgs(d.poct, paint(dir, d.rectangle(2)), d.sidecar, out);
    withLegend.insert(withLegend.end(), {"--legend", (dir / "bad.json").string()});
    expectFailure(withLegend, "bad.json: format");
    expectFailure(annotateArgs(dir / "none.poct", paint(dir, d.rectangle(2)), d.sidecar, out), "none.poct");
}

TEST(CliAnnotate, UsageErrorsExitTwo)
{
    const auto& d = stylos::test::annotatedDrum();
    TempDir dir;
    auto args = annotateArgs(d.poct, paint(dir, d.rectangle(2)), d.sidecar, dir / "out.poct");
    args[3] = "colour";
    EXPECT_EQ(runCli(args).exitCode, 2);
    EXPECT_EQ(runCli({"annotate", d.poct.string(), "-o", (dir / "out.poct").string()}).exitCode, 2);
    EXPECT_EQ(runCli({"annotate", "--help"}).exitCode, 0);
    EXPECT_FALSE(fs::exists(dir / "out.poct"));
}

TEST(CliExport, PlyHasTheLayersWithTheirValues)
{
    const auto& d = stylos::test::annotatedDrum();
    TempDir dir;
    ASSERT_EQ(runCli(annotateArgs(d.poct, paint(dir, d.rectangle(2)), d.sidecar, dir / "a.poct")).exitCode, 0);
    const auto run = runCli({"export", (dir / "a.poct").string(), "-o", (dir / "a.ply").string(), "--layers", "material,toolmark", "--json"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const auto j = nlohmann::json::parse(run.out);
    const auto material = labelsOf(dir / "a.poct", ann::AnnotationLayer::Material);
    EXPECT_EQ(j["points"].get<std::size_t>(), material.size());
    EXPECT_EQ(j["layers"], nlohmann::json({"material", "toolmark"}));
    EXPECT_TRUE(j.contains("seconds"));
    EXPECT_EQ(j["output"], (dir / "a.ply").string());

    auto reader = stylos::core::io::openPointReader(dir / "a.ply");
    ASSERT_TRUE(reader.ok()) << reader.error().message;
    EXPECT_EQ((*reader)->header().schema.scalarNames, (std::vector<std::string>{"material", "toolmark"}));
    auto all = stylos::test::readAllPoints(**reader, 1 << 22);
    ASSERT_TRUE(all.ok());
    ASSERT_EQ(all->size(), material.size());
    for (std::size_t i = 0; i < material.size(); ++i) {
        ASSERT_EQ(all->scalars[0][i], double(material[i])) << i;
        ASSERT_EQ(all->scalars[1][i], 0.0) << i;
    }
    const auto header = stylos::test::readBytes(dir / "a.ply");
    const std::string text(header.begin(), header.begin() + 400);
    EXPECT_NE(text.find("property uchar material"), std::string::npos) << text;
}

TEST(CliExport, BadInputAndUsage)
{
    const auto& d = stylos::test::annotatedDrum();
    TempDir dir;
    const auto noAmbient = runCli({"export", d.poct.string(), "-o", (dir / "x.ply").string(), "--layers", "ambient"});
    EXPECT_EQ(noAmbient.exitCode, 1);
    EXPECT_NE(noAmbient.err.find("drum.poct"), std::string::npos) << noAmbient.err;
    EXPECT_EQ(runCli({"export", (dir / "none.poct").string(), "-o", (dir / "x.ply").string()}).exitCode, 1);
    EXPECT_EQ(runCli({"export", d.poct.string(), "-o", (dir / "x.ply").string(), "--layers", "colour"}).exitCode, 2);
    EXPECT_EQ(runCli({"export", d.poct.string(), "-o", (dir / "x.ply").string(), "--legend", "l.json"}).exitCode, 2);
    EXPECT_EQ(runCli({"export", d.poct.string(), "-o", (dir / "x.txt").string()}).exitCode, 2);
    const auto noLegend = runCli({"export", d.poct.string(), "-o", (dir / "x.las").string(), "--legend", (dir / "none.json").string()});
    EXPECT_EQ(noLegend.exitCode, 1);
    EXPECT_NE(noLegend.err.find("none.json"), std::string::npos) << noLegend.err;
    EXPECT_TRUE(fs::is_empty(dir.path()));
}

TEST(CliExport, LasWithTheLegendsNames)
{
    const auto& d = stylos::test::annotatedDrum();
    TempDir dir;
    const auto legend = (dir / "legend.json").string();
    auto custom = stylos::core::annotation::Legend::defaults();
    custom.material[0].name = "marbre conservé";
    std::ofstream(legend) << custom.toJson().dump();
    const auto las = (dir / "x.las").string();
    const auto run = runCli({"export", d.poct.string(), "-o", las, "--legend", legend, "--json"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const auto j = nlohmann::json::parse(run.out);
    const auto bytes = stylos::test::readBytes(las);
    EXPECT_EQ(std::string(bytes.data(), 4), "LASF");
    EXPECT_EQ(std::uint8_t(bytes[104]), 6);
    const std::string text(bytes.begin(), bytes.end());
    EXPECT_NE(text.find("marbre conserv"), std::string::npos);
    const auto info = runCli({"info", las, "--json"});
    ASSERT_EQ(info.exitCode, 0) << info.err;
    EXPECT_EQ(nlohmann::json::parse(info.out)["points"], j["points"]);
}
