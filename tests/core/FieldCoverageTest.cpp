// measureCoverage: the closed footprint of the pixels with a height, exact counts on small fields.
#include "stylos/core/shading/FieldCoverage.h"

#include <gtest/gtest.h>

using namespace stylos::core::shading;

namespace {

HeightField fieldOf(const std::vector<std::string>& rows)
{
    auto field = HeightField::create(int(rows.front().size()), int(rows.size()), 0.001).value();
    for (int r = 0; r < field.height(); ++r)
        for (int c = 0; c < field.width(); ++c) {
            if (rows[std::size_t(r)][std::size_t(c)] == 'M') field.setMeasured(c, r, 0.0f);
            if (rows[std::size_t(r)][std::size_t(c)] == 'F') field.setFilled(c, r, 0.0f);
        }
    return field;
}

} // namespace

TEST(FieldCoverage, ACheckerboardClosesIntoItsWholeSquare)
{
    const auto field = fieldOf({"M.M.M.", ".M.M.M", "M.M.M.", ".M.M.M"});
    const FieldCoverage c = measureCoverage(field, 1);
    EXPECT_EQ(c.withHeight, 12u);
    EXPECT_EQ(c.footprint, 24u);
    EXPECT_DOUBLE_EQ(c.fraction(), 0.5);
}

TEST(FieldCoverage, AGapWiderThanTheClosingStaysOutside)
{
    // Two blocks of 2 × 3 pixels (one measured, one filled) 4 pixels apart: radius 1 bridges 2, not 4.
    const auto field = fieldOf({"MM....FF", "MM....FF", "MM....FF"});
    EXPECT_EQ(measureCoverage(field, 1).footprint, 12u);
    EXPECT_DOUBLE_EQ(measureCoverage(field, 1).fraction(), 1.0);
    // Radius 2 bridges the gap: the whole 8 × 3 rectangle is the footprint.
    EXPECT_EQ(measureCoverage(field, 2).footprint, 24u);
    EXPECT_DOUBLE_EQ(measureCoverage(field, 2).fraction(), 0.5);
}

TEST(FieldCoverage, AHoleInsideCountsAndTheBorderIsNotEaten)
{
    const auto field = fieldOf({"MMMMM", "MM.MM", "MMMMM"});
    const FieldCoverage c = measureCoverage(field, 1);
    EXPECT_EQ(c.withHeight, 14u);
    EXPECT_EQ(c.footprint, 15u);
}

TEST(FieldCoverage, RadiusZeroAndEmptyFields)
{
    const auto field = fieldOf({"M.M", "..."});
    EXPECT_EQ(measureCoverage(field, 0).footprint, 2u);
    EXPECT_DOUBLE_EQ(measureCoverage(fieldOf({"...", "..."}), 3).fraction(), 0.0);
    EXPECT_EQ(measureCoverage(HeightField{}, 1).footprint, 0u);
}
