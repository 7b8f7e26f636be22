#pragma once
// The model parameters of each generated motion, drawn for a site (docs/ground-motions.md, "Parameters"):
//
// - the fitted marginal distributions of the six parameters over Rezaeian & Der Kiureghian's (2010) NGA data set
//   of far-field records on firm ground (their table of the parameters' statistics): ln I_a [s g] normal
//   (-4.8255, 1.4318); D5-95 = 5 + 40 Beta(1.1314, 2.4474) s; t_mid = 0.5 + 39.5 Beta(1.5792, 3.6405) s;
//   w_mid / 2 pi Gamma(shape 4.0982, scale 1.4330) Hz; w' / 2 pi two-sided exponential on [-2, 0.5] Hz/s, density
//   4.8512 exp(6.7729 x) below 0 and 4.8512 exp(-17.095 x) above; zeta_f = 0.02 + 0.98 Beta(1.4250, 5.7208).
//   Each parameter theta_j is F_j^-1(Phi(v_j)) of a standard normal v_j.
// - for a scenario (magnitude M, rupture distance R [km], Vs30 [m/s], strike-slip or reverse faulting F), the
//   predictive equations of Rezaeian, Zhong & Zareian (2015, the RZZ model), which give the mean of each v_j:
//   v_1 = b0 + b1 M/7 + b2 F + b3 ln(R/25) + b4 ln(Vs30/750), v_j = b0 + b1 M + b2 F + b3 R + b4 Vs30 (j = 2..6),
//   with total standard deviations sqrt(sigma^2 + tau^2) and the total-error correlations between the six.
// - given medians: v_j's mean is Phi^-1(F_j(median)), its scatter that of the scenario equations.
//
// Without a scenario or a median the six v_j are independent standard normals (the data set's marginals; the 2010
// paper's correlations are not used). A draw whose D5-95 exceeds 4.92 t_mid (no gamma modulation with alpha2 > 1
// has it) is drawn again from the same stream.
#include <array>
#include <optional>
#include <string>

#include "motions/random_stream.hpp"
#include "motions/stochastic.hpp"

namespace vssw::motions {

struct Scenario {
    double magnitude;     // moment magnitude, 5 .. 8 (about the data's range)
    double distance_km;   // closest distance to the rupture, 1 .. 200 km
    double vs30_m_s;      // 150 .. 2000 m/s
    bool reverse;         // reverse or reverse-oblique faulting (F = 1); strike-slip otherwise (F = 0)
};

// The six parameters in ModelParameters' order.
enum Parameter { kArias = 0, kD595, kTmid, kMidFrequency, kSlope, kDamping, kParameterCount };

struct DrawSettings {
    std::optional<Scenario> scenario;
    // A median for any of the six (ModelParameters' units); it replaces the scenario's.
    std::array<std::optional<double>, kParameterCount> medians;
    // Scales the scatter in normal space: 1 as published, 0 for the medians themselves.
    double scatter = 1.0;
};

// The medians the model can honour, both ends included: a median's v_j = Phi^-1(F_j(median)) is held within 8
// standard deviations like every draw, and above 6 it no longer comes back from F_j to 1e-8 (rounding near 1), so
// the range is F_j's quantiles from Phi(-8) to Phi(6) (also within the support, and damping at most 0.95, where the
// draws are held), rounded inward to 6 significant digits: a median inside is the parameter at --scatter 0 to 1e-6.
struct MedianRange {
    double lo, hi;
};
MedianRange median_range(Parameter j);
// "from LO to HI", as the option's help and its refusal state it.
std::string median_range_text(Parameter j);

// InputError naming the option, value and range when a median lies outside median_range, a scenario outside the
// ranges above, or the scatter outside [0, 2].
void check_draw_settings(const DrawSettings& settings);
// The median of each parameter under `settings` (ModelParameters' units).
ModelParameters median_parameters(const DrawSettings& settings);
// One motion's parameters (InputError when 1000 draws in a row cannot be modulated: medians that force D5-95 above
// 4.92 t_mid).
ModelParameters draw_parameters(const DrawSettings& settings, RandomStream& random);

// The marginal distribution of parameter j: F_j and its inverse, in ModelParameters' units.
double marginal_cdf(Parameter j, double value);
double marginal_quantile(Parameter j, double p);

}  // namespace vssw::motions
