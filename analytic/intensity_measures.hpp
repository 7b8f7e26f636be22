#pragma once
// Intensity measures of a sampled ground-motion record, and the scale factor that brings a record to a given
// intensity: what a study's ensemble scales its records by (`intensity = "pga" | "pgv" | "sa" | "arias"`,
// study/spec.hpp) and reports its collapse intensities in. Pure functions of the samples as recorded: acceleration
// a_i [m/s^2] at strictly increasing times t_i [s], linear between samples, from rest at the first sample; nothing is
// filtered or baseline-corrected first (motions/measures.hpp measures the same PGV and Arias intensity).
//
// Each measure but the Arias intensity is proportional to the scale factor on the record; the Arias intensity grows
// with its square.
#include <string>
#include <vector>

#include "analytic/ground_motion.hpp"

namespace vssw {

enum class IntensityMeasure { pga, pgv, sa, arias };

// "pga", "pgv", "sa", "arias" (the study file's words); InputError otherwise.
IntensityMeasure parse_intensity_measure(const std::string& text);
const char* to_string(IntensityMeasure m);
// The unit the measure is given in: "g" (PGA, Sa), "m/s" (PGV, Arias intensity).
const char* intensity_unit(IntensityMeasure m);

// The 5 %-damped spectral acceleration of the usual response spectrum: the default of Intensity::sa_damping.
constexpr double kDefaultSaDamping = 0.05;

// A measure with its parameters: Sa's oscillator period [s] (> 0) and damping ratio (in [0, 1)).
struct Intensity {
    IntensityMeasure measure = IntensityMeasure::pga;
    double sa_period = 0.0;
    double sa_damping = kDefaultSaDamping;
};
// "pga", "pgv", "arias", "sa(1 s, 5 %)": how a title or an axis names it.
std::string intensity_name(const Intensity& im);
// The axis label with its unit: "PGA [g]", "PGV [m/s]", "Sa(1 s, 5 %) [g]", "Arias intensity [m/s]".
std::string intensity_label(const Intensity& im);

// max |v(t_i)| [m/s], v the trapezoidal integral of a from rest at the first sample.
double peak_ground_velocity(const std::vector<double>& times, const std::vector<double>& accel_m_s2);
// pi / (2 g0) * the trapezoidal integral of a^2 dt [m/s], g0 = kStandardGravity.
double arias_intensity(const std::vector<double>& times, const std::vector<double>& accel_m_s2);

// The relative displacement u(t_i) [m] of a linear oscillator of this natural period [s] and damping ratio, from rest
// at the first sample, under the ground acceleration a (u'' + 2 zeta omega u' + omega^2 u = -a): the exact solution
// for an excitation linear between samples (Nigam & Jennings 1969; Chopra, Dynamics of Structures, section 5.2), so
// its only error is the record's own sampling. period > 0, damping in [0, 1); InputError otherwise.
std::vector<double> oscillator_displacement(const std::vector<double>& times, const std::vector<double>& accel_m_s2,
                                            double period, double damping);
// The pseudo-spectral acceleration omega^2 max |u| [m/s^2] of that oscillator: the maximum over the record and the free
// vibration after it (the ground at rest), whose largest excursion is its first extremum, found in closed form.
double spectral_acceleration(const std::vector<double>& times, const std::vector<double>& accel_m_s2, double period,
                             double damping);

// The record's measure in the measure's unit (g or m/s), at scale 1. InputError for a motion that is not a sampled
// record (an analytic pulse has no samples to integrate) or a parameter out of its range.
double record_intensity(const GroundMotion& record, const Intensity& im);
// The measure of the record scaled by `scale`, from its value at scale 1: linear, the Arias intensity quadratic.
double intensity_at_scale(IntensityMeasure m, double at_scale_one, double scale);
// The factor that brings a measure of `at_scale_one` (> 0) to `level`: the inverse of intensity_at_scale.
double scale_to_intensity(IntensityMeasure m, double at_scale_one, double level);

}  // namespace vssw
