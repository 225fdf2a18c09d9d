#include <gtest/gtest.h>

#include <cmath>

#include "math/half_float.hpp"

namespace {

using sss::math::round_to_half;

TEST(HalfFloat, RoundsToNearestEvenLikeTheGl) {
  EXPECT_EQ(round_to_half(1.0f), 1.0f);
  EXPECT_EQ(round_to_half(1.0f + std::ldexp(1.0f, -11)), 1.0f);  // tie: to even
  EXPECT_EQ(round_to_half(1.0f + 3.0f * std::ldexp(1.0f, -11)), 1.0f + std::ldexp(1.0f, -9));
  EXPECT_EQ(round_to_half(0.1f), 0.0999755859375f);
  EXPECT_EQ(round_to_half(-2.5f), -2.5f);
  EXPECT_EQ(round_to_half(65504.0f), 65504.0f);
  EXPECT_EQ(round_to_half(65519.0f), 65504.0f);
  EXPECT_TRUE(std::isinf(round_to_half(65520.0f)));
  EXPECT_EQ(round_to_half(std::ldexp(1.0f, -24)), std::ldexp(1.0f, -24));   // smallest subnormal
  EXPECT_EQ(round_to_half(std::ldexp(1.0f, -25)), 0.0f);                    // tie to even: 0
  EXPECT_EQ(round_to_half(3.0f * std::ldexp(1.0f, -25)), std::ldexp(1.0f, -23));
  EXPECT_TRUE(std::isnan(round_to_half(NAN)));
}

}  // namespace
