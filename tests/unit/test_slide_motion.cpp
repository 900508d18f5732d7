// Prescribed slide motion: the spline through a measured table and the ln cosh law.

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "physics/SlideMotion.h"

namespace wcmps {
namespace {

// Block kinematics of case I, measured (../shared/spec/cases.md).
const std::vector<double> kT = {0.0, 0.1, 0.2, 0.3, 0.4};
const std::vector<double> kS = {0.0, 0.018, 0.058, 0.121, 0.190};

TEST(SplineSlide, PassesThroughTheTableFromRest) {
  const SplineSlide slide(kT, kS);
  for (std::size_t k = 0; k < kT.size(); ++k) EXPECT_NEAR(slide.at(kT[k]).s, kS[k], 1e-14);
  EXPECT_EQ(slide.at(0.0).u, 0.0);
  EXPECT_EQ(slide.at(-1.0).s, 0.0);
}

TEST(SplineSlide, SpeedAndAccelerationAreContinuous) {
  // At every knot the limits from both sides agree (to the rounding of evaluating the two
  // cubics 1e-9 s apart: |A'| is below 1e3 m/s^3 here, so 1e-5 m/s^2 is ample).
  const SplineSlide slide(kT, kS);
  for (std::size_t k = 1; k < kT.size(); ++k) {
    const SlideState l = slide.at(kT[k] - 1e-9), r = slide.at(kT[k] + 1e-9);
    EXPECT_NEAR(l.u, r.u, 1e-6) << "t = " << kT[k];
    EXPECT_NEAR(l.a, r.a, 1e-5) << "t = " << kT[k];
  }
  // A = 0 at the last time, and S carries on at the last speed.
  EXPECT_NEAR(slide.at(0.4).a, 0.0, 1e-12);
  const SlideState end = slide.at(0.4), later = slide.at(0.5);
  EXPECT_NEAR(later.s, end.s + 0.1 * end.u, 1e-14);
  EXPECT_EQ(later.a, 0.0);
}

TEST(SplineSlide, DerivativesAreThoseOfS) {
  // U and A against central differences of S inside the intervals (error h^2 S'''' ~ 1e-9).
  const SplineSlide slide(kT, kS);
  const double h = 1e-4;
  for (double t = 0.013; t < 0.4; t += 0.031) {
    const double sm = slide.at(t - h).s, s0 = slide.at(t).s, sp = slide.at(t + h).s;
    EXPECT_NEAR(slide.at(t).u, (sp - sm) / (2 * h), 1e-7) << "t = " << t;
    EXPECT_NEAR(slide.at(t).a, (sp - 2 * s0 + sm) / (h * h), 1e-3) << "t = " << t;
  }
}

TEST(SplineSlide, RejectsBadTables) {
  EXPECT_THROW(SplineSlide({0.0}, {0.0}), std::invalid_argument);
  EXPECT_THROW(SplineSlide({0.0, 0.1, 0.1}, {0.0, 0.1, 0.2}), std::invalid_argument);
  EXPECT_THROW(SplineSlide({0.0, 0.1}, {0.0}), std::invalid_argument);
  // Going back and forth.
  EXPECT_THROW(SplineSlide({0.0, 0.1, 0.2, 0.3}, {0.0, 0.05, 0.01, 0.06}), std::invalid_argument);
}

TEST(LnCoshSlide, StartsAtA0AndTendsToUt) {
  const LnCoshSlide slide{3.31, 0.775};
  EXPECT_EQ(slide.at(0.0).s, 0.0);
  EXPECT_NEAR(slide.at(0.0).a, 0.0, 0.0);  // at rest before the release
  EXPECT_NEAR(slide.at(1e-9).a, 3.31, 1e-8);
  EXPECT_NEAR(slide.at(50.0).u, 0.775, 1e-12);
  EXPECT_TRUE(std::isfinite(slide.at(1e4).s));
  // Derivatives by central differences.
  const double h = 1e-5;
  for (double t = 0.05; t < 1.0; t += 0.1) {
    EXPECT_NEAR(slide.at(t).u, (slide.at(t + h).s - slide.at(t - h).s) / (2 * h), 1e-8);
    EXPECT_NEAR(slide.at(t).a, (slide.at(t + h).u - slide.at(t - h).u) / (2 * h), 1e-6);
  }
}

TEST(LnCoshSlide, FitsTheMeasuredTables) {
  // ../shared/spec/cases.md: a0 = 3.31 m/s^2, ut = 0.775 m/s (I); 4.37, 0.770 (II), "to 1-2 mm".
  // That holds for case I (largest error 1.9 mm, at 0.1 s). For case II the law is 3.2 mm
  // short at 0.1 s; a least-squares fit of a0 and ut gives the same parameters and the same
  // error, so it is the law's shape, not the parameters: 3.5 mm for case II.
  const std::vector<double> s2 = {0.0, 0.024, 0.073, 0.140, 0.216};
  const LnCoshSlide one{3.31, 0.775}, two{4.37, 0.770};
  for (std::size_t k = 0; k < kT.size(); ++k) {
    EXPECT_NEAR(one.at(kT[k]).s, kS[k], 0.002) << "case I, t = " << kT[k];
    EXPECT_NEAR(two.at(kT[k]).s, s2[k], 0.0035) << "case II, t = " << kT[k];
  }
}

}  // namespace
}  // namespace wcmps
