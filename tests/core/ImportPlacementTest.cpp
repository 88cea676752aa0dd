// core::scene::placeImport: scans in their own frames set down side by side on the scene's ground, scans of
// one site frame kept at their true relative places with one offset, the first site scan moved near the
// origin by whole metres. Exact poses from known boxes.
#include "stylos/core/scene/ImportPlacement.h"

#include <gtest/gtest.h>

using namespace stylos::core::scene;

namespace {

Eigen::AlignedBox3d box(double x0, double y0, double z0, double x1, double y1, double z1)
{
    return Eigen::AlignedBox3d(Eigen::Vector3d(x0, y0, z0), Eigen::Vector3d(x1, y1, z1));
}

void expectTranslation(const Pose& pose, double x, double y, double z)
{
    const Pose expected = Pose::translation({x, y, z});
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(pose(r, c), expected(r, c), 1e-12) << r << "," << c;
}

} // namespace

TEST(ImportPlacementTest, TheFirstScanNearTheOriginStaysWhereItIs)
{
    expectTranslation(placeImport({}, box(-0.5, -0.5, 0, 0.5, 0.5, 0.4)), 0, 0, 0);
    expectTranslation(placeImport({}, Eigen::AlignedBox3d()), 0, 0, 0); // nothing to place
}

TEST(ImportPlacementTest, ScansInTheirOwnFramesGoSideBySide)
{
    // A drum 1 m wide and 0.4 m high at the origin; a fragment 0.2 × 0.3 × 0.1 m also near the origin in its
    // file. It goes to the drum's +x side, a gap of 0.25 × 1 m (the larger size) away, centred on the drum
    // in y, its bottom on the drum's (z = 0).
    std::vector<PlacedExtent> placed = {{box(-0.5, -0.5, 0, 0.5, 0.5, 0.4), Pose()}};
    const Eigen::AlignedBox3d fragment = box(0.1, 0.2, 0.3, 0.3, 0.5, 0.4);
    const Pose pose = placeImport(placed, fragment);
    // Its box: x from 0.5 + 0.25 = 0.75, y centred on 0, z from 0: shift (0.65, −0.35, −0.3).
    expectTranslation(pose, 0.65, -0.35, -0.3);
    const Eigen::AlignedBox3d there = worldBounds({fragment, pose});
    EXPECT_NEAR(there.min().x(), 0.75, 1e-12);
    EXPECT_NEAR(there.center().y(), 0.0, 1e-12);
    EXPECT_NEAR(there.min().z(), 0.0, 1e-12);

    // A third, the same fragment again: beside the two, after the fragment (x max 0.95), gap 0.25 × 1.45.
    placed.push_back({fragment, pose});
    const Pose third = placeImport(placed, fragment);
    const Eigen::AlignedBox3d thirdBox = worldBounds({fragment, third});
    EXPECT_NEAR(thirdBox.min().x(), 0.95 + 0.25 * 1.45, 1e-12);
    EXPECT_NEAR(thirdBox.min().z(), 0.0, 1e-12);
    EXPECT_FALSE(thirdBox.intersects(there));
}

TEST(ImportPlacementTest, TheSceneBoundsFollowTheFragmentsPoses)
{
    // A fragment turned a quarter about z and moved: its posed bounds, then the next one beside them.
    const Pose turned = Pose::fromTranslationAngles({{10, 0, 2}, {0, 0, M_PI / 2}});
    const PlacedExtent extent{box(0, 0, 0, 2, 1, 1), turned};
    const Eigen::AlignedBox3d b = worldBounds(extent);
    EXPECT_NEAR(b.min().x(), 9, 1e-12);
    EXPECT_NEAR(b.max().x(), 10, 1e-12);
    EXPECT_NEAR(b.min().y(), 0, 1e-12);
    EXPECT_NEAR(b.max().y(), 2, 1e-12);
    EXPECT_NEAR(b.min().z(), 2, 1e-12);
    // Gap 0.25 × 2 (the scene's larger side): x from 10.5; y centred on 1; z from 2.
    expectTranslation(placeImport({extent}, box(0, 0, 0, 1, 1, 1)), 10.5, 0.5, 2);
}

TEST(ImportPlacementTest, SiteScansKeepTheirTruePlacesWithOneOffset)
{
    // A scan in a site frame (UTM-like metres): moved by its centre rounded to whole metres.
    const Eigen::AlignedBox3d first = box(500100.2, 4200050.6, 120.0, 500101.4, 4200051.2, 121.1);
    const Pose offset = placeImport({}, first);
    expectTranslation(offset, -500101, -4200051, -121);
    // A second scan of the same site, a metre away: the same offset, so the two keep their true places.
    const Eigen::AlignedBox3d second = box(500102.5, 4200050.0, 120.0, 500103.0, 4200051.0, 120.5);
    std::vector<PlacedExtent> placed = {{first, offset}};
    expectTranslation(placeImport(placed, second), -500101, -4200051, -121);
    // The same, once the first was moved by the user: the second follows its pose (the frame they share).
    const Pose moved = Pose::translation({-500101 + 3.0, -4200051, -121});
    expectTranslation(placeImport({{first, moved}}, second), -500101 + 3.0, -4200051, -121);
    // A scan of the same site but far from the others (more than the larger diagonal away) goes beside them.
    const Eigen::AlignedBox3d far = box(500200, 4200050, 120, 500201, 4200051, 121);
    const Pose beside = placeImport(placed, far);
    const Eigen::AlignedBox3d firstThere = worldBounds(placed.front()), farThere = worldBounds({far, beside});
    EXPECT_NEAR(farThere.min().x(), firstThere.max().x() + 0.25 * 1.2, 1e-6);
    EXPECT_NEAR(farThere.min().z(), firstThere.min().z(), 1e-6);
    // An object in its own frame is never in a site's frame: beside, not at the site.
    const Pose object = placeImport(placed, box(-0.1, -0.1, 0, 0.1, 0.1, 0.2));
    EXPECT_NEAR(worldBounds({box(-0.1, -0.1, 0, 0.1, 0.1, 0.2), object}).min().x(), firstThere.max().x() + 0.3, 1e-6);
}
