// ImportFrame: the six up axes turned onto +Z by proper rotations (exact coordinates, det +1), the units
// converted to metres (1234 mm is 1.234 m to the last bit), the offset subtracted first, normals rotated and
// never scaled; the names; and the one place it is applied: openPointReader() hands out corrected points,
// so a build, a summary and a load all see them (the Happy Buddha, Y up in its file, stands along Z).
#include "TestSupport.h"

#include "stylos/core/io/ImportFrame.h"
#include "stylos/core/io/PointFileFormat.h"
#include "stylos/core/io/PointFileSummary.h"
#include "stylos/core/octree/OctreeBuild.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/view/GuideGeometry.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <map>

using namespace stylos::core;
using namespace stylos::core::io;

namespace {

using V3 = std::array<double, 3>;

constexpr UpAxis AllAxes[] = {UpAxis::PosX, UpAxis::NegX, UpAxis::PosY, UpAxis::NegY, UpAxis::PosZ, UpAxis::NegZ};

ImportFrame upFrame(UpAxis up)
{
    ImportFrame frame;
    frame.up = up;
    return frame;
}

Eigen::Matrix3d matrix(const ImportFrame& frame)
{
    const auto r = frame.rotation();
    Eigen::Matrix3d m;
    for (int i = 0; i < 9; ++i) m(i / 3, i % 3) = r[std::size_t(i)];
    return m;
}

TEST(ImportFrameTest, ThePoint123GoesWhereTheTableSays)
{
    EXPECT_EQ(upFrame(UpAxis::PosZ).applyToPosition({1, 2, 3}), (V3{1, 2, 3}));
    EXPECT_EQ(upFrame(UpAxis::NegZ).applyToPosition({1, 2, 3}), (V3{1, -2, -3}));
    EXPECT_EQ(upFrame(UpAxis::PosY).applyToPosition({1, 2, 3}), (V3{1, -3, 2}));
    EXPECT_EQ(upFrame(UpAxis::NegY).applyToPosition({1, 2, 3}), (V3{1, 3, -2}));
    EXPECT_EQ(upFrame(UpAxis::PosX).applyToPosition({1, 2, 3}), (V3{-3, 2, 1}));
    EXPECT_EQ(upFrame(UpAxis::NegX).applyToPosition({1, 2, 3}), (V3{3, 2, -1}));
}

TEST(ImportFrameTest, EveryUpAxisIsAProperRotationThatTakesItToPlusZ)
{
    const std::map<UpAxis, Eigen::Vector3d> up = {
        {UpAxis::PosX, {1, 0, 0}}, {UpAxis::NegX, {-1, 0, 0}}, {UpAxis::PosY, {0, 1, 0}},
        {UpAxis::NegY, {0, -1, 0}}, {UpAxis::PosZ, {0, 0, 1}}, {UpAxis::NegZ, {0, 0, -1}}};
    for (const UpAxis axis : AllAxes) {
        const Eigen::Matrix3d r = matrix(upFrame(axis));
        EXPECT_EQ(r.determinant(), 1.0) << upAxisName(axis);
        EXPECT_EQ(r * r.transpose(), Eigen::Matrix3d::Identity()) << upAxisName(axis);
        EXPECT_EQ(r * up.at(axis), Eigen::Vector3d(0, 0, 1)) << upAxisName(axis);
        // rotation() and the point mapping agree.
        const V3 p = upFrame(axis).applyToPosition({0.5, -7, 11});
        EXPECT_EQ(Eigen::Vector3d(p[0], p[1], p[2]), r * Eigen::Vector3d(0.5, -7, 11)) << upAxisName(axis);
    }
}

TEST(ImportFrameTest, UnitsBecomeMetresAndTheOffsetGoesFirst)
{
    ImportFrame mm;
    mm.unit = LengthUnit::Millimetre;
    EXPECT_EQ(mm.applyToPosition({1234, -5, 0.5}), (V3{1.234, -0.005, 0.0005}));
    ImportFrame cm;
    cm.unit = LengthUnit::Centimetre;
    EXPECT_EQ(cm.applyToPosition({250, 1, -3}), (V3{2.5, 0.01, -0.03}));
    EXPECT_EQ(unitsPerMetre(LengthUnit::Metre), 1.0);

    // Site coordinates in millimetres, Y up: the offset in the file's units, then mm → m, then the turn.
    const ImportFrame site{UpAxis::PosY, LengthUnit::Millimetre, {512000000, 2000, 4100000000}};
    EXPECT_EQ(site.applyToPosition({512001234, 2500, 4100000300}), (V3{1.234, -0.3, 0.5}));
    EXPECT_FALSE(site.isIdentity());
    EXPECT_TRUE(ImportFrame{}.isIdentity());
}

TEST(ImportFrameTest, NormalsTurnButAreNeitherScaledNorOffset)
{
    const ImportFrame frame{UpAxis::PosY, LengthUnit::Millimetre, {100, 200, 300}};
    EXPECT_EQ(frame.applyToNormal({0.6f, 0.8f, 0.0f}), (std::array<float, 3>{0.6f, 0.0f, 0.8f}));
    EXPECT_EQ(frame.applyToNormal({0.0f, 0.0f, 1.0f}), (std::array<float, 3>{0.0f, -1.0f, 0.0f}));
    for (const UpAxis axis : AllAxes) {
        const auto r = upFrame(axis).rotation();
        const auto n = upFrame(axis).applyToNormal({0.48f, -0.6f, 0.64f});
        for (int i = 0; i < 3; ++i)
            EXPECT_EQ(n[std::size_t(i)], float(r[std::size_t(3 * i)] * 0.48f + r[std::size_t(3 * i + 1)] * -0.6f +
                                               r[std::size_t(3 * i + 2)] * 0.64f))
                << upAxisName(axis);
    }
}

TEST(ImportFrameTest, BoundsMapOntoBounds)
{
    V3 min{-1, 2, 3}, max{4, 5, 6};
    upFrame(UpAxis::PosY).applyToBounds(min, max);
    EXPECT_EQ(min, (V3{-1, -6, 2}));
    EXPECT_EQ(max, (V3{4, -3, 5}));
}

TEST(ImportFrameTest, NamesRoundTripAndOthersAreRefused)
{
    for (const UpAxis axis : AllAxes) EXPECT_EQ(upAxisFromName(upAxisName(axis)), axis);
    EXPECT_EQ(upAxisFromName("y"), UpAxis::PosY);
    EXPECT_EQ(upAxisFromName("+z"), UpAxis::PosZ);
    EXPECT_EQ(upAxisFromName("-x"), UpAxis::NegX);
    EXPECT_EQ(upAxisFromName("\xE2\x88\x92Y"), UpAxis::NegY);  // "−Y", the Unicode minus
    for (const char* bad : {"", "+", "w", "+W", "xy", "++X", "Y+", "up"}) EXPECT_FALSE(upAxisFromName(bad)) << bad;
    for (const LengthUnit unit : {LengthUnit::Millimetre, LengthUnit::Centimetre, LengthUnit::Metre})
        EXPECT_EQ(lengthUnitFromName(lengthUnitName(unit)), unit);
    EXPECT_EQ(lengthUnitFromName("MM"), LengthUnit::Millimetre);
    for (const char* bad : {"", "km", "inch", "metre", "mmm"}) EXPECT_FALSE(lengthUnitFromName(bad)) << bad;
    EXPECT_EQ(upAxisChoices(), "+X, -X, +Y, -Y, +Z or -Z");
    EXPECT_EQ(lengthUnitChoices(), "mm, cm or m");
}

/** A text scan: positions in mm, Y up, with normals. */
std::filesystem::path writeYUpScan(const stylos::test::TempDir& dir)
{
    const auto path = dir / "yup.xyz";
    stylos::test::writeText(path, "# x y z nx ny nz\n"
                                  "1000 2000 3000 0 1 0\n"
                                  "-500 250 125 0.6 0 0.8\n");
    return path;
}

TEST(ImportFrameTest, OpenPointReaderHandsOutCorrectedPointsAndNormals)
{
    stylos::test::TempDir dir;
    ReadOptions options;
    options.frame = {UpAxis::PosY, LengthUnit::Millimetre, {}};
    auto reader = openPointReader(writeYUpScan(dir), options);
    ASSERT_TRUE(reader.ok()) << reader.error().message;
    auto points = stylos::test::readAllPoints(**reader, 1);
    ASSERT_TRUE(points.ok()) << points.error().message;
    EXPECT_EQ(points->positions, (std::vector<double>{1, -3, 2, -0.5, -0.125, 0.25}));
    EXPECT_EQ(points->normals, (std::vector<float>{0, 0, 1, 0.6f, -0.8f, 0}));
    EXPECT_EQ((*reader)->pointsRead(), 2u);
    EXPECT_EQ((*reader)->header().format, "xyz");
    EXPECT_EQ((*reader)->path(), dir / "yup.xyz");

    // The identity reads the file as it is.
    auto plain = openPointReader(dir / "yup.xyz");
    ASSERT_TRUE(plain.ok());
    auto raw = stylos::test::readAllPoints(**plain, 8);
    ASSERT_TRUE(raw.ok());
    EXPECT_EQ(raw->positions, (std::vector<double>{1000, 2000, 3000, -500, 250, 125}));
}

TEST(ImportFrameTest, AnOctreeBuiltWithTheFrameIsInTheCorrectedFrame)
{
    stylos::test::TempDir dir;
    // A 40 mm × 200 mm × 20 mm slab, Y up, in millimetres, normals along +Z of the file.
    std::string text = "# x y z nx ny nz\n";
    for (int i = 0; i <= 40; i += 2)
        for (int j = 0; j <= 200; j += 2)
            for (int k = 0; k <= 20; k += 10)
                text += std::to_string(i) + " " + std::to_string(j) + " " + std::to_string(k) + " 0 0 1\n";
    stylos::test::writeText(dir / "slab.xyz", text);
    ReadOptions read;
    read.frame = {UpAxis::PosY, LengthUnit::Millimetre, {}};
    octree::BuildOptions options;
    options.depth = 6;
    options.threads = 1;
    auto built = octree::buildOctreeFile(dir / "slab.xyz", dir / "slab.poct", options, nullptr, read);
    ASSERT_TRUE(built.ok()) << built.error().message;
    auto tree = octree::PackedOctree::open(dir / "slab.poct");
    ASSERT_TRUE(tree.ok()) << tree.error().message;
    // The root box is the cube around the corrected bounds: x 0..0.04, y −0.02..0, z 0..0.2 (metres).
    EXPECT_EQ(tree->box(), octree::RootBox::enclosing({0, -0.02, 0, 0.04, 0, 0.2}));
    const Eigen::AlignedBox3d occupied = view::occupiedBounds(*tree, 6);
    const Eigen::Vector3d size = occupied.sizes();
    // The tallest extent is along Z (whole cells of 0.2 / 64 m).
    EXPECT_GT(size.z(), 0.19);
    EXPECT_LT(size.x(), 0.05);
    EXPECT_LT(size.y(), 0.03);
}

TEST(ImportFrameTest, TheHappyBuddhaStandsAlongZWithUpPlusY)
{
    SKIP_WITHOUT_SHARED_DATA();
    const auto path = stylos::test::sharedData() / "scans/happy_buddha_1.1M.ply";
    auto asFiled = summarizePointFile(path);
    ASSERT_TRUE(asFiled.ok()) << asFiled.error().message;
    ReadOptions options;
    options.frame.up = UpAxis::PosY;
    auto upright = summarizePointFile(path, options);
    ASSERT_TRUE(upright.ok()) << upright.error().message;
    EXPECT_EQ(upright->points, 1099005u);
    // (x, y, z) → (x, −z, y): the box maps exactly.
    const V3 lo = *asFiled->min, hi = *asFiled->max;
    EXPECT_EQ(*upright->min, (V3{lo[0], -hi[2], lo[1]}));
    EXPECT_EQ(*upright->max, (V3{hi[0], -lo[2], hi[1]}));
    const V3 size{(*upright->max)[0] - (*upright->min)[0], (*upright->max)[1] - (*upright->min)[1],
                  (*upright->max)[2] - (*upright->min)[2]};
    EXPECT_GT(size[2], 2 * size[0]);  // 0.200 m tall, 0.082 m wide and deep
    EXPECT_GT(size[2], 2 * size[1]);
}

} // namespace
