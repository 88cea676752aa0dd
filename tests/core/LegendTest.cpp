// Legend: the default vocabulary, JSON round trip, and every bad key named in the error.
#include "stylos/core/annotation/Legend.h"

#include "TestSupport.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <set>

using namespace stylos::core::annotation;

namespace {

std::string errorOf(const nlohmann::json& json)
{
    auto legend = Legend::fromJson(json, "L.json");
    EXPECT_FALSE(legend.ok());
    return legend.ok() ? std::string() : legend.error().message;
}

} // namespace

TEST(Legend, DefaultsAreDistinctAndComplete)
{
    const Legend legend = Legend::defaults();
    ASSERT_EQ(legend.material.size(), 4u);
    ASSERT_EQ(legend.toolmark.size(), 5u);
    EXPECT_EQ(legend.material[2].name, "plaster/restoration");
    EXPECT_EQ(legend.toolmark[2].name, "claw chisel");
    for (AnnotationLayer layer : AllAnnotationLayers) {
        std::set<std::string> colours;
        std::set<Hatch> hatches;
        std::set<int> ids;
        for (const LegendClass& c : legend.classes(layer)) {
            colours.insert(c.colour.toHex());
            hatches.insert(c.hatch);
            ids.insert(c.id);
            EXPECT_GE(c.id, 1);
        }
        EXPECT_EQ(colours.size(), legend.classes(layer).size());
        EXPECT_EQ(hatches.size(), legend.classes(layer).size());
        EXPECT_EQ(ids.size(), legend.classes(layer).size());
    }
    EXPECT_EQ(legend.find(AnnotationLayer::Toolmark, 5)->name, "rasp");
    EXPECT_EQ(legend.find(AnnotationLayer::Material, 5), nullptr);
}

TEST(Legend, NamesRoundTrip)
{
    EXPECT_EQ(layerFromName("material"), AnnotationLayer::Material);
    EXPECT_EQ(layerFromName("toolmark"), AnnotationLayer::Toolmark);
    EXPECT_FALSE(layerFromName("class"));
    for (int h = 0; h <= int(Hatch::Solid); ++h) EXPECT_EQ(hatchFromName(hatchName(Hatch(h))), Hatch(h));
    EXPECT_FALSE(hatchFromName("zigzag"));
}

TEST(Legend, JsonRoundTripIsExact)
{
    Legend legend = Legend::defaults();
    legend.material.push_back({200, "lichen (ICOMOS: biological colonisation)", *stylos::core::scene::Rgb::fromHex("#00ff7f"),
                               Hatch::Solid});
    const auto back = Legend::fromJson(nlohmann::json::parse(legend.toJson().dump()), "mem");
    ASSERT_TRUE(back.ok()) << back.error().message;
    EXPECT_EQ(back.value(), legend);
    EXPECT_EQ(legend.toJson()["layers"]["material"][0]["colour"], "#e8e0c8");
}

TEST(Legend, ReadsAFileAndNamesIt)
{
    stylos::test::TempDir dir;
    stylos::test::writeText(dir / "legend.json", Legend::defaults().toJson().dump(2));
    const auto read = Legend::read(dir / "legend.json");
    ASSERT_TRUE(read.ok()) << read.error().message;
    EXPECT_EQ(read.value(), Legend::defaults());
    const auto missing = Legend::read(dir / "none.json");
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error().code, stylos::core::ErrorCode::NotFound);
    EXPECT_NE(missing.error().message.find("none.json"), std::string::npos);
    stylos::test::writeText(dir / "bad.json", "{\"format\": ");
    const auto bad = Legend::read(dir / "bad.json");
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().message.find("bad.json: line 1, column 12: not valid JSON"), std::string::npos) << bad.error().message;
}

TEST(Legend, EveryBadKeyIsNamed)
{
    const nlohmann::json good = Legend::defaults().toJson();
    auto with = [&](const std::function<void(nlohmann::json&)>& edit) {
        nlohmann::json j = good;
        edit(j);
        return errorOf(j);
    };
    EXPECT_EQ(errorOf(nlohmann::json::array()), "L.json: a legend must be a JSON object");
    EXPECT_EQ(with([](auto& j) { j["format"] = "x"; }), "L.json: format: missing or not \"stylos-legend\"");
    EXPECT_EQ(with([](auto& j) { j["version"] = 2; }), "L.json: version: missing or not 1");
    EXPECT_EQ(with([](auto& j) { j.erase("layers"); }), "L.json: layers: missing or not an object");
    EXPECT_EQ(with([](auto& j) { j["layers"].erase("toolmark"); }), "L.json: layers.toolmark: missing");
    EXPECT_EQ(with([](auto& j) { j["layers"]["material"] = 3; }), "L.json: layers.material: missing or not a list of classes");
    EXPECT_EQ(with([](auto& j) { j["layers"]["material"][1] = 3; }), "L.json: layers.material[1]: not an object");
    EXPECT_EQ(with([](auto& j) { j["layers"]["material"][2]["id"] = 1; }), "L.json: layers.material[2].id: duplicate id 1");
    EXPECT_EQ(with([](auto& j) { j["layers"]["toolmark"][0]["id"] = 0; }),
              "L.json: layers.toolmark[0].id: 0 is reserved for unlabelled cells");
    EXPECT_EQ(with([](auto& j) { j["layers"]["toolmark"][0]["id"] = 256; }), "L.json: layers.toolmark[0].id: 256 is outside 1..255");
    EXPECT_EQ(with([](auto& j) { j["layers"]["toolmark"][0]["id"] = -1; }), "L.json: layers.toolmark[0].id: -1 is outside 1..255");
    EXPECT_EQ(with([](auto& j) { j["layers"]["toolmark"][0]["id"] = 1.5; }), "L.json: layers.toolmark[0].id: missing or not an integer");
    EXPECT_EQ(with([](auto& j) { j["layers"]["toolmark"][1].erase("id"); }), "L.json: layers.toolmark[1].id: missing or not an integer");
    EXPECT_EQ(with([](auto& j) { j["layers"]["material"][3]["name"] = ""; }), "L.json: layers.material[3].name: empty");
    EXPECT_EQ(with([](auto& j) { j["layers"]["material"][3]["name"] = 7; }), "L.json: layers.material[3].name: missing or not a string");
    EXPECT_EQ(with([](auto& j) { j["layers"]["material"][3]["name"] = "unknown"; j["layers"]["material"][2]["name"] = "unknown"; }),
              "L.json: layers.material[3].name: duplicate name \"unknown\"");
    EXPECT_EQ(with([](auto& j) { j["layers"]["material"][0]["colour"] = "red"; }), "L.json: layers.material[0].colour: missing or not \"#rrggbb\"");
    EXPECT_EQ(with([](auto& j) { j["layers"]["material"][0].erase("colour"); }), "L.json: layers.material[0].colour: missing or not \"#rrggbb\"");
    EXPECT_NE(with([](auto& j) { j["layers"]["material"][0]["hatch"] = "zigzag"; }).find("L.json: layers.material[0].hatch: missing or not one of"),
              std::string::npos);
}
