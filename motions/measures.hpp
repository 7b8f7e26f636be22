#pragma once
// Measures of a ground-motion record (docs/ground-motions.md, "Measures"). Pure functions of the samples as
// recorded: acceleration a_i [m/s^2] at strictly increasing times t_i [s] (evenly spaced or not), linear between
// samples. Nothing is filtered or baseline-corrected first.
#include <vector>

#include "analytic/ground_motion.hpp"

namespace vssw::motions {

struct Measures {
    double pga_g;             // max |a_i| / g0, g0 = 9.80665 m/s^2 (kStandardGravity)
    // max |v(t_i)| [m/s], v the trapezoidal integral of a from rest at the first sample, of the acceleration as
    // recorded: no baseline correction, so a record with an offset or drift reports the velocity that drift makes.
    double pgv_m_s;
    double arias_m_s;         // I_a = pi / (2 g0) * integral of a^2 dt (trapezoidal) [m/s]
    // D5-95: the time between 5 % and 95 % of I_a on the Husid curve H(t) = integral_0^t a^2 / integral a^2, the
    // crossing times interpolated linearly between samples [s]. NaN when I_a is 0.
    double d5_95_s;
    double t_mid_s;           // the time at 45 % of I_a (Rezaeian & Der Kiureghian's t_mid), as D5-95 [s]
    // The rate of zero-level up-crossings around t_mid [Hz], Rezaeian & Der Kiureghian's omega_mid / 2 pi: for a
    // process that is a filter's response to white noise, that rate is the filter's frequency. Window: the times
    // [t_mid - D5-95/4, t_mid + D5-95/4] (clipped to the record), half the significant duration, centred on t_mid so that
    // a frequency drifting linearly in time (the model's omega') averages to its value at t_mid, and long enough to
    // hold tens of crossings of a typical record. Rate = (N - 1) / (t_N - t_1) over the N up-crossings inside it
    // (each crossing time interpolated linearly): crossings counted from the first to the last, not in a fixed
    // window, so that a window a fraction of a period longer or shorter does not add or lose a whole crossing.
    // NaN with fewer than 2 crossings there.
    double mid_frequency_hz;
    double duration_s;        // t_last - t_first
    double dt_s;              // the sample step when the samples are evenly spaced (to 1e-6 relative), NaN otherwise
};

// Measures of the samples; times.size() == accel.size() >= 2, times strictly increasing (InputError otherwise).
Measures measure(const std::vector<double>& times, const std::vector<double>& accel_m_s2);
// Measures of a record read by analytic/ground_motion.hpp (a sampled record; InputError for any other motion).
Measures measure(const GroundMotion& record);
// Measures of samples a_i at t_i = i * dt.
Measures measure_uniform(const std::vector<double>& accel_m_s2, double dt);

// The Husid curve's crossing of `fraction` (0..1) of the total: the time [s], interpolated linearly. NaN when the
// total is 0.
double husid_time(const std::vector<double>& times, const std::vector<double>& accel_m_s2, double fraction);

}  // namespace vssw::motions
