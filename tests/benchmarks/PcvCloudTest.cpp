// The benchmarks' PCV helpers (PcvCloud.h) on tiny hand-made files: CloudCompare's scalar field read back
// with exact values, the nearest point within a radius, the factor F(n) between the two definitions.
#include "PcvCloud.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;
using stylos::bench::PointGrid;
using stylos::bench::readPcvCloud;

namespace {

class PcvCloudTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        m_dir = fs::temp_directory_path() / ("stylos_pcv_cloud_test_" + std::to_string(::getpid()));
        fs::create_directories(m_dir);
    }
    void TearDown() override { fs::remove_all(m_dir); }
    fs::path write(const std::string& name, const std::string& text)
    {
        const fs::path p = m_dir / name;
        std::ofstream(p, std::ios::binary) << text;
        return p;
    }
    fs::path m_dir;
};

// As CloudCompare 2.11 writes it (there binary, float x y z and the field), here in ASCII, with another
// scalar first so the column is chosen by name.
const char* kPcvPly = "ply\n"
                      "format ascii 1.0\n"
                      "comment Created by CloudCompare v2.11.3 (Anoia)\n"
                      "element vertex 4\n"
                      "property float x\n"
                      "property float y\n"
                      "property float z\n"
                      "property uchar scan_id\n"
                      "property float scalar_Illuminance_(PCV)\n"
                      "end_header\n"
                      "0 0 0 7 0.25\n"
                      "1 0 0 7 0.5\n"
                      "0 2 0 8 0.75\n"
                      "1000.5 2000.25 50 9 1\n";

} // namespace

TEST_F(PcvCloudTest, ReadsPositionsAndThePcvFieldInFileOrder)
{
    const auto cloud = readPcvCloud(write("a_PCV.ply", kPcvPly));
    ASSERT_TRUE(cloud.ok()) << cloud.error().message;
    EXPECT_EQ(cloud->field, "scalar_Illuminance_(PCV)");
    ASSERT_EQ(cloud->positions.size(), 4u);
    ASSERT_EQ(cloud->values.size(), 4u);
    EXPECT_EQ(cloud->values[0], 0.25);
    EXPECT_EQ(cloud->values[1], 0.5);
    EXPECT_EQ(cloud->values[2], 0.75);
    EXPECT_EQ(cloud->values[3], 1.0);
    EXPECT_EQ(cloud->positions[2], (std::array<double, 3>{0.0, 2.0, 0.0}));
    EXPECT_EQ(cloud->positions[3], (std::array<double, 3>{1000.5, 2000.25, 50.0}));
}

TEST_F(PcvCloudTest, AFileWithoutThePcvFieldIsRefusedNamingIt)
{
    const fs::path p = write("plain.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                                          "property float y\nproperty float z\nproperty float intensity\n"
                                          "end_header\n0 0 0 0.5\n");
    const auto cloud = readPcvCloud(p);
    ASSERT_FALSE(cloud.ok());
    EXPECT_EQ(cloud.error().code, stylos::core::ErrorCode::Malformed);
    EXPECT_EQ(cloud.error().message, p.string() + ": no PCV / Illuminance scalar field");
}

TEST_F(PcvCloudTest, AMissingOrTruncatedFileGivesTheReadersError)
{
    const auto missing = readPcvCloud(m_dir / "none_PCV.ply");
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().message.find("none_PCV.ply"), std::string::npos);
    std::string cut = kPcvPly;
    cut.resize(cut.find("0 2 0 8"));
    const auto truncated = readPcvCloud(write("cut_PCV.ply", cut));
    ASSERT_FALSE(truncated.ok());
    EXPECT_NE(truncated.error().message.find("cut_PCV.ply"), std::string::npos);
}

TEST_F(PcvCloudTest, NearestPointWithinTheRadiusOfTheReadCloud)
{
    const auto cloud = readPcvCloud(write("a_PCV.ply", kPcvPly));
    ASSERT_TRUE(cloud.ok());
    const PointGrid grid(cloud->positions, 1.0);
    EXPECT_EQ(grid.nearest({0.1, 0.1, 0.0}), 0u);
    EXPECT_EQ(grid.nearest({0.9, -0.2, 0.3}), 1u);
    EXPECT_EQ(grid.nearest({0.2, 1.5, 0.0}), 2u);   // 0.54 from point 2, 1.51 from point 0
    EXPECT_EQ(grid.nearest({0.5, 0.0, 0.0}), 0u);   // a tie: the lower index
    EXPECT_EQ(grid.nearest({1000.5, 2000.0, 50.0}), 3u);
    EXPECT_EQ(grid.nearest({0.0, 1.0, 0.0}), 0u);   // exactly 1 from points 0 and 2: within, lower index
    EXPECT_EQ(grid.nearest({3.0, 0.0, 0.0}), SIZE_MAX); // 2 from point 1: beyond the radius
    EXPECT_EQ(grid.nearest({-0.6, -0.6, -0.6}), SIZE_MAX); // 1.04 from point 0, in a neighbouring bin
    const PointGrid wide(cloud->positions, 2.5);
    EXPECT_EQ(wide.nearest({3.0, 0.0, 0.0}), 1u);
    EXPECT_EQ(wide.nearest({-0.6, -0.6, -0.6}), 0u);
    EXPECT_EQ(wide.nearest({500.0, 1000.0, 25.0}), SIZE_MAX);
}

TEST(PcvDefinition, FrontFractionCountsTheDirectionsInFrontOfTheNormal)
{
    const std::vector<stylos::core::ao::Direction> d{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.6, 0.8, 0}};
    EXPECT_EQ(stylos::bench::frontFraction(d, {1, 0, 0}), 2.0 / 5.0);  // (1,0,0), (0.6,0.8,0)
    EXPECT_EQ(stylos::bench::frontFraction(d, {0, 1, 0}), 2.0 / 5.0);  // (0,1,0), (0.6,0.8,0)
    EXPECT_EQ(stylos::bench::frontFraction(d, {0, 0, -1}), 0.0);       // tangent ones (n·d = 0) are not in front
    EXPECT_EQ(stylos::bench::frontFraction(d, {-1, 0, 0}), 1.0 / 5.0);
    EXPECT_EQ(stylos::bench::frontFraction({}, {1, 0, 0}), 0.0);
}
