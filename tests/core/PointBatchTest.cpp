// PointBatch: shaping, appending and dropping points keep every attribute array in step.
#include "stylos/core/io/PointBatch.h"

#include <gtest/gtest.h>

using namespace stylos::core::io;

TEST(PointBatch, ResetAppendAndPopBackKeepAttributesInStep)
{
    const PointSchema schema{true, true, {"intensity"}};
    EXPECT_EQ(schema.attributeNames(), (std::vector<std::string>{"normal", "color", "intensity"}));
    PointBatch a, b;
    a.reset(schema, 4);
    EXPECT_TRUE(a.empty());
    EXPECT_EQ(a.scalars.size(), 1u);
    a.positions = {1, 2, 3};
    a.normals = {0, 0, 1};
    a.colors = {10, 20, 30};
    a.scalars[0] = {7};
    b.reset(schema, 4);
    b.positions = {4, 5, 6, 7, 8, 9};
    b.normals = {1, 0, 0, 0, 1, 0};
    b.colors = {1, 2, 3, 4, 5, 6};
    b.scalars[0] = {8, 9};
    a.append(b);
    ASSERT_EQ(a.size(), 3u);
    EXPECT_EQ(a.positions, (std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8, 9}));
    EXPECT_EQ(a.colors, (std::vector<std::uint8_t>{10, 20, 30, 1, 2, 3, 4, 5, 6}));
    EXPECT_EQ(a.scalars[0], (std::vector<double>{7, 8, 9}));
    a.popBack();
    EXPECT_EQ(a.size(), 2u);
    EXPECT_EQ(a.normals.size(), 6u);
    EXPECT_EQ(a.colors.size(), 6u);
    EXPECT_EQ(a.scalars[0], (std::vector<double>{7, 8}));
    a.reset(PointSchema{}, 1);
    EXPECT_TRUE(a.empty());
    EXPECT_TRUE(a.scalars.empty());
}
