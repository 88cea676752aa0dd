// stylos-cli plate as a user runs it: a développée PDF of a generated drum with the contract's JSON keys (page,
// dpi, the panel's image size in mm and px, pixel size, scale bar), the same bytes from two runs (two processes),
// a 3D front view of a point file as PNG, a composed plate from a layout file; usage errors exit 2, bad input
// exits 1 naming the file and the problem and leaves no file.
#include "CliRunner.h"
#include "TestSupport.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <fstream>

using stylos::test::runCli;
using stylos::test::TempDir;
namespace fs = std::filesystem;

namespace {

std::string drum(const TempDir& dir)
{
    const auto path = (dir / "drum.ply").string();
    const auto run = runCli({"generate", "drum", "-o", path, "--spacing", "0.006", "--seed", "4"});
    EXPECT_EQ(run.exitCode, 0) << run.err;
    return path;
}

} // namespace

TEST(PlateCommand, DeveloppeePdfWithTheContractsKeysAndTheSameBytesTwice)
{
    TempDir dir;
    const auto in = drum(dir);
    const auto a = (dir / "a.pdf").string(), b = (dir / "b.pdf").string();
    const auto run = runCli({"plate", in, "-o", a, "--view", "developpee", "--scale", "20", "--dpi", "300",
                             "--landscape", "--caption", "Drum, développée at 1:20", "--json"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const auto j = nlohmann::json::parse(run.out);
    EXPECT_EQ(j["page_mm"], nlohmann::json({297.0, 210.0}));
    EXPECT_EQ(j["dpi"], 300);
    ASSERT_EQ(j["panels"].size(), 1u);
    const auto& p = j["panels"][0];
    EXPECT_EQ(p["view"], "developpee");
    EXPECT_EQ(p["scale"], 20.0);
    EXPECT_DOUBLE_EQ(p["pixel_size_m"].get<double>(), 20 * 0.0254 / 300);
    EXPECT_DOUBLE_EQ(p["scale_bar_m"].get<double>(), 1.0);
    EXPECT_DOUBLE_EQ(p["scale_bar_mm"].get<double>(), 50.0);
    // The image in px is its size in mm at 300 dpi, to the pixel.
    EXPECT_NEAR(p["image_px"][0].get<double>(), p["image_mm"][0].get<double>() / 25.4 * 300, 1.0);
    EXPECT_NEAR(p["image_px"][1].get<double>(), p["image_mm"][1].get<double>() / 25.4 * 300, 1.0);
    EXPECT_TRUE(j.contains("seconds"));
    ASSERT_EQ(runCli({"plate", in, "-o", b, "--view", "developpee", "--scale", "20", "--dpi", "300", "--landscape",
                      "--caption", "Drum, développée at 1:20"})
                  .exitCode,
              0);
    EXPECT_EQ(stylos::test::readBytes(a), stylos::test::readBytes(b));
}

TEST(PlateCommand, FrontViewOfAPointFileAndALayoutFile)
{
    TempDir dir;
    const auto in = drum(dir);
    const auto png = (dir / "front.png").string();
    const auto run = runCli({"plate", in, "-o", png, "--view", "front", "--scale", "10", "--dpi", "150", "--json"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.err.find("headlight"), std::string::npos) << run.err; // no skydome layer: said, not hidden
    EXPECT_TRUE(fs::exists(png));
    const auto j = nlohmann::json::parse(run.out);
    EXPECT_EQ(j["panels"][0]["view"], "front");
    // Nothing is left beside the output (the octree built for the view went with its scratch folder).
    int files = 0;
    for (const auto& e : fs::directory_iterator(dir.path())) files += e.path().filename().string()[0] == '.';
    EXPECT_EQ(files, 0);

    const auto layout = (dir / "plate.json").string();
    std::ofstream(layout) << R"({"page": "A3", "landscape": true, "dpi": 150, "caption": "Two views",
        "panels": [{"view": "developpee", "scale": 20}, {"view": "top", "scale": 20, "shading": "headlight"}]})";
    const auto svg = (dir / "two.svg").string();
    const auto composed = runCli({"plate", in, "--layout", layout, "-o", svg, "--json"});
    ASSERT_EQ(composed.exitCode, 0) << composed.err;
    const auto k = nlohmann::json::parse(composed.out);
    ASSERT_EQ(k["panels"].size(), 2u);
    EXPECT_EQ(k["panels"][1]["view"], "top");
    EXPECT_EQ(k["page_mm"], nlohmann::json({420.0, 297.0}));

    // A layout's 3D panel that states no shading is lit from the viewer where there is no skydome, as the options'
    // panel is (it failed: "has no skydome"); a custom page already landscape stays so with --landscape.
    const auto unstated = (dir / "unstated.json").string();
    std::ofstream(unstated) << R"({"format": "stylos-plate", "version": 1, "page": [300, 200], "dpi": 100,
        "panels": [{"view": "front", "scale": 10}]})";
    const auto lit = runCli({"plate", in, "--layout", unstated, "-o", (dir / "lit.png").string(), "--json"});
    ASSERT_EQ(lit.exitCode, 0) << lit.err;
    EXPECT_NE(lit.err.find("has no skydome layer: the 3D view is lit from the viewer (headlight)"), std::string::npos)
        << lit.err;
    const auto wide = runCli({"plate", in, "--layout", unstated, "--landscape", "-o", (dir / "wide.png").string(), "--json"});
    ASSERT_EQ(wide.exitCode, 0) << wide.err;
    EXPECT_EQ(nlohmann::json::parse(wide.out)["page_mm"], nlohmann::json({300.0, 200.0}));
}

TEST(PlateCommand, UsageErrorsAndBadInput)
{
    TempDir dir;
    const auto out = (dir / "p.pdf").string();
    EXPECT_EQ(runCli({"plate", "x.ply", "-o", out}).exitCode, 2);                        // no --scale
    EXPECT_EQ(runCli({"plate", "x.ply", "-o", out, "--scale", "10", "--view", "side"}).exitCode, 2);
    EXPECT_EQ(runCli({"plate", "x.ply", "-o", (dir / "p.jpg").string(), "--scale", "10"}).exitCode, 2);
    EXPECT_EQ(runCli({"plate", "x.ply", "-o", out, "--scale", "10", "--dpi", "5"}).exitCode, 2);
    // Out-of-range values name the option, not a layout key.
    const auto zero = runCli({"plate", "x.ply", "-o", out, "--scale", "0"});
    EXPECT_EQ(zero.exitCode, 2);
    EXPECT_EQ(zero.err.rfind("stylos-cli: --scale must be a number in 1..1000000 (the panel at 1:N) (usage:", 0), 0u)
        << zero.err;
    for (const char* page : {"5x5", "nanx100", "axb"}) {
        const auto small = runCli({"plate", "x.ply", "-o", out, "--scale", "10", "--page", page});
        EXPECT_EQ(small.exitCode, 2) << page;
        EXPECT_NE(small.err.find(std::string("--page WxH: each side must be a number of millimetres in 10..2000, not \"") +
                                 page + "\""),
                  std::string::npos)
            << small.err;
    }
    EXPECT_EQ(runCli({"plate", "x.ply", "-o", out, "--scale", "10", "--view", "front", "--shading", "light"}).exitCode, 2);
    // Said in the options' words, not the layout file's keys ("margin_mm", "panels[0].shading").
    const auto margin = runCli({"plate", "x.ply", "-o", out, "--scale", "10", "--margin", "200"});
    EXPECT_EQ(margin.exitCode, 2);
    EXPECT_NE(margin.err.find("--margin: must be 0..70 mm"), std::string::npos) << margin.err;
    const auto shading = runCli({"plate", "x.ply", "-o", out, "--scale", "10", "--view", "front", "--shading", "height"});
    EXPECT_EQ(shading.exitCode, 2);
    EXPECT_NE(shading.err.find("--shading: a 3D view takes skydome or headlight"), std::string::npos) << shading.err;
    EXPECT_EQ(shading.err.find("panels[0]"), std::string::npos) << shading.err;
    const auto bits = runCli({"plate", "x.ply", "-o", out, "--scale", "10", "--bits", "16"}); // a PDF: not taken
    EXPECT_EQ(bits.exitCode, 2);
    EXPECT_NE(bits.err.find("--bits applies to TIFF and PNG plates"), std::string::npos) << bits.err;

    auto missing = runCli({"plate", (dir / "none.ply").string(), "-o", out, "--scale", "10"});
    EXPECT_EQ(missing.exitCode, 1);
    EXPECT_NE(missing.err.find("none.ply"), std::string::npos) << missing.err;
    // An empty or cut input: its error alone, not first a note that its 3D view is lit from the viewer.
    std::ofstream(dir / "empty.poct").flush();
    std::ofstream(dir / "empty.ply").flush();
    for (const char* name : {"empty.poct", "empty.ply"}) {
        const auto empty = runCli({"plate", (dir / name).string(), "-o", out, "--view", "front", "--scale", "10"});
        EXPECT_EQ(empty.exitCode, 1) << name;
        EXPECT_EQ(empty.err, "stylos-cli: " + (dir / name).string() + ": the file is empty (0 bytes)\n");
    }

    const auto in = drum(dir);
    const auto big = runCli({"plate", in, "-o", out, "--scale", "2"}); // a 3.4 m circumference at 1:2 on A4
    EXPECT_EQ(big.exitCode, 1);
    EXPECT_NE(big.err.find("use 1:"), std::string::npos) << big.err;
    EXPECT_FALSE(fs::exists(out));
    // A project whose fragment's octree is missing: named, with its path; no file.
    const auto project = (dir / "p.stylos").string();
    std::ofstream(project) << R"({"format": "stylos-project", "version": 2, "fragments": [{"id": 1, "name": "Drum 2",
        "octree": "gone.poct", "pose": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]}]})";
    const auto gone = runCli({"plate", project, "-o", out, "--view", "front", "--scale", "10", "--shading", "headlight"});
    EXPECT_EQ(gone.exitCode, 1);
    EXPECT_NE(gone.err.find("Drum 2"), std::string::npos) << gone.err;
    EXPECT_NE(gone.err.find("gone.poct"), std::string::npos) << gone.err;
    EXPECT_FALSE(fs::exists(out));
    const auto other = runCli({"plate", project, "-o", out, "--scale", "10", "--fragment", "Drum 9"});
    EXPECT_EQ(other.exitCode, 1);
    EXPECT_NE(other.err.find("Drum 9"), std::string::npos) << other.err;

    const auto layout = (dir / "bad.json").string();
    std::ofstream(layout) << R"({"panels": [{"view": "front"}]})";
    const auto bad = runCli({"plate", in, "--layout", layout, "-o", out});
    EXPECT_EQ(bad.exitCode, 1);
    EXPECT_NE(bad.err.find("panels[0].scale"), std::string::npos) << bad.err;
    EXPECT_FALSE(fs::exists(out));
}
