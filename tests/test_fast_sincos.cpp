// analytic/fast_sincos.hpp against the C library's sin and cos: the model terms use it at every integrator stage, so
// it must agree to a few ulp wherever the models evaluate it, including where a result is near zero.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "analytic/fast_sincos.hpp"

namespace vssw {
namespace {

// Our rounding (Taylor sums of |r| <= pi/4: at most 1 ulp measured) plus the C library's own (under 1 ulp, glibc's
// manual): two results differ by at most 2 ulp of the exact value.
constexpr double kModelRangeUlp = 2.0;
// Far arguments add the reduction's rounding (k kPio2Lo and the last subtraction): 2 ulp measured up to 1e6 rad.
constexpr double kFarRangeUlp = 3.0;
// The angles the models use: alpha1 - q, k q, theta2 and the parapet's are all within a few radians; twice round.
constexpr double kModelRange = 4.0 * 3.141592653589793;
constexpr int kSamples = 200000;

double ulp_of(double v) {
    const double a = std::abs(v);
    return std::nextafter(a, std::numeric_limits<double>::infinity()) - a;
}

// Largest difference from std::sin/std::cos in ulp of the library's results at x.
double ulp_error(double x) {
    const SinCos sc = fast_sincos(x);
    return std::max(std::abs(sc.sin - std::sin(x)) / ulp_of(std::sin(x)),
                    std::abs(sc.cos - std::cos(x)) / ulp_of(std::cos(x)));
}

TEST(AnalyticSinCos, WithinTwoUlpOverTheModelsRange) {
    double worst = 0.0;
    for (int i = 0; i <= kSamples; ++i) {  // an even grid: every quadrant and both signs
        const double x = -kModelRange + 2.0 * kModelRange * i / kSamples;
        worst = std::max(worst, ulp_error(x));
    }
    EXPECT_LE(worst, kModelRangeUlp);
}

TEST(AnalyticSinCos, SmallAnglesTakeTheShortSeriesWithinTwoUlp) {
    // |x| <= kSmall stop at x^9 and x^10 (a slender wall's every angle): an even grid over the range and a little past
    // it (both branches at the edge), and tiny angles down to the subnormals. One term fewer would be 1500 ulp off.
    const double edge = 1.01 * fast_sincos_detail::kSmall;
    double worst = 0.0;
    for (int i = 0; i <= kSamples; ++i) worst = std::max(worst, ulp_error(-edge + 2.0 * edge * i / kSamples));
    for (double x = 1e-310; x < edge; x *= 1.37) {
        worst = std::max(worst, ulp_error(x));
        worst = std::max(worst, ulp_error(-x));
    }
    EXPECT_LE(worst, kModelRangeUlp);
}

TEST(AnalyticSinCos, KeepsRelativeAccuracyNearMultiplesOfHalfPi) {
    // There one result is near zero: only a reduction exact to well past double precision keeps its ulps.
    double worst = 0.0;
    for (int k = -8; k <= 8; ++k) {
        const double centre = k * 1.5707963267948966;
        double x = centre;
        for (int n = 0; n < 64; ++n) {  // the 64 doubles from k pi/2 up, and their mirrors below it
            worst = std::max(worst, ulp_error(x));
            worst = std::max(worst, ulp_error(2.0 * centre - x));
            x = std::nextafter(x, std::numeric_limits<double>::infinity());
        }
    }
    EXPECT_LE(worst, kModelRangeUlp);
}

TEST(AnalyticSinCos, WithinThreeUlpUpToTheReductionLimit) {
    std::mt19937_64 rng(12);
    std::uniform_real_distribution<double> far(-fast_sincos_detail::kMaxReduced, fast_sincos_detail::kMaxReduced);
    double worst = 0.0;
    for (int i = 0; i < kSamples; ++i) worst = std::max(worst, ulp_error(far(rng)));
    EXPECT_LE(worst, kFarRangeUlp);
}

TEST(AnalyticSinCos, HandsFarAndNonFiniteArgumentsToTheLibrary) {
    for (double x : {2e6, -3.5e9, 1e300}) {
        EXPECT_EQ(fast_sincos(x).sin, std::sin(x)) << x;
        EXPECT_EQ(fast_sincos(x).cos, std::cos(x)) << x;
    }
    for (double x : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
        EXPECT_TRUE(std::isnan(fast_sincos(x).sin));
        EXPECT_TRUE(std::isnan(fast_sincos(x).cos));
    }
    EXPECT_EQ(fast_sincos(0.0).sin, 0.0);
    EXPECT_EQ(fast_sincos(0.0).cos, 1.0);
}

}  // namespace
}  // namespace vssw
