// shareBudget: the water-filling share of the 3D view's point budget among fragments, exactly.
#include "stylos/core/view/BudgetShare.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using stylos::core::view::shareBudget;
using V = std::vector<std::uint64_t>;

TEST(BudgetShareTest, InProportionToTheDemands)
{
    EXPECT_EQ(shareBudget({1, 1, 2}, {100, 100, 100}, 100), (V{25, 25, 50}));
    EXPECT_EQ(shareBudget({1, 0, 2}, {100, 100, 100}, 90), (V{30, 0, 60}));
}

TEST(BudgetShareTest, WhatACappedOneCannotUseGoesToTheOthers)
{
    EXPECT_EQ(shareBudget({1, 1, 2}, {10, 100, 100}, 100), (V{10, 30, 60}));
    EXPECT_EQ(shareBudget({1, 1}, {5, 7}, 100), (V{5, 7}));
}

TEST(BudgetShareTest, RoundingGoesToTheFirstAndNobodyWithADemandGetsZero)
{
    EXPECT_EQ(shareBudget({1, 1, 1}, {100, 100, 100}, 10), (V{4, 3, 3}));
    EXPECT_EQ(shareBudget({1000, 1}, {100, 100}, 100), (V{99, 1}));
    EXPECT_EQ(shareBudget({1, 1}, {100, 100}, 1), (V{1, 0})); // one point: the budget does not last
}

TEST(BudgetShareTest, NothingToShare)
{
    EXPECT_EQ(shareBudget({}, {}, 100), V{});
    EXPECT_EQ(shareBudget({1, 2}, {10, 10}, 0), (V{0, 0}));
    // Negative or non-finite demands and zero caps get nothing; the others share the whole budget.
    EXPECT_EQ(shareBudget({-1, std::nan(""), std::numeric_limits<double>::infinity(), 1, 1}, {9, 9, 9, 0, 100}, 50),
              (V{0, 0, 0, 0, 50}));
}
