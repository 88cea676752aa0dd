// The CPU print render against the generator's truth: a plain drum (radius 0.2 m, height 0.3 m) brought to
// its own frame (axis +Z) seen from the front at 1 mm per pixel spans its diameter and its height in pixels
// (within the discs' radius), the frame is exactly pixels × pixel size, the near side hides the far side
// (the centre is the front face: bright under the headlight), the top view of the axis is a disc whose
// labels are the upper half's (the nearest leaves), and a too-large frame or a skydome without an "ambient" layer is refused.
#include "SyntheticTestSupport.h"
#include "TestSupport.h"

#include "stylos/core/octree/OctreeBuild.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/plate/OrthoRender.h"

#include <gtest/gtest.h>

#include <fstream>
#include <memory>
#include <numbers>

using namespace stylos::core;
using plate::OrthoOptions;
using plate::OrthoSource;

namespace {

struct Drum {
    std::unique_ptr<stylos::test::TempDir> dir;
    std::unique_ptr<octree::PackedOctree> octree;
    scene::Pose toDrum; ///< file frame → drum frame (axis z, bed at z = 0)
    double radius = 0.2, height = 0.3, spacing = 0.004;
};

const Drum& drum()
{
    static Drum d = [] {
        Drum d;
        d.dir = std::make_unique<stylos::test::TempDir>();
        auto o = stylos::test::coarse(d.spacing, 11);
        o.radius = d.radius;
        o.height = d.height;
        o.grooves = 0;
        o.writeNormals = true;
        const auto ply = *d.dir / "drum.ply";
        const auto report = stylos::test::generate(synth::SyntheticKind::Drum, o, ply);
        std::ifstream truth(report.truthPath);
        const Eigen::Affine3d pose = stylos::test::poseOf(nlohmann::json::parse(truth)).inverse();
        std::array<double, 16> m{};
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) m[std::size_t(4 * r + c)] = pose.matrix()(r, c);
        d.toDrum = scene::Pose(m);
        octree::BuildOptions build;
        build.depth = 8;
        build.threads = 1;
        const auto built = octree::buildOctreeFile(ply, *d.dir / "drum.poct", build);
        EXPECT_TRUE(built.ok()) << (built.ok() ? "" : built.error().message);
        auto opened = octree::PackedOctree::open(*d.dir / "drum.poct");
        if (opened.ok()) d.octree = std::make_unique<octree::PackedOctree>(std::move(opened).value());
        return d;
    }();
    return d;
}

/** First and last non-paper column of row @p y (−1, −1 when none). */
std::pair<int, int> coveredColumns(const plate::PanelImage& image, int y)
{
    int first = -1, last = -1;
    for (int x = 0; x < image.width; ++x)
        if (image.sample(x, y) != 65535) {
            if (first < 0) first = x;
            last = x;
        }
    return {first, last};
}

} // namespace

TEST(OrthoRender, FrontViewSpansTheTrueDiameterAndHeight)
{
    const Drum& d = drum();
    ASSERT_TRUE(d.octree);
    OrthoSource s{d.octree.get(), d.toDrum, {}};
    OrthoOptions o;
    o.view = view::StandardView::Front;
    o.pixelSizeM = 0.001;
    const auto r = plate::renderOrtho(std::span(&s, 1), o);
    ASSERT_TRUE(r.ok()) << r.error().message;
    const plate::PanelImage& img = r->image;
    EXPECT_DOUBLE_EQ(r->extentM[0], img.width * 0.001);
    EXPECT_DOUBLE_EQ(r->extentM[1], img.height * 0.001);
    EXPECT_EQ(r->leaves, d.octree->cellCount(d.octree->depth()));
    // Discs reach at most their radius (the largest leaf spacing) past the true silhouette.
    float maxSpacing = 0;
    for (std::uint64_t i = 0; i < r->leaves; ++i) maxSpacing = std::max(maxSpacing, d.octree->leafSpacing(i));
    const double slack = maxSpacing / 0.001 + 2;
    EXPECT_NEAR(img.width, 2 * d.radius / 0.001, 2 * slack);
    EXPECT_NEAR(img.height, d.height / 0.001, 2 * slack);
    const auto [first, last] = coveredColumns(img, img.height / 2);
    EXPECT_NEAR(last - first + 1, 2 * d.radius / 0.001, 2 * slack);
    // The near face is drawn: at the centre the surface faces the viewer (headlight near white).
    EXPECT_GT(img.sample(img.width / 2, img.height / 2), 0.9 * 65535);
    EXPECT_TRUE(img.classes.empty());
}

TEST(OrthoRender, TopViewIsADiscAndLabelsFollowTheNearestLeaf)
{
    const Drum& d = drum();
    ASSERT_TRUE(d.octree);
    const std::uint64_t leaves = d.octree->cellCount(d.octree->depth());
    // Class 2 on the upper half of the drum, 1 below: from the top only class 2 shows.
    std::vector<std::uint8_t> labels(leaves, 1);
    d.octree->forEachCell(d.octree->depth(), [&](const octree::CellView& c) {
        if (d.toDrum.apply(c.centre)[2] > 0.5 * d.height) labels[c.index] = 2;
        return true;
    });
    OrthoSource s{d.octree.get(), d.toDrum, labels};
    OrthoOptions o;
    o.view = view::StandardView::Top;
    o.pixelSizeM = 0.002;
    o.keepClasses = true;
    const auto r = plate::renderOrtho(std::span(&s, 1), o);
    ASSERT_TRUE(r.ok()) << r.error().message;
    const plate::PanelImage& img = r->image;
    ASSERT_EQ(img.classes.size(), std::size_t(img.width) * std::size_t(img.height));
    std::size_t one = 0, two = 0;
    for (const auto c : img.classes) one += c == 1, two += c == 2;
    // The lower half shows only where the upper half is missing (the generator's broken region, the rim).
    EXPECT_GT(two, 0u);
    EXPECT_LT(double(one), 0.02 * double(two));
    // A disc: the drawn area lies between π R² and π (R + r)², r the largest disc radius.
    float maxSpacing = 0;
    for (std::uint64_t i = 0; i < leaves; ++i) maxSpacing = std::max(maxSpacing, d.octree->leafSpacing(i));
    std::size_t drawn = 0;
    for (const auto v : img.samples) drawn += v != 65535;
    EXPECT_GT(double(drawn), 0.98 * std::numbers::pi * std::pow(d.radius / 0.002, 2));
    EXPECT_LT(double(drawn), std::numbers::pi * std::pow((d.radius + maxSpacing) / 0.002 + 1, 2));
}

TEST(OrthoRender, RefusesTooLargeFramesAndAMissingSkydome)
{
    const Drum& d = drum();
    ASSERT_TRUE(d.octree);
    OrthoSource s{d.octree.get(), d.toDrum, {}};
    OrthoOptions o;
    o.pixelSizeM = 0.00001; // 40 000 px across
    o.maxPixels = 1'000'000;
    auto r = plate::renderOrtho(std::span(&s, 1), o);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::OutOfBudget);
    EXPECT_NE(r.error().message.find("Mpx limit"), std::string::npos) << r.error().message;
    o.pixelSizeM = 0.002;
    o.shading = plate::PanelShading::Skydome;
    r = plate::renderOrtho(std::span(&s, 1), o);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("ambient"), std::string::npos);
    EXPECT_NE(r.error().message.find("drum.poct"), std::string::npos);
    OrthoSource wrong{d.octree.get(), d.toDrum, std::vector<std::uint8_t>(3, 1)};
    o.shading = plate::PanelShading::Headlight;
    EXPECT_EQ(plate::renderOrtho(std::span(&wrong, 1), o).error().code, ErrorCode::InvalidArgument);
}

TEST(OrthoRender, ACameraOrientationIsItsStandardSideAndTurnsTheFrame)
{
    const Drum& d = drum();
    ASSERT_TRUE(d.octree);
    OrthoSource s{d.octree.get(), d.toDrum, {}};
    OrthoOptions o;
    o.pixelSizeM = 0.003;
    o.view = view::StandardView::Right;
    const auto side = plate::renderOrtho(std::span(&s, 1), o);
    o.orientation = view::Camera::standardOrientation(view::StandardView::Right);
    const auto camera = plate::renderOrtho(std::span(&s, 1), o);
    ASSERT_TRUE(side.ok() && camera.ok());
    EXPECT_EQ(side->image.samples, camera->image.samples);
    // Rolled 90° about the viewing direction: width and height swap.
    o.orientation = *o.orientation * Eigen::Quaterniond(Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitZ()));
    const auto rolled = plate::renderOrtho(std::span(&s, 1), o);
    ASSERT_TRUE(rolled.ok());
    EXPECT_NEAR(rolled->image.width, side->image.height, 2);
    EXPECT_NEAR(rolled->image.height, side->image.width, 2);

    plate::PanelSpec panel;
    panel.view = plate::PanelView::Camera;
    panel.scale = 10;
    panel.shading = plate::PanelShading::Headlight;
    plate::PlateSpec spec;
    spec.panels = {panel};
    EXPECT_FALSE(spec.validate("p.json").ok()); // no orientation
    spec.panels[0].camera = std::array<double, 4>{2, 0, 0, 0};
    EXPECT_FALSE(spec.validate("p.json").ok()); // not unit
    spec.panels[0].camera = std::array<double, 4>{1, 0, 0, 0};
    EXPECT_TRUE(spec.validate("p.json").ok());
    const auto back = plate::PlateSpec::fromJson(spec.toJson(), "p.json");
    ASSERT_TRUE(back.ok());
    EXPECT_EQ(back.value(), spec);
}
