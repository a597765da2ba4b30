// PLIC geometry (plic.cpp) against exact areas: the inverse alpha(c) reproduces c for every
// orientation, sub-rectangle fractions add up to the whole, and known cuts give known areas.
#include <gtest/gtest.h>

#include <cmath>

#include "twod/plic.hpp"

using namespace granbench::twod;

TEST(Plic, KnownAreas) {
  EXPECT_DOUBLE_EQ(plic_area(0.0, 1.0, 0.3), 0.3);      // horizontal line z = 0.3
  EXPECT_DOUBLE_EQ(plic_area(1.0, 1.0, 1.0), 0.5);      // diagonal
  EXPECT_DOUBLE_EQ(plic_area(1.0, 1.0, 0.5), 0.125);    // corner triangle
  EXPECT_DOUBLE_EQ(plic_area(-1.0, 0.0, -0.25), 0.75);  // fluid on x >= 0.25
  EXPECT_DOUBLE_EQ(plic_area(2.0, 1.0, 3.0), 1.0);
  EXPECT_DOUBLE_EQ(plic_area(2.0, 1.0, -0.1), 0.0);
}

TEST(Plic, InverseRoundTrip) {
  for (int a = 0; a < 24; ++a) {
    const double th = 2.0 * M_PI * (a + 0.37) / 24.0;
    const double m1 = std::cos(th), m2 = std::sin(th);
    for (double c : {1e-9, 0.01, 0.2, 0.5, 0.77, 0.99, 1.0 - 1e-9})
      EXPECT_NEAR(plic_area(m1, m2, plic_alpha(m1, m2, c)), c, 1e-13) << th << " " << c;
  }
}

TEST(Plic, SubRectanglesPartitionTheCell) {
  const double m1 = -0.3, m2 = 0.8, alpha = plic_alpha(m1, m2, 0.42);
  const double s = 0.37;
  const double left = s * plic_rect_fraction(m1, m2, alpha, 0.0, s, 0.0, 1.0);
  const double right = (1 - s) * plic_rect_fraction(m1, m2, alpha, s, 1 - s, 0.0, 1.0);
  EXPECT_NEAR(left + right, 0.42, 1e-14);
  const double bottom = s * plic_rect_fraction(m1, m2, alpha, 0.0, 1.0, 0.0, s);
  const double top = (1 - s) * plic_rect_fraction(m1, m2, alpha, 0.0, 1.0, s, 1 - s);
  EXPECT_NEAR(bottom + top, 0.42, 1e-14);
}
