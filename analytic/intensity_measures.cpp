#include "analytic/intensity_measures.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "analytic/error.hpp"

namespace vssw {
namespace {

void check_samples(const std::vector<double>& t, const std::vector<double>& a) {
    if (t.size() != a.size() || t.size() < 2)
        throw InputError(fmt::format("an intensity measure needs at least 2 samples of time and acceleration, got {} "
                                     "and {}",
                                     t.size(), a.size()));
    for (std::size_t i = 1; i < t.size(); ++i)
        if (!(t[i] > t[i - 1]))
            throw InputError(fmt::format("an intensity measure's sample times must increase: sample {} at {} s "
                                         "follows {} s",
                                         i, t[i], t[i - 1]));
}

void check_oscillator(double period, double damping) {
    require(std::isfinite(period) && period > 0.0, "the spectral acceleration's period [s]", "> 0", period);
    require(std::isfinite(damping) && damping >= 0.0 && damping < 1.0, "the spectral acceleration's damping ratio",
            "in [0, 1)", damping);
}

// The exact step of u'' + 2 zeta omega u' + omega^2 u = p(t), p linear over the step from p_i to p_i+1
// (Chopra, Table 5.2.1): u_i+1 = A u_i + B v_i + C p_i + D p_i+1, v_i+1 = A' u_i + B' v_i + C' p_i + D' p_i+1.
struct Recurrence {
    double A, B, C, D, Av, Bv, Cv, Dv;
};

Recurrence recurrence(double omega, double zeta, double dt) {
    const double k = omega * omega;
    const double root = std::sqrt(1.0 - zeta * zeta);
    const double wd = omega * root;
    const double e = std::exp(-zeta * omega * dt);
    const double s = std::sin(wd * dt), c = std::cos(wd * dt);
    const double wdt = omega * dt;
    Recurrence r{};
    r.A = e * (zeta / root * s + c);
    r.B = e * s / wd;
    r.C = (2.0 * zeta / wdt + e * (((1.0 - 2.0 * zeta * zeta) / (wd * dt) - zeta / root) * s -
                                   (1.0 + 2.0 * zeta / wdt) * c)) /
          k;
    r.D = (1.0 - 2.0 * zeta / wdt + e * ((2.0 * zeta * zeta - 1.0) / (wd * dt) * s + 2.0 * zeta / wdt * c)) / k;
    r.Av = -e * omega / root * s;
    r.Bv = e * (c - zeta / root * s);
    r.Cv = (-1.0 / dt + e * ((omega / root + zeta / (dt * root)) * s + c / dt)) / k;
    r.Dv = (1.0 - e * (zeta / root * s + c)) / (k * dt);
    return r;
}

struct OscillatorState {
    std::vector<double> u;
    double v_end = 0.0;  // the velocity at the last sample [m/s]
};

OscillatorState oscillate(const std::vector<double>& t, const std::vector<double>& a, double period, double damping) {
    check_samples(t, a);
    check_oscillator(period, damping);
    const double omega = 2.0 * M_PI / period;
    OscillatorState out;
    out.u.assign(t.size(), 0.0);
    double u = 0.0, v = 0.0;
    double dt_of_r = -1.0;
    Recurrence r{};
    for (std::size_t i = 1; i < t.size(); ++i) {
        const double dt = t[i] - t[i - 1];
        if (dt != dt_of_r) {  // a record's steps are nearly always even: one set of coefficients for all
            r = recurrence(omega, damping, dt);
            dt_of_r = dt;
        }
        const double p0 = -a[i - 1], p1 = -a[i];
        const double u1 = r.A * u + r.B * v + r.C * p0 + r.D * p1;
        v = r.Av * u + r.Bv * v + r.Cv * p0 + r.Dv * p1;
        u = u1;
        out.u[i] = u;
    }
    out.v_end = v;
    return out;
}

// The largest |u| of the free vibration from (u0, v0), the ground at rest: at the start or at the first extremum
// (where v = 0), the later ones smaller by the damping. v(t) = e^(-zeta omega t) (v0 cos x - q sin x), x = omega_d t,
// q = (omega^2 u0 + zeta omega v0) / omega_d, which is R cos(x + phi) with phi = atan2(q, v0).
double free_vibration_peak(double u0, double v0, double omega, double zeta) {
    const double wd = omega * std::sqrt(1.0 - zeta * zeta);
    const double q = (omega * omega * u0 + zeta * omega * v0) / wd;
    if (v0 == 0.0 && q == 0.0) return std::abs(u0);
    double x = M_PI / 2.0 - std::atan2(q, v0);  // in [-pi/2, 3 pi/2): the first positive root of cos(x + phi)
    if (x <= 0.0) x += M_PI;
    if (x > M_PI) x -= M_PI;
    const double t = x / wd;
    const double u = std::exp(-zeta * omega * t) * (u0 * std::cos(x) + (v0 + zeta * omega * u0) / wd * std::sin(x));
    return std::max(std::abs(u0), std::abs(u));
}

}  // namespace

IntensityMeasure parse_intensity_measure(const std::string& text) {
    if (text == "pga") return IntensityMeasure::pga;
    if (text == "pgv") return IntensityMeasure::pgv;
    if (text == "sa") return IntensityMeasure::sa;
    if (text == "arias") return IntensityMeasure::arias;
    throw InputError(fmt::format("'{}' is not an intensity measure (pga, pgv, sa, arias)", text));
}

const char* to_string(IntensityMeasure m) {
    switch (m) {
        case IntensityMeasure::pga: return "pga";
        case IntensityMeasure::pgv: return "pgv";
        case IntensityMeasure::sa: return "sa";
        case IntensityMeasure::arias: return "arias";
    }
    return "pga";
}

const char* intensity_unit(IntensityMeasure m) {
    return m == IntensityMeasure::pgv || m == IntensityMeasure::arias ? "m/s" : "g";
}

std::string intensity_name(const Intensity& im) {
    if (im.measure != IntensityMeasure::sa) return to_string(im.measure);
    return fmt::format("sa({:g} s, {:g} %)", im.sa_period, 100.0 * im.sa_damping);
}

std::string intensity_label(const Intensity& im) {
    switch (im.measure) {
        case IntensityMeasure::pga: return "PGA [g]";
        case IntensityMeasure::pgv: return "PGV [m/s]";
        case IntensityMeasure::sa:
            return fmt::format("Sa({:g} s, {:g} %) [g]", im.sa_period, 100.0 * im.sa_damping);
        case IntensityMeasure::arias: return "Arias intensity [m/s]";
    }
    return "";
}

double peak_ground_velocity(const std::vector<double>& t, const std::vector<double>& a) {
    check_samples(t, a);
    double v = 0.0, pgv = 0.0;
    for (std::size_t i = 1; i < a.size(); ++i) {
        v += 0.5 * (t[i] - t[i - 1]) * (a[i - 1] + a[i]);
        pgv = std::max(pgv, std::fabs(v));
    }
    return pgv;
}

double arias_intensity(const std::vector<double>& t, const std::vector<double>& a) {
    check_samples(t, a);
    double e = 0.0;
    for (std::size_t i = 1; i < t.size(); ++i) e += 0.5 * (t[i] - t[i - 1]) * (a[i - 1] * a[i - 1] + a[i] * a[i]);
    return M_PI / (2.0 * kStandardGravity) * e;
}

std::vector<double> oscillator_displacement(const std::vector<double>& times, const std::vector<double>& accel_m_s2,
                                            double period, double damping) {
    return oscillate(times, accel_m_s2, period, damping).u;
}

double spectral_acceleration(const std::vector<double>& times, const std::vector<double>& accel_m_s2, double period,
                             double damping) {
    const OscillatorState s = oscillate(times, accel_m_s2, period, damping);
    const double omega = 2.0 * M_PI / period;
    double peak = free_vibration_peak(s.u.back(), s.v_end, omega, damping);
    for (const double u : s.u) peak = std::max(peak, std::abs(u));
    return omega * omega * peak;
}

double record_intensity(const GroundMotion& record, const Intensity& im) {
    const std::vector<double>& t = record.sample_times();
    const std::vector<double>& a = record.sample_values();
    if (im.measure == IntensityMeasure::pga) return record.pga() / kStandardGravity;
    if (t.empty())
        throw InputError(fmt::format("'{}' is not a sampled record: its {} is not measured", record.name(),
                                     to_string(im.measure)));
    switch (im.measure) {
        case IntensityMeasure::pgv: return peak_ground_velocity(t, a);
        case IntensityMeasure::arias: return arias_intensity(t, a);
        case IntensityMeasure::sa: return spectral_acceleration(t, a, im.sa_period, im.sa_damping) / kStandardGravity;
        case IntensityMeasure::pga: break;
    }
    return record.pga() / kStandardGravity;
}

double intensity_at_scale(IntensityMeasure m, double at_scale_one, double scale) {
    return m == IntensityMeasure::arias ? scale * scale * at_scale_one : scale * at_scale_one;
}

double scale_to_intensity(IntensityMeasure m, double at_scale_one, double level) {
    return m == IntensityMeasure::arias ? std::sqrt(level / at_scale_one) : level / at_scale_one;
}

}  // namespace vssw
