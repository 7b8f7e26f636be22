#pragma once
// The sine and cosine of one angle together, for the model terms that every integrator stage evaluates (Eq. 11's
// coefficients, the exact kinematics' angles, the parapet, the two blocks' turns). glibc's sincos was the largest
// single cost of an analytic run (about 30 % of the Fig. 6 free vibration's instructions, callgrind). This one is
// within a few ulp of it (tests/test_fast_sincos.cpp) with half its instructions and a shorter chain of dependent
// operations, which is what an integrator's stages wait on: 14-16 ns a call against glibc's 21-23 ns in a loop where
// each argument depends on the last result (machine loaded). A Horner evaluation of the same polynomials, with the
// reduction always done, had fewer instructions still but took 1.5 times glibc's time there.
//
// Method: x = k pi/2 + r with |r| <= pi/4 (Cody & Waite's reduction with pi/2 in three parts), then the Taylor
// series of sin r and cos r in r^2, to r^17 and r^18: on |r| <= pi/4 the first omitted terms, (pi/4)^19 / 19! and
// (pi/4)^20 / 20!, are below 1e-19, far under half an ulp of the results (>= 0.7 there). The coefficients are 1/n!.
// Arguments beyond kMaxReduced (and NaN, infinities) go to std::sin and std::cos; those within kSmall take shorter
// series (below).
#include <cmath>

namespace vssw {

struct SinCos {
    double sin, cos;
};

namespace fast_sincos_detail {

// pi/2 = kPio2Hi + kPio2Mid + kPio2Lo. The first two have 33 significant bits (their hexadecimal mantissas end in
// zeros), so k times either is exact while |k| < 2^20, and x - k kPio2Hi is exact near k pi/2 (Sterbenz): the
// reduced argument keeps its relative accuracy even where the result is near zero (x close to a multiple of pi/2).
constexpr double kPio2Hi = 0x1.921fb544p+0;
constexpr double kPio2Mid = 0x1.0b4611a6p-34;
constexpr double kPio2Lo = 0x1.3198a2e037073p-69;
constexpr double kTwoOverPi = 0x1.45f306dc9c883p-1;  // 2/pi rounded: only picks k, an error there moves r by ulps
// Below pi/4 (rounded down), x * 2/pi rounds to k = 0: no reduction.
constexpr double kQuarterPi = 0.785;
// Up to 1/8 the series stop at x^9 and x^10: the first omitted terms, x^11/11! and x^12/12!, are at most 0.26 and
// 0.0003 ulp of the results there (1 ulp from glibc's measured, as on the whole range; tests/test_fast_sincos.cpp).
constexpr double kSmall = 0.125;
// |k| < 2^20 keeps k kPio2Hi exact: |x| below 2^20 pi/2 = 1.6e6; a round bound under it.
constexpr double kMaxReduced = 1e6;
// Adding and subtracting 1.5 * 2^52 rounds a double of magnitude below 2^51 to the nearest integer (ties to even),
// without a library call.
constexpr double kRoundMagic = 0x1.8p52;

constexpr double inverse_factorial(int n) {
    double f = 1.0;  // n! is exact in double up to 22!
    for (int i = 2; i <= n; ++i) f *= i;
    return 1.0 / f;
}

}  // namespace fast_sincos_detail

inline SinCos fast_sincos(double x) {
    namespace d = fast_sincos_detail;
    if (!(std::abs(x) <= d::kMaxReduced)) return {std::sin(x), std::cos(x)};  // NaN fails this test too
    constexpr auto f = d::inverse_factorial;
    if (std::abs(x) <= d::kSmall) {
        // A rocking wall's angles are mostly this small (a slender wall's alpha1 and all its rotations): the series
        // to x^9 and x^10, two levels of Estrin's scheme instead of three, is a shorter chain for each stage to wait
        // on (the Rinaldi record run: 0.93 of the time). The same forms as below.
        const double z = x * x, z2 = z * z;
        const double ps = (-f(3) + z * f(5)) + z2 * (-f(7) + z * f(9));
        const double pc = (f(4) - z * f(6)) + z2 * (f(8) - z * f(10));
        const double half_z = 0.5 * z, w = 1.0 - half_z;
        return {x + x * z * ps, w + (((1.0 - w) - half_z) + z2 * pc)};
    }
    // Most of the models' angles are within pi/4 already, where the reduction would give k = 0 and r = x exactly:
    // skipping it takes a quarter off the latency, which is what counts in a chain of dependent evaluations.
    double k = 0.0, r = x;
    if (!(std::abs(x) <= d::kQuarterPi)) {
        k = (x * d::kTwoOverPi + d::kRoundMagic) - d::kRoundMagic;
        r = ((x - k * d::kPio2Hi) - k * d::kPio2Mid) - k * d::kPio2Lo;
    }
    // The Taylor polynomials in z = r^2 by Estrin's scheme (pairs of terms combined with z, z^2, z^4): the same
    // terms as Horner's rule with a third of its chain of dependent operations (measured 1.5 times glibc's
    // latency with Horner, 0.7 times with this).
    const double z = r * r, z2 = z * z, z4 = z2 * z2;
    // sin r = r (1 - z/3! + ... + z^8/17!)
    const double ps = (-f(3) + z * f(5)) + z2 * (-f(7) + z * f(9)) +
                      z4 * ((-f(11) + z * f(13)) + z2 * (-f(15) + z * f(17)));
    // cos r = 1 - z/2 + z^2 (1/4! - z/6! + ... + z^7/18!), with 1 - z/2 carried in two parts (w and the rounding
    // error of 1 - w - z/2, exact by Sterbenz): the term that rounds worst near r = pi/4 adds no error of its own.
    const double pc = (f(4) - z * f(6)) + z2 * (f(8) - z * f(10)) +
                      z4 * ((f(12) - z * f(14)) + z2 * (f(16) - z * f(18)));
    const double s = r + r * z * ps;
    const double half_z = 0.5 * z, w = 1.0 - half_z;
    const double c = w + (((1.0 - w) - half_z) + z2 * pc);
    // Quadrant k mod 4 (two's complement: -1 & 3 = 3): sin(r + k pi/2), cos(r + k pi/2).
    switch (static_cast<long long>(k) & 3) {
        case 0: return {s, c};
        case 1: return {c, -s};
        case 2: return {-s, -c};
        default: return {-c, s};
    }
}

}  // namespace vssw
