#pragma once
// The site-based stochastic ground-motion model of Rezaeian & Der Kiureghian (2008, Earthquake Engng Struct. Dyn.
// 37:1565-1584; 2010, 39:1155-1180): a time-modulated, filtered white noise, high-pass filtered
// (docs/ground-motions.md, "The generator", which gives each equation with the papers' numbers).
//
//   x(t) = q(t) * sum_i s_i(t) u_i,  s_i(t) = h(t - t_i; w_f(t_i)) / sqrt(sum_{t_j <= t} h(t - t_j; w_f(t_j))^2),
//   h(s; w)  = w / sqrt(1 - zeta_f^2) exp(-zeta_f w s) sin(w sqrt(1 - zeta_f^2) s) for s >= 0, else 0,
//   w_f(tau) = w_mid + w' (tau - t_mid),   q(t) = alpha1 t^(alpha2 - 1) exp(-alpha3 t),
//
// u_i independent standard normal at the sample times t_i = i dt: the filtered noise has unit variance at every t,
// so E[a(t)^2] = q(t)^2 and the expected Arias intensity is pi / (2 g) * integral q^2 dt. The ground acceleration is
// then the response u'' of a critically damped oscillator u'' + 2 w_c u' + w_c^2 u = x(t) (corner f_c = w_c / 2 pi):
// a high-pass filter whose output integrates to velocity u'(t) and displacement u(t), both back to ~0 once the
// oscillator has come to rest after the shaking.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "motions/random_stream.hpp"

namespace vssw::motions {

// The model's six physical parameters.
struct ModelParameters {
    double arias_m_s;           // I_a [m/s] (pi / 2g * integral a^2 dt)
    double d5_95_s;             // D5-95 [s]
    double t_mid_s;             // t_mid, the time at 45 % of I_a [s]
    double mid_frequency_hz;    // w_mid / 2 pi [Hz]
    double slope_hz_per_s;      // w' / 2 pi [Hz/s]
    double damping;             // zeta_f, 0 < zeta_f < 1
};

// The gamma-shaped modulation q(t) = alpha1 t^(alpha2 - 1) exp(-alpha3 t) [m/s^2, t in s].
struct Modulation {
    double alpha1, alpha2, alpha3;
    double operator()(double t) const;
    // The time at which `fraction` of integral q^2 has passed: P^-1(2 alpha2 - 1, fraction) / (2 alpha3) [s].
    double energy_time(double fraction) const;
};

// The modulation whose q^2 has D5-95, t_mid and Arias intensity as given. q^2 is a gamma density of shape
// k = 2 alpha2 - 1 and rate 2 alpha3 (times a constant), so t_p = P^-1(k, p) / (2 alpha3): the ratio D5-95 / t_mid
// fixes k alone, solved by bisection, then alpha3 = P^-1(k, 0.45) / (2 t_mid) and alpha1 from
// I_a = pi / (2g) alpha1^2 Gamma(k) / (2 alpha3)^k. Nothing when the ratio needs alpha2 <= 1 (D5-95 > 4.92 t_mid):
// q(t) would be infinite at t = 0.
std::optional<Modulation> modulation_for(double arias_m_s, double d5_95_s, double t_mid_s);
// The largest D5-95 / t_mid a modulation with alpha2 >= 1 has (4.92, an exponential q^2).
double max_duration_ratio();

struct SimulationSettings {
    double dt = 0.005;                // the sample step [s]
    std::optional<double> duration;   // [s]; default: default_duration()
    double corner_hz = 0.2;           // f_c of the high-pass filter [Hz]
};

// InputError naming the option (--dt, --duration, --corner) when a setting is out of range: dt in (0, 0.1] s, a
// duration longer than dt and of at most 10^7 samples, a positive corner frequency.
void check_settings(const SimulationSettings& settings);

// Lowest and highest filter frequency w_f / 2 pi [Hz]: w' moves w_f linearly and the line may cross zero within a
// long record (a slope of -2 Hz/s ten seconds after t_mid); w_f is held at 0.3 Hz there, a frequency the high-pass
// filter passes, and at most a quarter of the sampling rate, so that the sampled oscillator keeps four samples a
// period.
constexpr double kMinFilterHz = 0.3;
double max_filter_hz(double dt);
// The damped filter's impulse response is followed until exp(-zeta w s) < exp(-25) (1e-11 of its start).
constexpr double kImpulseDecay = 25.0;

// The record length when --duration is not given: the time at 99.9 % of integral q^2, then 12 / w_c for the
// high-pass oscillator to come to rest (its free motion decays as (1 + w_c t) exp(-w_c t): below 1e-4 by then).
double default_duration(const Modulation& q, double corner_hz);

// The filter's cost bound: each sample's impulse response is followed for 25 / (zeta w dt) samples, so a long record
// at low damping and frequency costs samples x span steps, quadratic in its length (--damping 0.021
// --mid-frequency 0.31 --duration 500 took 16 s; at --duration 50000 it would take hours). Measured about 3e8 steps
// a second (0.98 s for 3.1e8 steps, the 125 s record of that case); the bound is some 100 s of CPU a motion, 20 times
// the cost of that 500 s record.
constexpr double kFilterStepsPerSecond = 3e8;
constexpr double kMaxFilterSteps = 3e10;
// The samples of the motion with parameters p: InputError naming the options (--duration or the default length with
// --corner, --dt) past 1e7 samples, or (--duration, --dt, --damping, --mid-frequency) past kMaxFilterSteps; `what`
// names the motion ("motion 3", "the median motion"). 0 when no modulation has p's D5-95 and t_mid.
std::size_t record_samples(const ModelParameters& p, const SimulationSettings& settings, const std::string& what);

// One motion: accelerations [m/s^2] at t_i = i dt, i = 0 .. floor(duration / dt). Consumes one standard normal per
// sample from `random`. InputError when the parameters or settings are out of range.
std::vector<double> simulate(const ModelParameters& p, const SimulationSettings& settings, RandomStream& random);

}  // namespace vssw::motions
