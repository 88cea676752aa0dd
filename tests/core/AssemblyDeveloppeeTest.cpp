// computeAssemblyDeveloppee: a generated fragment docked on a generated drum of its design shows in the
// drum's développée at its place (the pixels of its sector, by its true azimuth), owned by its id; the drum's
// own pixels and the far side own none; bad input is refused.
#include "DockTestSupport.h"

#include "stylos/core/developpee/AssemblyDeveloppee.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace stylos::core::developpee {
namespace {

TEST(AssemblyDeveloppeeTest, AFragmentShowsAtItsPlaceOnTheDrum)
{
    const auto& drum = test::dockDrum(0.004);
    const auto& fragment = test::dockFragment(5, 0.004);
    const unroll::Axis axis = test::trueAxis(drum.truth, 0);
    DeveloppeeOptions options;
    options.axis = axis;
    options.shading = Shading::Height;
    AssemblyPiece piece{&fragment.cloud, test::truePose(fragment, drum), 7};
    auto result = computeAssemblyDeveloppee(drum.cloud, {piece}, options);
    ASSERT_TRUE(result.ok()) << result.error().message;
    const Developpee& d = result->developpee;
    ASSERT_EQ(result->pieceAt.size(), std::size_t(d.map.width()) * std::size_t(d.map.height()));

    // The fragment's pixels: about its outer face's unrolled area (50° of the 0.55 m radius, 0.225..0.5 m high).
    std::size_t owned = 0;
    for (std::uint64_t id : result->pieceAt) {
        EXPECT_TRUE(id == 0 || id == 7);
        owned += id == 7;
    }
    const double s = d.unroll.pixelSize;
    const double faceArea = 0.55 * 2.0 * 0.436 * (0.5 - 0.225);
    EXPECT_NEAR(double(owned) * s * s / faceArea, 1.0, 0.15) << owned << " pixels of " << s * 1e3 << " mm";

    // At its sector's centre (drum frame azimuth thetaCentre, mid-height) the fragment; opposite, the drum.
    const double theta = fragment.truth["fragment"]["thetaCentre"].get<double>();
    const Eigen::Affine3d drumPose = test::affineOf(drum.truth["stations"][0]["toOutput"]);
    const auto pixelAt = [&](double azimuth, double z) {
        const Eigen::Vector3d p = drumPose * Eigen::Vector3d(0.55 * std::cos(azimuth), 0.55 * std::sin(azimuth), z);
        const auto hit = d.map.pixelOf(p);
        EXPECT_TRUE(hit.has_value());
        return hit ? result->pieceOf(int(hit->column), int(hit->row)) : 99;
    };
    EXPECT_EQ(pixelAt(theta, 0.36), 7u);
    EXPECT_EQ(pixelAt(theta + std::numbers::pi, 0.36), 0u);
    EXPECT_EQ(pixelAt(theta, 0.1), 0u); // below the fragment's lower break: the drum
    EXPECT_EQ(result->pieceOf(-1, 0), 0u);
}

TEST(AssemblyDeveloppeeTest, RefusesNoAxisAndPiecesWithoutAnId)
{
    const auto& drum = test::dockDrum(0.004);
    DeveloppeeOptions options;
    auto noAxis = computeAssemblyDeveloppee(drum.cloud, {}, options);
    ASSERT_FALSE(noAxis.ok());
    EXPECT_NE(noAxis.error().message.find("needs the drum's axis"), std::string::npos);
    options.axis = test::trueAxis(drum.truth, 0);
    auto noId = computeAssemblyDeveloppee(drum.cloud, {AssemblyPiece{&drum.cloud, Eigen::Isometry3d::Identity(), 0}}, options);
    ASSERT_FALSE(noId.ok());
    EXPECT_EQ(noId.error().code, ErrorCode::InvalidArgument);
}

} // namespace
} // namespace stylos::core::developpee
