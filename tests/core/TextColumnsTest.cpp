#include "stylos/core/io/TextColumns.h"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstring>

using namespace stylos::core;
using namespace stylos::core::io;

TEST(TextColumns, NumbersMatchFromChars)
{
    for (const std::string token :
         {"0", "-0.0", "0.1", "4.35", "1234567.125", "0.30000000000000004", "9007199254740993", "9007199254740992.5",
          "123456789012345678.9", "1.", ".5", "-.5", "+.5", "+7", "00012.5", "1e5", "1E-3", "-2.5e+2",
          "0.0000000000000000000001", "0.00000000000000000000001", "3.14159265358979323846264338327950288"}) {
        double fast = 0.0, reference = 0.0;
        const FieldScan scan = parseFields(token, Separator::Whitespace, &fast, 1);
        const std::string_view unsigned_ = token[0] == '+' ? std::string_view(token).substr(1) : std::string_view(token);
        std::from_chars(unsigned_.data(), unsigned_.data() + unsigned_.size(), reference);
        EXPECT_EQ(scan.count, 1u) << token;
        EXPECT_EQ(scan.badField, 0u) << token;
        EXPECT_EQ(std::memcmp(&fast, &reference, sizeof fast), 0) << token << ": " << fast << " vs " << reference;
    }
}

TEST(TextColumns, NotNumbers)
{
    for (const std::string token : {".", "-", "+", "1.5.2", "+-1", "--1", "1e", "abc", "0x10", "1,5", "12a"}) {
        double v = 0.0;
        const FieldScan scan = parseFields(token, Separator::Whitespace, &v, 1);
        EXPECT_EQ(scan.badField, 1u) << token;
        EXPECT_EQ(scan.badToken, token);
    }
}

TEST(TextColumns, FieldCounts)
{
    double v[3];
    EXPECT_EQ(parseFields("1 2 3 4 5", Separator::Whitespace, v, 3).count, 5u); // counted beyond the capacity
    EXPECT_EQ(parseFields(" 1,2 , 3, ", Separator::Comma, v, 3).count, 3u);
    const FieldScan empty = parseFields("1;;3", Separator::Semicolon, v, 3);
    EXPECT_EQ(empty.badField, 2u);
    EXPECT_TRUE(empty.badToken.empty());
    EXPECT_EQ(detectSeparator("1,5;2"), Separator::Semicolon);
    EXPECT_EQ(detectSeparator("1,5 2"), Separator::Comma);
    EXPECT_EQ(detectSeparator("1\t5 2"), Separator::Whitespace);
}

TEST(TextColumns, OverrideLayout)
{
    auto layout = layoutFromOverride("x, y, z, Intensity, red, green, blue, _, normal_x, ny, nz, Temp");
    ASSERT_TRUE(layout.ok()) << layout.error().message;
    EXPECT_EQ(layout->describe(), "x y z intensity r g b _ nx ny nz Temp");
    EXPECT_EQ(layout->schema().scalarNames, (std::vector<std::string>{"intensity", "Temp"}));
    EXPECT_TRUE(layout->schema().hasNormals);
    EXPECT_EQ(layoutFromOverride("x y z").value().columnCount(), 3u);
    EXPECT_EQ(layoutFromOverride("x,y,z,rf,gf,bf").value().colorScale, ColorScale::Unit);
    EXPECT_EQ(layoutFromOverride("x,y").error().code, ErrorCode::InvalidArgument);
}

TEST(TextColumns, DetectedLayouts)
{
    const auto detect = [](std::size_t columns, std::vector<double> values) {
        ColumnSample sample;
        sample.columns = columns;
        sample.values = std::move(values);
        sample.fractional.assign(columns, 0);
        return detectLayout(sample).describe();
    };
    EXPECT_EQ(detect(3, {1, 2, 3}), "x y z");
    EXPECT_EQ(detect(4, {1, 2, 3, 4}), "x y z intensity");
    EXPECT_EQ(detect(6, {1, 2, 3, 0, 128, 255}), "x y z r g b");
    EXPECT_EQ(detect(6, {1, 2, 3, 0, 0, 1}), "x y z nx ny nz"); // integers, but a unit vector
    EXPECT_EQ(detect(6, {1, 2, 3, 0.3, -0.2, 5}), "x y z nx ny nz");
    EXPECT_EQ(detect(7, {1, 2, 3, 4, 5, 6, 7}), "x y z intensity r g b");
    EXPECT_EQ(detect(9, {1, 2, 3, 9, 9, 9, 0, 0.6, 0.8}), "x y z r g b nx ny nz");
    EXPECT_EQ(detect(9, {1, 2, 3, 0, 0.6, 0.8, 9, 9, 9}), "x y z nx ny nz r g b");
    EXPECT_EQ(detect(5, {1, 2, 3, 4, 5}), "x y z scalar_4 scalar_5");
}

TEST(TextColumns, ColorScale)
{
    ColumnSample sample;
    sample.columns = 6;
    sample.values = {1, 2, 3, 0, 1, 1};
    sample.fractional.assign(6, 0);
    const ColumnLayout layout = layoutFromOverride("x,y,z,r,g,b").value();
    EXPECT_EQ(detectColorScale(layout, sample), ColorScale::Byte);
    sample.fractional[4] = 1; // "1.0": written as a float
    EXPECT_EQ(detectColorScale(layout, sample), ColorScale::Unit);
    sample.values[3] = 2;
    EXPECT_EQ(detectColorScale(layout, sample), ColorScale::Byte);
    EXPECT_EQ(colorToByte(0.5, true), 128);
    EXPECT_EQ(colorToByte(254.4, false), 254);
    EXPECT_EQ(colorToByte(std::nan(""), false), 0);
    EXPECT_EQ(colorToByte(1e9, false), 255);
}
