#include "motions/parameter_draws.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "analytic/error.hpp"
#include "analytic/ground_motion.hpp"
#include "motions/special_functions.hpp"

namespace vssw::motions {
namespace {

// Rezaeian & Der Kiureghian (2010), fitted marginals (docs/ground-motions.md, "Parameters", which gives the source).
constexpr double kLnAriasMean = -4.8255, kLnAriasSd = 1.4318;  // ln(I_a [s g])
struct BetaOn {
    double lo, hi, a, b;
};
constexpr BetaOn kD595Beta{5.0, 45.0, 1.1314, 2.4474};
constexpr BetaOn kTmidBeta{0.5, 40.0, 1.5792, 3.6405};
constexpr BetaOn kDampingBeta{0.02, 1.0, 1.4250, 5.7208};
constexpr double kFreqShape = 4.0982, kFreqScale = 1.4330;
// Two-sided exponential of w'/2pi on [kSlopeLo, kSlopeHi]: c exp(b x) for x < 0, c exp(-a x) for x >= 0.
constexpr double kSlopeA = 17.095, kSlopeB = 6.7729, kSlopeC = 4.8512, kSlopeLo = -2.0, kSlopeHi = 0.5;

// Rezaeian, Zhong & Zareian (2015): the means of v_1..v_6 (coefficients b0..b4 of the forms in parameter_draws.hpp),
// the within-event and between-event standard deviations, the total-error correlations.
constexpr double kBeta[kParameterCount][5] = {
    {-2.2962, 2.9440, -0.0707, -1.3564, -0.2654}, {-6.1946, 0.9703, -0.7034, 0.0087, -0.0007},
    {-5.0105, 0.6625, -0.3450, 0.0139, -0.0002},  {2.2525, -0.2586, -0.0808, -0.0084, 0.0000},
    {-2.4886, 0.3440, 0.0441, 0.0026, -0.0001},   {-0.2583, 0.1293, -0.4772, -0.0115, 0.0004}};
constexpr double kSigma[kParameterCount] = {0.5937, 0.5688, 0.4145, 0.7228, 0.9529, 0.7601};
constexpr double kTau[kParameterCount] = {0.2738, 0.4574, 0.5114, 0.6918, 0.1286, 0.6815};
constexpr double kRho[kParameterCount][kParameterCount] = {
    {1.0000, -0.3555, 0.0066, -0.1545, 0.1341, -0.0078}, {-0.3555, 1.0000, 0.6729, -0.1303, -0.1576, -0.1958},
    {0.0066, 0.6729, 1.0000, -0.2761, -0.1977, -0.2188}, {-0.1545, -0.1303, -0.2761, 1.0000, -0.2034, 0.2814},
    {0.1341, -0.1576, -0.1977, -0.2034, 1.0000, -0.0137}, {-0.0078, -0.1958, -0.2188, 0.2814, -0.0137, 1.0000}};

// Draws of v beyond 8 standard deviations (probability 1e-15) are held there: Phi(v) rounds to 1 past 8.3.
constexpr double kMaxNormal = 8.0;
// Draws again at most this often before giving up on medians no modulation can have.
constexpr int kMaxDraws = 1000;
// zeta_f's distribution reaches 1, where the filter is critically damped and the model's h(t) divides by zero; the
// draws above 0.95 (probability 2e-7) are held there.
constexpr double kMaxDamping = 0.95;
constexpr double kMaxScatter = 2.0;

const char* const kOption[kParameterCount] = {"--arias", "--d5-95", "--t-mid", "--mid-frequency", "--frequency-slope",
                                              "--damping"};

double slope_cdf(double x) {
    const double at_zero = kSlopeC / kSlopeB * (1.0 - std::exp(kSlopeB * kSlopeLo));
    if (x <= kSlopeLo) return 0.0;
    if (x < 0.0) return kSlopeC / kSlopeB * (std::exp(kSlopeB * x) - std::exp(kSlopeB * kSlopeLo));
    return std::min(1.0, at_zero + kSlopeC / kSlopeA * (1.0 - std::exp(-kSlopeA * std::min(x, kSlopeHi))));
}

double slope_quantile(double p) {
    const double at_zero = kSlopeC / kSlopeB * (1.0 - std::exp(kSlopeB * kSlopeLo));
    double x = p < at_zero ? std::log(p * kSlopeB / kSlopeC + std::exp(kSlopeB * kSlopeLo)) / kSlopeB
                           : -std::log1p(-(p - at_zero) * kSlopeA / kSlopeC) / kSlopeA;
    if (!std::isfinite(x)) x = p < at_zero ? kSlopeLo : kSlopeHi;
    return std::clamp(x, kSlopeLo, kSlopeHi);
}

double beta_cdf(const BetaOn& d, double x) { return beta_i(d.a, d.b, (x - d.lo) / (d.hi - d.lo)); }
double beta_quantile(const BetaOn& d, double p) { return d.lo + (d.hi - d.lo) * beta_i_inverse(d.a, d.b, p); }

// The mean of v_j for a scenario.
double scenario_mean(int j, const Scenario& s) {
    const double* b = kBeta[j];
    const double f = s.reverse ? 1.0 : 0.0;
    if (j == kArias)
        return b[0] + b[1] * s.magnitude / 7.0 + b[2] * f + b[3] * std::log(s.distance_km / 25.0) +
               b[4] * std::log(s.vs30_m_s / 750.0);
    return b[0] + b[1] * s.magnitude + b[2] * f + b[3] * s.distance_km + b[4] * s.vs30_m_s;
}

struct NormalSpace {
    Eigen::Matrix<double, kParameterCount, 1> mean;
    Eigen::Matrix<double, kParameterCount, kParameterCount> factor;  // lower Cholesky factor of the covariance
};

NormalSpace normal_space(const DrawSettings& s) {
    NormalSpace n;
    const bool site = s.scenario.has_value() ||
                      std::any_of(s.medians.begin(), s.medians.end(), [](const auto& m) { return m.has_value(); });
    Eigen::Matrix<double, kParameterCount, kParameterCount> cov;
    for (int j = 0; j < kParameterCount; ++j) {
        const Parameter pj = static_cast<Parameter>(j);
        n.mean[j] = s.medians[j]        ? normal_quantile(marginal_cdf(pj, *s.medians[j]))
                    : s.scenario        ? scenario_mean(j, *s.scenario)
                                        : 0.0;
        for (int k = 0; k < kParameterCount; ++k) {
            const bool own_j = s.medians[j] || s.scenario, own_k = s.medians[k] || s.scenario;
            const double sd_j = own_j ? std::hypot(kSigma[j], kTau[j]) : 1.0;
            const double sd_k = own_k ? std::hypot(kSigma[k], kTau[k]) : 1.0;
            cov(j, k) = (site ? kRho[j][k] : (j == k ? 1.0 : 0.0)) * sd_j * sd_k;
        }
    }
    n.factor = cov.llt().matrixL();
    return n;
}

ModelParameters from_normal(const Eigen::Matrix<double, kParameterCount, 1>& v) {
    double theta[kParameterCount];
    for (int j = 0; j < kParameterCount; ++j)
        theta[j] = marginal_quantile(static_cast<Parameter>(j), normal_cdf(std::clamp(v[j], -kMaxNormal, kMaxNormal)));
    return {theta[kArias], theta[kD595], theta[kTmid], theta[kMidFrequency], theta[kSlope],
            std::min(theta[kDamping], kMaxDamping)};
}

// A median's v_j is Phi^-1(F_j(median)): in the upper tail F_j is 1 - q, q known only to the 1.1e-16 spacing of doubles
// below 1, so v_j comes back off by 1.1e-16 / phi(v_j) (the sweep: --arias 5000, v 7.7, gave 4967.5). At 6 that is
// 2e-8, a parameter to 3e-8; past it the error grows ~e^(v^2/2). The upper ends of the medians' ranges stop there
// (the lower tail's F_j keeps its relative precision: those ends are the draws' own, kMaxNormal).
constexpr double kHonouredUpperNormal = 6.0;
// A range's ends are printed and checked at this many significant digits (median_range).
constexpr int kRangeDigits = 6;

// x rounded to `digits` significant digits towards +inf (direction +1) or -inf (-1): an end moved inward, so that
// every value within the printed range is one the model reaches.
double rounded_inward(double x, int digits, double direction) {
    if (x == 0.0 || !std::isfinite(x)) return x;
    const double unit = std::pow(10.0, std::floor(std::log10(std::abs(x))) - (digits - 1));
    const double r = (direction > 0.0 ? std::ceil(x / unit) : std::floor(x / unit)) * unit;
    // Parsed back from its printed digits: the end checked is the very number the message shows.
    return std::strtod(fmt::format("{:.{}g}", r, digits).c_str(), nullptr);
}

}  // namespace

double marginal_cdf(Parameter j, double value) {
    switch (j) {
    case kArias: return normal_cdf((std::log(value / kStandardGravity) - kLnAriasMean) / kLnAriasSd);
    case kD595: return beta_cdf(kD595Beta, value);
    case kTmid: return beta_cdf(kTmidBeta, value);
    case kMidFrequency: return gamma_p(kFreqShape, value / kFreqScale);
    case kSlope: return slope_cdf(value);
    case kDamping: return beta_cdf(kDampingBeta, value);
    default: return 0.0;
    }
}

double marginal_quantile(Parameter j, double p) {
    switch (j) {
    case kArias: return kStandardGravity * std::exp(kLnAriasMean + kLnAriasSd * normal_quantile(p));
    case kD595: return beta_quantile(kD595Beta, p);
    case kTmid: return beta_quantile(kTmidBeta, p);
    case kMidFrequency: return kFreqScale * gamma_p_inverse(kFreqShape, p);
    case kSlope: return slope_quantile(p);
    case kDamping: return beta_quantile(kDampingBeta, p);
    default: return 0.0;
    }
}

MedianRange median_range(Parameter j) {
    const double lo[kParameterCount] = {0.0, kD595Beta.lo, kTmidBeta.lo, 0.0, kSlopeLo, kDampingBeta.lo};
    const double hi[kParameterCount] = {HUGE_VAL, kD595Beta.hi, kTmidBeta.hi, HUGE_VAL, kSlopeHi, kMaxDamping};
    const double reach_lo = marginal_quantile(j, normal_cdf(-kMaxNormal));
    const double reach_hi = marginal_quantile(j, normal_cdf(kHonouredUpperNormal));
    return {rounded_inward(std::max(lo[j], reach_lo), kRangeDigits, +1.0),
            rounded_inward(std::min(hi[j], reach_hi), kRangeDigits, -1.0)};
}

std::string median_range_text(Parameter j) {
    const MedianRange r = median_range(j);
    return fmt::format("from {:g} to {:g}", r.lo, r.hi);
}

void check_draw_settings(const DrawSettings& s) {
    for (int j = 0; j < kParameterCount; ++j) {
        if (!s.medians[j]) continue;
        const double m = *s.medians[j];
        const MedianRange r = median_range(static_cast<Parameter>(j));
        if (!(m >= r.lo && m <= r.hi))
            throw InputError(fmt::format("{} must be {}, the medians the model's fitted distribution gives back "
                                         "as given, got {:g}",
                                         kOption[j], median_range_text(static_cast<Parameter>(j)), m));
    }
    if (s.scenario) {
        require(s.scenario->magnitude >= 5.0 && s.scenario->magnitude <= 8.0, "--magnitude", "from 5 to 8",
                s.scenario->magnitude);
        require(s.scenario->distance_km >= 1.0 && s.scenario->distance_km <= 200.0, "--distance [km]",
                "from 1 to 200", s.scenario->distance_km);
        require(s.scenario->vs30_m_s >= 150.0 && s.scenario->vs30_m_s <= 2000.0, "--vs30 [m/s]", "from 150 to 2000",
                s.scenario->vs30_m_s);
    }
    require(s.scatter >= 0.0 && s.scatter <= kMaxScatter, "--scatter", "from 0 to 2", s.scatter);
}

ModelParameters median_parameters(const DrawSettings& settings) {
    return from_normal(normal_space(settings).mean);
}

ModelParameters draw_parameters(const DrawSettings& settings, RandomStream& random) {
    const NormalSpace n = normal_space(settings);
    for (int attempt = 0; attempt < kMaxDraws; ++attempt) {
        Eigen::Matrix<double, kParameterCount, 1> z;
        for (int j = 0; j < kParameterCount; ++j) z[j] = random.normal();
        const ModelParameters p = from_normal(n.mean + settings.scatter * (n.factor * z));
        if (p.d5_95_s <= max_duration_ratio() * p.t_mid_s) return p;
    }
    const ModelParameters m = median_parameters(settings);
    throw InputError(fmt::format("no motion could be drawn: {} draws in a row had D5-95 above 4.92 t_mid, which no "
                                 "gamma modulation has (median D5-95 {:g} s, t_mid {:g} s)",
                                 kMaxDraws, m.d5_95_s, m.t_mid_s));
}

}  // namespace vssw::motions
