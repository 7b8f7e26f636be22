#include "motions/measures.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "analytic/intensity_measures.hpp"

namespace vssw::motions {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Steps that differ by less than this (relative) are one step: an AT2 record's times are i * DT, rounded.
constexpr double kEvenSteps = 1e-6;

void check_samples(const std::vector<double>& times, const std::vector<double>& accel) {
    if (times.size() != accel.size())
        throw InputError(fmt::format("measures: {} times but {} accelerations", times.size(), accel.size()));
    if (times.size() < 2) throw InputError("measures: a record needs at least 2 samples");
    for (std::size_t i = 1; i < times.size(); ++i)
        if (!(times[i] > times[i - 1]))
            throw InputError(fmt::format("measures: times must increase, sample {} at {} s follows {} s", i, times[i],
                                         times[i - 1]));
}

// The cumulative trapezoidal integral of a^2: E[i] = integral from t_0 to t_i.
std::vector<double> cumulative_energy(const std::vector<double>& t, const std::vector<double>& a) {
    std::vector<double> e(t.size(), 0.0);
    for (std::size_t i = 1; i < t.size(); ++i)
        e[i] = e[i - 1] + 0.5 * (t[i] - t[i - 1]) * (a[i - 1] * a[i - 1] + a[i] * a[i]);
    return e;
}

double crossing_time(const std::vector<double>& t, const std::vector<double>& e, double fraction) {
    const double total = e.back();
    if (!(total > 0.0)) return kNaN;
    const double level = fraction * total;
    const auto it = std::lower_bound(e.begin(), e.end(), level);
    if (it == e.begin()) return t.front();
    if (it == e.end()) return t.back();
    const std::size_t i = static_cast<std::size_t>(it - e.begin());
    const double share = (level - e[i - 1]) / (e[i] - e[i - 1]);
    return t[i - 1] + share * (t[i] - t[i - 1]);
}

double up_crossing_rate(const std::vector<double>& t, const std::vector<double>& a, double from, double to) {
    double first = kNaN, last = kNaN;
    int count = 0;
    for (std::size_t i = 1; i < t.size(); ++i) {
        if (!(a[i - 1] < 0.0 && a[i] >= 0.0)) continue;
        const double at = t[i - 1] + (-a[i - 1]) / (a[i] - a[i - 1]) * (t[i] - t[i - 1]);
        if (at < from || at > to) continue;
        if (count == 0) first = at;
        last = at;
        ++count;
    }
    return count >= 2 && last > first ? (count - 1) / (last - first) : kNaN;
}

}  // namespace

double husid_time(const std::vector<double>& times, const std::vector<double>& accel_m_s2, double fraction) {
    check_samples(times, accel_m_s2);
    return crossing_time(times, cumulative_energy(times, accel_m_s2), fraction);
}

Measures measure(const std::vector<double>& t, const std::vector<double>& a) {
    check_samples(t, a);
    Measures m{};
    double peak = 0.0;
    for (const double x : a) peak = std::max(peak, std::fabs(x));
    m.pga_g = peak / kStandardGravity;
    // The same PGV and Arias intensity a study scales records to (analytic/intensity_measures.hpp).
    m.pgv_m_s = peak_ground_velocity(t, a);
    const std::vector<double> e = cumulative_energy(t, a);
    m.arias_m_s = arias_intensity(t, a);
    m.d5_95_s = crossing_time(t, e, 0.95) - crossing_time(t, e, 0.05);
    m.t_mid_s = crossing_time(t, e, 0.45);
    const double half = m.d5_95_s / 4.0;
    m.mid_frequency_hz = std::isfinite(half) ? up_crossing_rate(t, a, m.t_mid_s - half, m.t_mid_s + half) : kNaN;
    m.duration_s = t.back() - t.front();
    const double step = m.duration_s / static_cast<double>(t.size() - 1);
    bool even = true;
    for (std::size_t i = 1; i < t.size() && even; ++i) even = std::fabs((t[i] - t[i - 1]) - step) <= kEvenSteps * step;
    m.dt_s = even ? step : kNaN;
    return m;
}

Measures measure(const GroundMotion& record) {
    if (record.sample_times().empty())
        throw InputError(fmt::format("measures: '{}' is not a sampled record", record.name()));
    return measure(record.sample_times(), record.sample_values());
}

Measures measure_uniform(const std::vector<double>& accel_m_s2, double dt) {
    std::vector<double> t(accel_m_s2.size());
    for (std::size_t i = 0; i < t.size(); ++i) t[i] = static_cast<double>(i) * dt;
    return measure(t, accel_m_s2);
}

}  // namespace vssw::motions
