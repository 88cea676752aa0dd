// Plate model in millimetres: scale bars from {1, 2, 5}·10^k within 20–60 mm at every scale, the layout file's
// round trip and its errors by key, page names, and the packing (exact image places, a too-large panel named
// with the scale that would fit, nothing placed then).
#include "stylos/core/plate/PlateLayout.h"
#include "stylos/core/plate/ScaleBar.h"
#include "stylos/core/scene/ProjectFile.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace stylos::core::plate;

TEST(ScaleBar, PicksTheNiceLengthNearestFortyMillimetres)
{
    const ScaleBar ten = chooseScaleBar(10);
    EXPECT_DOUBLE_EQ(ten.lengthM, 0.5);
    EXPECT_DOUBLE_EQ(ten.lengthMm, 50.0);
    EXPECT_EQ(ten.segments, 5);
    EXPECT_EQ(ten.unit, "cm");
    EXPECT_EQ(ten.tickLabel(0), "0");
    EXPECT_EQ(ten.tickLabel(1), "10");
    EXPECT_EQ(ten.tickLabel(5), "50 cm");

    const ScaleBar three = chooseScaleBar(3);
    EXPECT_DOUBLE_EQ(three.lengthM, 0.1);
    EXPECT_DOUBLE_EQ(three.lengthMm, 0.1 * 1000.0 / 3.0);

    const ScaleBar fifty = chooseScaleBar(50);
    EXPECT_DOUBLE_EQ(fifty.lengthM, 2.0);
    EXPECT_EQ(fifty.segments, 4);
    EXPECT_EQ(fifty.unit, "m");
    EXPECT_EQ(fifty.tickLabel(1), "0.5");

    const ScaleBar half = chooseScaleBar(0.5); // 2:1 enlargement of a small find
    EXPECT_DOUBLE_EQ(half.lengthM, 0.02);
    EXPECT_EQ(half.unit, "cm");
    EXPECT_EQ(chooseScaleBar(0.1).unit, "mm");

    EXPECT_EQ(chooseScaleBar(0).segments, 0);
    EXPECT_EQ(chooseScaleBar(-3).segments, 0);
    EXPECT_EQ(chooseScaleBar(std::nan("")).segments, 0);
}

TEST(ScaleBar, HoldsAtEveryScale)
{
    for (double n = 1; n <= 200000; n *= 1.0173) {
        const ScaleBar bar = chooseScaleBar(n);
        ASSERT_GE(bar.segments, 2) << n;
        EXPECT_GE(bar.lengthMm, kScaleBarMinMm - 1e-9) << n;
        EXPECT_LE(bar.lengthMm, kScaleBarMaxMm + 1e-9) << n;
        EXPECT_DOUBLE_EQ(bar.lengthMm, bar.lengthM * 1000.0 / n) << n;
        const double mantissa = bar.lengthM / std::pow(10.0, std::floor(std::log10(bar.lengthM) + 1e-9));
        EXPECT_TRUE(std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 2) < 1e-9 || std::abs(mantissa - 5) < 1e-9) << n;
    }
}

TEST(PlateSpec, PageNamesAndOrientation)
{
    EXPECT_DOUBLE_EQ(pageFromName("a4")->widthMm, 210);
    EXPECT_DOUBLE_EQ(pageFromName("A3")->heightMm, 420);
    EXPECT_DOUBLE_EQ(pageFromName("letter")->widthMm, 215.9);
    EXPECT_DOUBLE_EQ(pageFromName("170x105")->heightMm, 105);
    EXPECT_DOUBLE_EQ(pageFromName("200.5X150")->widthMm, 200.5);
    EXPECT_FALSE(pageFromName("A5"));
    EXPECT_FALSE(pageFromName("5x150"));
    EXPECT_FALSE(pageFromName("200x"));
    PlateSpec s;
    s.landscape = true;
    EXPECT_DOUBLE_EQ(s.orientedPage().widthMm, 297);
    s.pageName = "170x105";
    s.page = *pageFromName(s.pageName);
    s.landscape = false;
    EXPECT_DOUBLE_EQ(s.orientedPage().widthMm, 170); // a print area keeps its stated orientation
    s.landscape = true; // turned (the plate dialog's "Turned")
    EXPECT_DOUBLE_EQ(s.orientedPage().widthMm, 105);
    EXPECT_DOUBLE_EQ(s.orientedPage().heightMm, 170);
}

TEST(PlateSpec, LayoutFileRoundTripAndErrorsByKey)
{
    PlateSpec s;
    s.pageName = "A3";
    s.page = *pageFromName("A3");
    s.landscape = true;
    s.dpi = 1200;
    s.caption = "Drum 2, développée";
    PanelSpec a;
    a.scale = 5;
    a.layer = stylos::core::annotation::AnnotationLayer::Material;
    a.hatches = true;
    PanelSpec b;
    b.view = PanelView::Top;
    b.scale = 20;
    b.shading = PanelShading::Headlight;
    b.fragment = "Drum 2";
    b.atMm = std::array<double, 2>{30, 200};
    s.panels = {a, b};
    const auto back = PlateSpec::fromJson(s.toJson(), "p.json");
    ASSERT_TRUE(back.ok()) << back.error().message;
    EXPECT_EQ(back.value(), s);

    auto bad = s.toJson();
    bad["panels"][1]["scale"] = 0.5;
    auto r = PlateSpec::fromJson(bad, "p.json");
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("panels[1].scale"), std::string::npos) << r.error().message;
    bad = s.toJson();
    bad["panels"][0]["view"] = "sideways";
    r = PlateSpec::fromJson(bad, "p.json");
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("panels[0].view"), std::string::npos);
    bad = s.toJson();
    bad["panels"][0]["shading"] = "headlight"; // a développée has no headlight
    r = PlateSpec::fromJson(bad, "p.json");
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("panels[0].shading"), std::string::npos);
    bad = s.toJson();
    bad["dpi"] = 20000;
    EXPECT_FALSE(PlateSpec::fromJson(bad, "p.json").ok());
    bad = s.toJson();
    bad.erase("panels");
    EXPECT_FALSE(PlateSpec::fromJson(bad, "p.json").ok());
    // Keys it does not know, misspelt ones first, are named rather than left at the defaults.
    bad = s.toJson();
    bad["pagee"] = "A4";
    r = PlateSpec::fromJson(bad, "p.json");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().message, "p.json: pagee: is not a key of a plate layout (a misspelling?)");
    bad = s.toJson();
    bad["panels"][1]["scael"] = 5;
    r = PlateSpec::fromJson(bad, "p.json");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().message, "p.json: panels[1].scael: is not a key of a plate layout (a misspelling?)");
    EXPECT_EQ(PlateSpec::read("/no/such/plate.json").error().code, stylos::core::ErrorCode::NotFound);
}

TEST(PlateLayout, PlacesImagesAtTheirExactSizeAndCentres)
{
    PlateSpec s; // A4 portrait, 15 mm margins: a 180 × 267 mm print area
    PanelSpec p;
    p.scale = 10;
    s.panels = {p};
    const std::array<double, 2> size{100.0, 50.0};
    const auto layout = layoutPlate(s, std::span(&size, 1), 0, 0);
    ASSERT_TRUE(layout.ok()) << layout.error().message;
    const PanelBox& box = layout->panels[0];
    EXPECT_DOUBLE_EQ(box.image.x, 15 + (180 - 100) / 2.0);
    EXPECT_DOUBLE_EQ(box.image.y, 15 + kLetterBandMm);
    EXPECT_DOUBLE_EQ(box.image.w, 100);
    EXPECT_DOUBLE_EQ(box.image.h, 50);
    EXPECT_TRUE(box.letter.empty());
    EXPECT_TRUE(box.ruler);
    EXPECT_DOUBLE_EQ(box.barRect.w, 50.0); // 0.5 m at 1:10
    EXPECT_EQ(box.scaleText, "1:10");
    EXPECT_EQ(scaleText(1e6), "1:1000000");
    EXPECT_EQ(scaleText(12.5), "1:12.5");
    EXPECT_DOUBLE_EQ(layout->legend.h, 0);
}

TEST(PlateLayout, PacksPanelsInRowsWithLetters)
{
    PlateSpec s;
    PanelSpec front;
    front.view = PanelView::Front;
    front.scale = 10;
    PanelSpec side = front;
    side.view = PanelView::Right;
    s.panels = {front, side};
    const std::array<std::array<double, 2>, 2> sizes{{{80, 60}, {70, 60}}};
    const auto layout = layoutPlate(s, sizes, 3, 10);
    ASSERT_TRUE(layout.ok()) << layout.error().message;
    const auto& a = layout->panels[0];
    const auto& b = layout->panels[1];
    EXPECT_EQ(a.letter, "A");
    EXPECT_EQ(b.letter, "B");
    EXPECT_DOUBLE_EQ(a.image.y, b.image.y); // one row: 80 + 6 + 70 ≤ 180
    EXPECT_DOUBLE_EQ(a.image.x, 15 + (180 - 156) / 2.0);
    EXPECT_DOUBLE_EQ(b.image.x, a.image.right() + kPanelGapMm);
    EXPECT_FALSE(a.ruler);
    EXPECT_DOUBLE_EQ(layout->legend.h, 3 * kLegendRowMm);
    EXPECT_GT(layout->legend.y, a.barRect.bottom());
    EXPECT_GT(layout->caption.y, layout->legend.bottom());
}

TEST(PlateLayout, RefusesWhatDoesNotFitAndNamesTheScaleThatWould)
{
    PlateSpec s;
    PanelSpec p;
    p.scale = 10;
    s.panels = {p};
    const double width = 2 * 3.14159265 * 0.5 * 1000 / 10; // a 0.5 m drum at 1:10: 314.2 mm
    const std::array<double, 2> size{width, 50};
    LayoutFailure failure;
    const auto layout = layoutPlate(s, std::span(&size, 1), 0, 0, {}, &failure);
    ASSERT_FALSE(layout.ok());
    EXPECT_EQ(layout.error().code, stylos::core::ErrorCode::InvalidArgument);
    // The same as values (for the workbench's own words).
    EXPECT_EQ(failure.kind, LayoutFailure::Kind::PanelTooLarge);
    EXPECT_EQ(failure.panel, 0u);
    EXPECT_EQ(failure.sizeMm[0], width);
    EXPECT_EQ(failure.sizeMm[1], 50);
    EXPECT_DOUBLE_EQ(failure.printArea.w, 180);
    EXPECT_DOUBLE_EQ(failure.printArea.h, 267);
    EXPECT_EQ(failure.smallerScale, std::optional<double>(18));
    EXPECT_NE(layout.error().message.find("314.2 × 50.0 mm"), std::string::npos) << layout.error().message;
    EXPECT_NE(layout.error().message.find("180.0 × 267.0 mm"), std::string::npos) << layout.error().message;
    EXPECT_NE(layout.error().message.find("use 1:18"), std::string::npos) << layout.error().message;
    // At the scale it names, it fits.
    s.panels[0].scale = 18;
    const std::array<double, 2> smaller{width * 10 / 18, 50 * 10 / 18.0};
    EXPECT_TRUE(layoutPlate(s, std::span(&smaller, 1), 0, 0, {}, &failure).ok());
    EXPECT_EQ(failure.kind, LayoutFailure::Kind::None); // not the last call's failure
    // Too much height with the caption.
    const std::array<double, 2> tall{100, 230};
    const auto crowded = layoutPlate(s, std::span(&tall, 1), 0, 40, {}, &failure);
    ASSERT_FALSE(crowded.ok());
    EXPECT_EQ(failure.kind, LayoutFailure::Kind::TooTall);
    EXPECT_GT(failure.sizeMm[1], 267);
    EXPECT_NE(crowded.error().message.find("of height"), std::string::npos) << crowded.error().message;
    // A caption that alone takes the print area's height: no scale helps, and none is offered.
    const std::array<double, 2> small{10, 10};
    const auto wordy = layoutPlate(s, std::span(&small, 1), 0, 270, {}, &failure);
    ASSERT_FALSE(wordy.ok());
    EXPECT_EQ(failure.kind, LayoutFailure::Kind::CaptionTooTall);
    EXPECT_DOUBLE_EQ(failure.sizeMm[1], 272.0);
    EXPECT_NE(wordy.error().message.find("the caption alone needs 272.0 mm of height; the A4 print area is 180.0 × 267.0 mm: "
                                         "shorten the caption or use a larger page"),
              std::string::npos) << wordy.error().message;
    EXPECT_EQ(wordy.error().message.find("scale"), std::string::npos) << wordy.error().message;
    // A page too small for the panel's labels alone: no scale to name, only a larger page.
    s.page = {10, 10};
    s.pageName = "10x10";
    s.marginMm = 0;
    const std::array<double, 2> any{110, 112};
    const auto tiny = layoutPlate(s, std::span(&any, 1), 0, 0, {}, &failure);
    ASSERT_FALSE(tiny.ok());
    EXPECT_EQ(failure.kind, LayoutFailure::Kind::PanelTooLarge);
    EXPECT_EQ(failure.smallerScale, std::nullopt);
    EXPECT_NE(tiny.error().message.find("no scale fits this page; use a larger page"), std::string::npos)
        << tiny.error().message;
}

TEST(PlateLayout, APanelTakesTheWidthOfItsLabels)
{
    // A 1:1000 panel whose image is 6 mm wide beside a 1:20 one: its title and bar (50 mm on paper) would run under
    // the next panel if only the image counted.
    PlateSpec s;
    PanelSpec small;
    small.view = PanelView::Developpee;
    small.scale = 1000;
    PanelSpec back;
    back.view = PanelView::Back;
    back.scale = 20;
    s.panels = {small, back};
    const std::array<std::array<double, 2>, 2> sizes{{{6, 2}, {60, 40}}};
    const std::array<double, 2> labels{71.5, 55};
    const auto widths = [](const std::array<double, 2>& w) {
        return PanelLabelWidth([w](std::size_t i, const PanelSpec&) { return w[i]; });
    };
    const auto layout = layoutPlate(s, sizes, 0, 0, widths(labels));
    ASSERT_TRUE(layout.ok()) << layout.error().message;
    const auto& a = layout->panels[0];
    const auto& b = layout->panels[1];
    EXPECT_DOUBLE_EQ(a.image.y, b.image.y); // one row: 71.5 + 6 + 60 ≤ 180
    EXPECT_DOUBLE_EQ(a.image.x, 15 + (180 - (71.5 + 6 + 60)) / 2.0);
    EXPECT_DOUBLE_EQ(b.image.x, a.image.x + 71.5 + kPanelGapMm);
    EXPECT_DOUBLE_EQ(a.image.w, 6); // the image keeps its exact size
    // Without label widths, as before: the image alone.
    const auto bare = layoutPlate(s, sizes, 0, 0);
    ASSERT_TRUE(bare.ok());
    EXPECT_DOUBLE_EQ(bare->panels[1].image.x, bare->panels[0].image.right() + kPanelGapMm);
    // Labels wider than the row left: the next panel goes to a new row.
    const std::array<double, 2> wide{130, 55};
    const auto rows = layoutPlate(s, sizes, 0, 0, widths(wide));
    ASSERT_TRUE(rows.ok());
    EXPECT_GT(rows->panels[1].image.y, rows->panels[0].barRect.bottom());
    // Labels wider than the print area: the row starts at its left edge, never in the margin.
    const std::array<double, 2> wider{200, 55};
    const auto edge = layoutPlate(s, sizes, 0, 0, widths(wider));
    ASSERT_TRUE(edge.ok());
    EXPECT_DOUBLE_EQ(edge->panels[0].image.x, 15.0);
}

TEST(PlateLayout, TheScalesSuggestedFitWithTheirOwnLabels)
{
    // Ten 30 × 78 mm panels at 1:16 on A4 landscape, each with labels as wide as its bar + 9 mm + "1:N": at a
    // smaller scale the bars grow and fewer panels share a row, so the suggestion must measure them again.
    PlateSpec s;
    s.landscape = true;
    PanelSpec p;
    p.view = PanelView::Front;
    p.scale = 16;
    s.panels.assign(10, p);
    const std::vector<std::array<double, 2>> sizes(10, {30, 78});
    const PanelLabelWidth labels = [](std::size_t, const PanelSpec& panel) {
        return chooseScaleBar(panel.scale).lengthMm + 9.0 + 2.0 * double(scaleText(panel.scale).size());
    };
    const auto refused = layoutPlate(s, sizes, 0, 0, labels);
    ASSERT_FALSE(refused.ok());
    const std::string& message = refused.error().message;
    const auto at = message.find("(A 1:");
    ASSERT_NE(at, std::string::npos) << message;
    double scale = 0;
    ASSERT_EQ(std::sscanf(message.c_str() + at, "(A 1:%lf", &scale), 1) << message;
    PlateSpec t = s;
    std::vector<std::array<double, 2>> shrunk = sizes;
    for (std::size_t i = 0; i < t.panels.size(); ++i) {
        t.panels[i].scale = scale;
        shrunk[i] = {30 * 16 / scale, 78 * 16 / scale};
    }
    const auto fits = layoutPlate(t, shrunk, 0, 0, labels);
    EXPECT_TRUE(fits.ok()) << message << " → " << (fits.ok() ? "" : fits.error().message);
}

TEST(PlateLayout, PanelsTooTallTogetherAreGivenScalesThatFit)
{
    // Two panels of 100 × 120 mm at 1:5 and 1:10 on A4 landscape (267 × 180 mm print area): side by side they need
    // 206.5 mm with a 60 mm caption (the message says so): too tall.
    PlateSpec s;
    s.landscape = true;
    PanelSpec a;
    a.scale = 5;
    PanelSpec b = a;
    b.view = PanelView::Front;
    b.scale = 10;
    s.panels = {a, b};
    const std::array<std::array<double, 2>, 2> sizes{{{100, 120}, {100, 120}}};
    LayoutFailure failure;
    const auto refused = layoutPlate(s, sizes, 0, 60, {}, &failure);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(failure.kind, LayoutFailure::Kind::TooTall);
    EXPECT_DOUBLE_EQ(failure.sizeMm[1], 206.5);
    EXPECT_EQ(failure.fittingScales, (std::vector<double>{7, 13})); // as the message says, below
    const std::string& message = refused.error().message;
    EXPECT_NE(message.find("of height"), std::string::npos) << message;
    // "use a smaller scale (A 1:N, B 1:M)": both scales grown by one factor, rounded up; they fit, and no smaller does.
    const auto at = message.find("(A 1:");
    ASSERT_NE(at, std::string::npos) << message;
    double scaleA = 0, scaleB = 0;
    ASSERT_EQ(std::sscanf(message.c_str() + at, "(A 1:%lf, B 1:%lf)", &scaleA, &scaleB), 2) << message;
    EXPECT_GT(scaleA, 5);
    EXPECT_GT(scaleB, 10);
    const auto layoutAt = [&](double sa, double sb) {
        PlateSpec t = s;
        t.panels[0].scale = sa;
        t.panels[1].scale = sb;
        const std::array<std::array<double, 2>, 2> shrunk{
            {{100 * 5 / sa, 120 * 5 / sa}, {100 * 10 / sb, 120 * 10 / sb}}};
        return layoutPlate(t, shrunk, 0, 60);
    };
    EXPECT_TRUE(layoutAt(scaleA, scaleB).ok());
    EXPECT_FALSE(layoutAt(scaleA - 1, scaleB - 2).ok());
    // The height left for the images is 180 − 60 − 2 − 25 = 93 mm: the factor is 120 / 93 → 1:7 and 1:13.
    EXPECT_EQ(scaleA, 7);
    EXPECT_EQ(scaleB, 13);
}

TEST(PlateSpec, TheProjectKeepsItsPlate)
{
    using stylos::core::scene::ProjectFile;
    stylos::core::scene::Scene scene;
    const auto none = ProjectFile::fromJson(ProjectFile::toJson(scene, "/p/a.stylos"), "/p/a.stylos");
    ASSERT_TRUE(none.ok());
    EXPECT_FALSE(none->scene.plate().has_value());
    EXPECT_EQ(ProjectFile::toJson(scene, "/p/a.stylos").find("\"plate\""), std::string::npos);

    PlateSpec plate;
    PanelSpec p;
    p.scale = 25;
    p.layer = stylos::core::annotation::AnnotationLayer::Toolmark;
    plate.panels = {p};
    plate.caption = "Drum 2";
    scene.setPlate(plate);
    const auto back = ProjectFile::fromJson(ProjectFile::toJson(scene, "/p/a.stylos"), "/p/a.stylos");
    ASSERT_TRUE(back.ok()) << back.error().message;
    ASSERT_TRUE(back->scene.plate().has_value());
    EXPECT_EQ(*back->scene.plate(), plate);

    auto json = nlohmann::json::parse(ProjectFile::toJson(scene, "/p/a.stylos"));
    json["plate"]["panels"][0]["layer"] = "paint";
    json["plate"]["scael"] = 20; // a misspelt key too
    // The project opens without the plate it cannot read, says why, and writes the section back as it was.
    const auto bad = ProjectFile::fromJson(json.dump(), "/p/a.stylos");
    ASSERT_TRUE(bad.ok()) << bad.error().message;
    EXPECT_FALSE(bad->scene.plate().has_value());
    ASSERT_TRUE(bad->plateProblem.has_value());
    EXPECT_EQ(bad->plateProblem->code, stylos::core::ErrorCode::Malformed);
    EXPECT_NE(bad->plateProblem->message.find("/p/a.stylos: plate"), std::string::npos) << bad->plateProblem->message;
    EXPECT_NE(bad->plateProblem->message.find("scael"), std::string::npos) << bad->plateProblem->message;
    EXPECT_TRUE(bad->problems.empty());
    EXPECT_EQ(nlohmann::json::parse(bad->scene.unreadPlate()), json["plate"]);
    const auto saved = nlohmann::json::parse(ProjectFile::toJson(bad->scene, "/p/a.stylos"));
    EXPECT_EQ(saved["plate"], json["plate"]);
    EXPECT_EQ(saved["legend"], json["legend"]);

    // A plate set since is what is written; set and undone (no plate again), the unread section comes back.
    auto replaced = bad->scene;
    replaced.setPlate(plate);
    const auto again = ProjectFile::fromJson(ProjectFile::toJson(replaced, "/p/a.stylos"), "/p/a.stylos");
    ASSERT_TRUE(again.ok());
    EXPECT_FALSE(again->plateProblem.has_value());
    ASSERT_TRUE(again->scene.plate().has_value());
    EXPECT_EQ(*again->scene.plate(), plate);
    replaced.setPlate(std::nullopt);
    EXPECT_EQ(nlohmann::json::parse(ProjectFile::toJson(replaced, "/p/a.stylos"))["plate"], json["plate"]);

    // The project's other sections are still checked strictly.
    json["legend"] = 3;
    EXPECT_FALSE(ProjectFile::fromJson(json.dump(), "/p/a.stylos").ok());
}

TEST(PlateLayout, EachLayersClassesFollowItsOwnTitle)
{
    // Material with 2 classes and tool marks with 1, on 3 columns: each title starts a row, its classes beside it.
    // Before, the entries flowed down the columns: "claw chisel" beside "Material / condition", "Tool marks" under.
    const std::vector<int> two{2, 1};
    EXPECT_EQ(legendGrid(two, 3), (std::vector<LegendCell>{{0, 0}, {1, 0}, {2, 0}, {0, 1}, {1, 1}}));
    EXPECT_EQ(legendGridRows(two, 3), 2);
    // More classes than columns: they go on under the first class, never under the title.
    const std::vector<int> many{5};
    EXPECT_EQ(legendGrid(many, 3), (std::vector<LegendCell>{{0, 0}, {1, 0}, {2, 0}, {1, 1}, {2, 1}, {1, 2}}));
    EXPECT_EQ(legendGridRows(many, 3), 3);
    // One column: the title, then a class a row; a layer without classes takes no row.
    const std::vector<int> narrow{1, 0, 2};
    EXPECT_EQ(legendGrid(narrow, 1), (std::vector<LegendCell>{{0, 0}, {0, 1}, {0, 2}, {0, 3}, {0, 4}}));
    EXPECT_EQ(legendGridRows(narrow, 1), 5);
    EXPECT_EQ(legendGridRows(std::vector<int>{}, 3), 0);
}
