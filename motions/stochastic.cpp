#include "motions/stochastic.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "analytic/ground_motion.hpp"
#include "motions/special_functions.hpp"

namespace vssw::motions {
namespace {

// Fractions of integral q^2 that define D5-95 and t_mid (Rezaeian & Der Kiureghian 2010, their Eqs. for D5-95 and
// t_mid; docs/ground-motions.md).
constexpr double kP05 = 0.05, kP95 = 0.95, kPmid = 0.45;
// The shape k = 2 alpha2 - 1 is bisected on [1, 1e6]: k = 1 is alpha2 = 1 (q finite at t = 0); k = 1e6 gives
// D5-95 / t_mid = 0.0033, far below any record's ratio (the fitted ranges give at least 5 / 40).
constexpr double kMinShape = 1.0, kMaxShape = 1e6;
// The high-pass oscillator rests 12 / w_c after the shaking: (1 + 12) exp(-12) < 1e-4.
constexpr double kRestTimes = 12.0;
// The fraction of integral q^2 the default record holds.
constexpr double kEnergyKept = 0.999;
// The largest record: 10^7 samples (80 MB of doubles while it is made), far beyond any earthquake's few minutes.
constexpr double kMaxSamples = 1e7;

double duration_ratio(double k) {
    const double t05 = gamma_p_inverse(k, kP05), t95 = gamma_p_inverse(k, kP95), tmid = gamma_p_inverse(k, kPmid);
    return (t95 - t05) / tmid;
}

void check_parameters(const ModelParameters& p, const SimulationSettings& s) {
    require(std::isfinite(p.arias_m_s) && p.arias_m_s > 0.0, "the Arias intensity [m/s]", "positive", p.arias_m_s);
    require(std::isfinite(p.d5_95_s) && p.d5_95_s > 0.0, "D5-95 [s]", "positive", p.d5_95_s);
    require(std::isfinite(p.t_mid_s) && p.t_mid_s > 0.0, "t_mid [s]", "positive", p.t_mid_s);
    require(std::isfinite(p.mid_frequency_hz) && p.mid_frequency_hz > 0.0, "the mid frequency [Hz]", "positive",
            p.mid_frequency_hz);
    require(std::isfinite(p.slope_hz_per_s), "the frequency slope [Hz/s]", "finite", p.slope_hz_per_s);
    require(p.damping > 0.0 && p.damping < 1.0, "the filter damping", "between 0 and 1", p.damping);
    check_settings(s);
}

}  // namespace

void check_settings(const SimulationSettings& s) {
    require(std::isfinite(s.dt) && s.dt > 0.0 && s.dt <= 0.1, "--dt [s]", "positive and at most 0.1", s.dt);
    require(std::isfinite(s.corner_hz) && s.corner_hz > 0.0, "--corner [Hz]", "positive", s.corner_hz);
    if (s.duration)
        require(std::isfinite(*s.duration) && *s.duration > s.dt && *s.duration / s.dt <= kMaxSamples,
                "--duration [s]", fmt::format("longer than dt and at most {:g} samples", kMaxSamples), *s.duration);
}

namespace {

// The samples an impulse's response is followed for: until exp(-zeta w s) < exp(-kImpulseDecay).
double impulse_span(double damping, double w, double dt) { return std::ceil(kImpulseDecay / (damping * w * dt)); }
std::size_t impulse_end(std::size_t i, std::size_t n, double span) {
    return span >= static_cast<double>(n - i) ? n : i + static_cast<std::size_t>(span);
}
// w_f(t) in rad/s, held within [kMinFilterHz, max_filter_hz(dt)].
double filter_w(const ModelParameters& p, double t, double dt) {
    return 2.0 * M_PI * std::clamp(p.mid_frequency_hz + p.slope_hz_per_s * (t - p.t_mid_s), kMinFilterHz,
                                   max_filter_hz(dt));
}

// Sum_i h(t - t_i; w_f(t_i)) u_i / sqrt(sum_i h^2), the unit-variance filtered noise at every sample. Each impulse's
// response is a damped sine sampled at steps dt: the complex number exp((-zeta w + i w_d) m dt), advanced by one
// multiplication a step, gives it without a sine or exponential per sample.
std::vector<double> filtered_noise(const ModelParameters& p, double dt, std::size_t n, RandomStream& random) {
    std::vector<double> num(n, 0.0), den(n, 0.0);
    const double root = std::sqrt(1.0 - p.damping * p.damping);
    for (std::size_t i = 0; i < n; ++i) {
        const double u = random.normal();
        const double t = static_cast<double>(i) * dt;
        const double w = filter_w(p, t, dt);
        const double gain = w / root;
        const double decay = std::exp(-p.damping * w * dt);
        const double step_re = decay * std::cos(w * root * dt), step_im = decay * std::sin(w * root * dt);
        const std::size_t end = impulse_end(i, n, impulse_span(p.damping, w, dt));
        double re = 1.0, im = 0.0;  // exp((-zeta w + i w_d) (k - i) dt), from k = i
        for (std::size_t k = i + 1; k < end; ++k) {
            const double next_re = re * step_re - im * step_im;
            im = re * step_im + im * step_re;
            re = next_re;
            const double h = gain * im;
            num[k] += h * u;
            den[k] += h * h;
        }
    }
    for (std::size_t k = 0; k < n; ++k) num[k] = den[k] > 0.0 ? num[k] / std::sqrt(den[k]) : 0.0;
    return num;
}

// The critically damped oscillator u'' + 2 w_c u' + w_c^2 u = x, from rest, by Newmark's average acceleration
// (trapezoidal in u' and u: the trapezoidal integral of the output u'' is the oscillator's u' exactly). Returns u''.
std::vector<double> high_pass(const std::vector<double>& x, double dt, double corner_hz) {
    const double wc = 2.0 * M_PI * corner_hz, c = 2.0 * wc, k = wc * wc;
    const double lhs = 1.0 + c * dt / 2.0 + k * dt * dt / 4.0;
    std::vector<double> out(x.size());
    double u = 0.0, v = 0.0, a = x.empty() ? 0.0 : x[0];
    if (!x.empty()) out[0] = a;
    for (std::size_t i = 1; i < x.size(); ++i) {
        const double v_pred = v + dt / 2.0 * a, u_pred = u + dt * v + dt * dt / 4.0 * a;
        const double a_next = (x[i] - c * v_pred - k * u_pred) / lhs;
        v = v_pred + dt / 2.0 * a_next;
        u = u_pred + dt * dt / 4.0 * a_next;
        a = a_next;
        out[i] = a;
    }
    return out;
}

}  // namespace

std::size_t record_samples(const ModelParameters& p, const SimulationSettings& s, const std::string& what) {
    const std::optional<Modulation> q = modulation_for(p.arias_m_s, p.d5_95_s, p.t_mid_s);
    if (!q) return 0;  // simulate names the parameters no modulation has
    const double duration = s.duration ? *s.duration : default_duration(*q, s.corner_hz);
    const double samples = duration / s.dt;
    if (!(samples <= kMaxSamples)) {
        const std::string length =
            s.duration ? fmt::format("--duration {:g} s", *s.duration)
                       : fmt::format("the default length {:.4g} s ({}'s modulation to 99.9 % of its energy, then 12/w_c "
                                     "for --corner {:g} Hz)",
                                     duration, what, s.corner_hz);
        throw InputError(fmt::format("{} / --dt {:g} s is {:.4g} samples, more than the {:g} allowed: give a larger "
                                     "--dt{}",
                                     length, s.dt, samples, kMaxSamples, s.duration ? " or a shorter --duration"
                                                                                    : ", a larger --corner or --duration"));
    }
    const std::size_t n = static_cast<std::size_t>(std::floor(samples)) + 1;
    // The filter's cost: each sample's impulse response followed for its span (filtered_noise), summed.
    double steps = 0.0;
    double longest = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const double span = impulse_span(p.damping, filter_w(p, static_cast<double>(i) * s.dt, s.dt), s.dt);
        steps += static_cast<double>(impulse_end(i, n, span) - i);
        longest = std::max(longest, span);
    }
    if (steps > kMaxFilterSteps)
        throw InputError(fmt::format("{} would take {:.3g} filter steps ({} samples, each impulse followed for up to "
                                     "{:.3g} samples at damping {:g}), more than the {:g} allowed (about {:.0f} s of "
                                     "CPU): give a shorter --duration, a larger --dt, or a larger --damping or "
                                     "--mid-frequency",
                                     what, steps, n, std::min(longest, static_cast<double>(n)), p.damping,
                                     kMaxFilterSteps, kMaxFilterSteps / kFilterStepsPerSecond));
    return n;
}

double Modulation::operator()(double t) const {
    if (!(t > 0.0)) return 0.0;
    return alpha1 * std::exp((alpha2 - 1.0) * std::log(t) - alpha3 * t);
}

double Modulation::energy_time(double fraction) const {
    return gamma_p_inverse(2.0 * alpha2 - 1.0, fraction) / (2.0 * alpha3);
}

std::optional<Modulation> modulation_for(double arias_m_s, double d5_95_s, double t_mid_s) {
    if (!(arias_m_s > 0.0 && d5_95_s > 0.0 && t_mid_s > 0.0)) return std::nullopt;
    const double target = d5_95_s / t_mid_s;
    double lo = std::log(kMinShape), hi = std::log(kMaxShape);
    if (target > max_duration_ratio() || target < duration_ratio(kMaxShape)) return std::nullopt;
    // The ratio falls as k grows (the gamma density narrows about its mean, relative to it).
    for (int i = 0; i < 200 && hi - lo > 1e-14; ++i) {
        const double mid = 0.5 * (lo + hi);
        (duration_ratio(std::exp(mid)) > target ? lo : hi) = mid;
    }
    const double k = std::exp(0.5 * (lo + hi));
    Modulation q{};
    q.alpha2 = (k + 1.0) / 2.0;
    q.alpha3 = gamma_p_inverse(k, kPmid) / (2.0 * t_mid_s);
    // I_a = pi / (2 g0) alpha1^2 Gamma(k) / (2 alpha3)^k, in logarithms (Gamma(k) overflows past k = 171).
    q.alpha1 = std::exp(0.5 * (std::log(arias_m_s * 2.0 * kStandardGravity / M_PI) + k * std::log(2.0 * q.alpha3) -
                               std::lgamma(k)));
    return q;
}

double max_duration_ratio() {
    static const double ratio = duration_ratio(kMinShape);
    return ratio;
}

double max_filter_hz(double dt) { return 0.25 / dt; }

double default_duration(const Modulation& q, double corner_hz) {
    return q.energy_time(kEnergyKept) + kRestTimes / (2.0 * M_PI * corner_hz);
}

std::vector<double> simulate(const ModelParameters& p, const SimulationSettings& settings, RandomStream& random) {
    check_parameters(p, settings);
    const std::optional<Modulation> q = modulation_for(p.arias_m_s, p.d5_95_s, p.t_mid_s);
    if (!q)
        throw InputError(fmt::format("D5-95 = {:g} s and t_mid = {:g} s: the gamma modulation needs D5-95 below "
                                     "{:.3g} t_mid (alpha2 > 1)",
                                     p.d5_95_s, p.t_mid_s, max_duration_ratio()));
    const std::size_t n = record_samples(p, settings, "a motion");
    std::vector<double> x = filtered_noise(p, settings.dt, n, random);
    for (std::size_t i = 0; i < n; ++i) x[i] *= (*q)(static_cast<double>(i) * settings.dt);
    return high_pass(x, settings.dt, settings.corner_hz);
}

}  // namespace vssw::motions
