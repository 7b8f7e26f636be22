#pragma once
// The sine and cosine of one angle together, for the model terms that every integrator stage evaluates (Eq. 11's
// coefficients, the exact kinematics' angles, the parapet, the two blocks' turns). glibc's sincos was the largest
// single cost of an analytic run (about 30 % of the Fig. 6 free vibration's instructions, callgrind); this one is
// a third of its instructions and within a few ulp of it (tests/test_fast_sincos.cpp).
//
// Method: x = k pi/2 + r with |r| <= pi/4 (Cody & Waite's reduction with pi/2 in three parts), then the Taylor
// series of sin r and cos r in r^2, to r^17 and r^18: on |r| <= pi/4 the first omitted terms, (pi/4)^19 / 19! and
// (pi/4)^20 / 20!, are below 1e-19, far under half an ulp of the results (>= 0.7 there). The coefficients are 1/n!.
// Arguments beyond kMaxReduced (and NaN, infinities) go to std::sin and std::cos.
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
    const double k = (x * d::kTwoOverPi + d::kRoundMagic) - d::kRoundMagic;
    const double r = ((x - k * d::kPio2Hi) - k * d::kPio2Mid) - k * d::kPio2Lo;
    const double r2 = r * r;
    constexpr auto f = d::inverse_factorial;
    // Horner in r^2: sin r = r (1 - r^2/3! + ... + r^16/17!), cos r = 1 - r^2/2! + ... + r^18/18!.
    const double ps = -f(3) + r2 * (f(5) + r2 * (-f(7) + r2 * (f(9) + r2 * (-f(11) + r2 * (f(13) + r2 * (-f(15) +
                                                                                                       r2 * f(17)))))));
    const double pc = -f(2) + r2 * (f(4) + r2 * (-f(6) + r2 * (f(8) + r2 * (-f(10) + r2 * (f(12) + r2 * (-f(14) +
                                                                                                     r2 * (f(16) - r2 * f(18))))))));
    const double s = r + r * r2 * ps;
    const double c = 1.0 + r2 * pc;
    // Quadrant k mod 4 (two's complement: -1 & 3 = 3): sin(r + k pi/2), cos(r + k pi/2).
    switch (static_cast<long long>(k) & 3) {
        case 0: return {s, c};
        case 1: return {c, -s};
        case 2: return {-s, -c};
        default: return {-c, s};
    }
}

}  // namespace vssw
