// HeightField: creation limits, row-major layout with row 0 at the top, pixel states.
#include "stylos/core/shading/HeightField.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace stylos::core;
using namespace stylos::core::shading;

TEST(ShadingHeightField, CreatesEmptyFieldRowMajor)
{
    auto field = HeightField::create(5, 3, 0.0005);
    ASSERT_TRUE(field.ok());
    EXPECT_EQ(field->width(), 5);
    EXPECT_EQ(field->height(), 3);
    EXPECT_EQ(field->pixelSize(), 0.0005);
    EXPECT_EQ(field->pixelCount(), 15u);
    EXPECT_EQ(field->count(PixelState::Empty), 15u);
    EXPECT_EQ(field->index(0, 0), 0u);
    EXPECT_EQ(field->index(4, 0), 4u);
    EXPECT_EQ(field->index(0, 1), 5u); // row 1 follows row 0 (the top row)
    EXPECT_EQ(field->index(3, 2), 13u);
    EXPECT_TRUE(field->contains(4, 2));
    EXPECT_FALSE(field->contains(5, 0));
    EXPECT_FALSE(field->contains(0, -1));
}

TEST(ShadingHeightField, StatesAndHeights)
{
    auto field = HeightField::create(4, 4, 0.001).value();
    field.setMeasured(1, 2, 0.25f);
    field.setFilled(3, 0, -0.5f);
    EXPECT_EQ(field.stateAt(1, 2), PixelState::Measured);
    EXPECT_EQ(field.heightAt(1, 2), 0.25f);
    EXPECT_EQ(field.heights()[field.index(1, 2)], 0.25f);
    EXPECT_EQ(field.stateAt(3, 0), PixelState::Filled);
    EXPECT_TRUE(field.hasHeight(3, 0));
    EXPECT_FALSE(field.hasHeight(0, 0));
    EXPECT_EQ(field.count(PixelState::Measured), 1u);
    EXPECT_EQ(field.count(PixelState::Filled), 1u);
    EXPECT_EQ(field.count(PixelState::Empty), 14u);
    field.clear(1, 2);
    EXPECT_EQ(field.stateAt(1, 2), PixelState::Empty);
    EXPECT_EQ(field.heightAt(1, 2), 0.0f);
    EXPECT_EQ(field.count(PixelState::Measured), 0u);
}

TEST(ShadingHeightField, RefusesBadSizes)
{
    EXPECT_TRUE(HeightField::create(0, 0, 1.0).ok());
    EXPECT_TRUE(HeightField::create(HeightField::kMaxSide, 1, 1.0).ok());
    for (auto bad : {HeightField::create(-1, 4, 1.0), HeightField::create(4, -1, 1.0),
                     HeightField::create(HeightField::kMaxSide + 1, 4, 1.0),
                     HeightField::create(4, 40000, 1.0), HeightField::create(4, 4, 0.0),
                     HeightField::create(4, 4, -0.001),
                     HeightField::create(4, 4, std::numeric_limits<double>::quiet_NaN()),
                     HeightField::create(4, 4, std::numeric_limits<double>::infinity())}) {
        ASSERT_FALSE(bad.ok());
        EXPECT_EQ(bad.error().code, ErrorCode::InvalidArgument);
    }
    const auto huge = HeightField::create(40000, 100, 0.001);
    ASSERT_FALSE(huge.ok());
    EXPECT_NE(huge.error().message.find("40000 x 100"), std::string::npos) << huge.error().message;
}
