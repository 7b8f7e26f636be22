#pragma once
// Ground motions: recorded accelerograms and synthetic inputs, as one type the integrator can evaluate.
//
// A GroundMotion is an acceleration a(t) in m/s^2 (positive along +x, or upward for a vertical component), zero
// before t = 0 and after duration(). Records are linear between samples; their sample times are breakpoints, where
// a(t) has a kink, so the integrator steps onto them and keeps its order between them.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace vssw {

enum class AccelUnits { g, m_per_s2, cm_per_s2 };

// Standard gravity (CGPM 1901): what "in g" means for records (their agencies converted with it), --pga and
// --amplitude. A wall's own g (VsswGeometry::g) is a separate model parameter, deliberately not used here.
constexpr double kStandardGravity = 9.80665;  // [m/s^2]

// Parses "g", "m/s2" (also "m/s^2"), "cm/s2" (also "cm/s^2", "gal"); throws InputError naming the text otherwise.
AccelUnits parse_units(const std::string& text);
// Factor that converts a value in `units` to m/s^2, with standard gravity g0 = 9.80665 for "g".
double to_m_per_s2(AccelUnits units);

// What the maker of an analytic signal knows of its shape, which a scan of the function would only approximate: a fast
// harmonic sampled on any fixed grid can land on its zeros (a 1 ms period scanned every 0.5 ms reads 1e-11 of its
// amplitude), so the peak and the extrema are given, not searched for.
struct AnalyticShape {
    double peak;  // max |a(t)| over [0, duration] [m/s^2]
    // The first extremum of a(t) after t, or +infinity when none is left before the end. Empty: a(t) is monotone
    // between its breakpoints. Between two consecutive extrema or breakpoints a(t) is monotone, so |a| there is
    // largest at an end: the rest phase looks at those instants and misses no excursion past the threshold (under a
    // horizontal motion alone or with a vertical record; simulate.cpp, rest_phase).
    std::function<double(double)> next_extremum;
};

class GroundMotion {
public:
    // A sampled record: strictly increasing times (from 0 or later), accelerations in m/s^2.
    static GroundMotion sampled(std::vector<double> times, std::vector<double> accel_m_s2, std::string name);
    // An analytic signal a(t) on [0, duration], zero outside, with the times where it is not smooth and its shape.
    static GroundMotion analytic(std::function<double(double)> a, double duration, std::vector<double> breakpoints,
                                 AnalyticShape shape, std::string name);
    // No motion at all.
    static GroundMotion none();

    double operator()(double t) const;
    // A piece of the line on which a(t) is linear around t, for a caller that evaluates the motion many times in one
    // interval (the integrator's stages within a record's sample interval): a(x) = value + slope (x - start) for x
    // in [start, end], equal to operator() there to rounding. A record's sample interval holding t, every finite time
    // for no motion; nothing for an analytic signal or where a record is not sampled (before its first sample,
    // after its end, a NaN time).
    struct LinearPiece {
        double start, end, value, slope;
    };
    std::optional<LinearPiece> linear_piece(double t) const;
    // Whether a(t) is known to be continuous at t: a record inside its span (linear between samples), no motion at
    // all. False where it may jump (a record's first and last sample, any analytic signal's breakpoint).
    bool continuous_at(double t) const;
    double duration() const { return duration_; }
    const std::vector<double>& breakpoints() const { return breakpoints_; }
    const std::string& name() const { return name_; }
    double pga() const;  // max |a| in m/s^2 (over the samples, or an analytic signal's AnalyticShape::peak)
    // The time after which |a(t)| stays at or below `level` (m/s^2, >= 0): for a record, the sample that follows the
    // last one above it (a(t) is linear between samples), 0 when none is; for an analytic signal its duration (its
    // shape is not scanned); 0 for no motion.
    double quiet_after(double level) const;
    // The first extremum of an analytic signal after t (AnalyticShape::next_extremum); +infinity for a record (its
    // samples are its breakpoints), for no motion and for a signal monotone between its breakpoints.
    double next_extremum(double t) const;
    bool is_zero() const { return is_zero_; }

    GroundMotion scaled(double factor) const;           // a(t) * factor; factor must be finite
    GroundMotion scaled_to_pga(double pga_m_s2) const;  // scaled so that pga() == target; target must be > 0
    // Only for sampled records (empty otherwise).
    const std::vector<double>& sample_times() const { return times_; }
    const std::vector<double>& sample_values() const { return values_; }

private:
    // The sample interval [times_[i], times_[i + 1]] holding t, for t within the record's samples.
    std::size_t interval_of(double t) const;

    std::function<double(double)> fn_;
    std::function<double(double)> next_extremum_;  // an analytic signal's, when it has extrema inside its pieces
    double analytic_peak_ = 0.0;                   // an analytic signal's max |a| [m/s^2]
    std::vector<double> times_, values_;
    std::vector<double> breakpoints_;
    double duration_ = 0.0;
    double uniform_dt_ = 0.0;  // > 0 when a record's samples are evenly spaced: O(1) lookup
    bool is_zero_ = false;
    std::string name_;
};

// Records -------------------------------------------------------------------------------------------------------
// Every reader refuses, before opening it, a path that is not a regular file (a device such as /dev/zero, a FIFO or
// socket, which would be read without end or block forever) and a file larger than kMaxRecordBytes. The bound: the
// largest real accelerograms are a few MB (a PEER AT2 file of 60,000 samples is ~0.6 MB; 10 minutes at 200 Hz in two
// columns is ~3 MB); 64 MiB is ten times more than any, and small enough to hold in memory at once.
constexpr long long kMaxRecordBytes = 64LL * 1024 * 1024;
// The smallest time between two samples of a record [s]: a nanosecond is a million times faster than any
// accelerometer's sampling, and far above the steps whose slopes overflow (DT 1e-310 ran into "theta1'' must be a
// finite number, got -nan", naming neither the file nor the step).
constexpr double kMinSampleStep = 1e-9;
// PEER AT2, both header styles: line 4 is either "1991    0.0100    NPTS, DT" (older) or
// "NPTS=  1991, DT=   .0100 SEC" (NGA-West2). Units are read from line 3 ("... IN UNITS OF G"); `units_override`
// replaces them. Throws InputError (naming the file and the line) on a missing file, an empty or truncated file, a
// header without NPTS/DT, non-numeric text, or a sample count that differs from NPTS.
GroundMotion read_peer_at2(const std::string& path, const AccelUnits* units_override = nullptr);
// Two columns "time acceleration" separated by blanks, tabs or a comma; '#' starts a comment; blank lines skipped.
// Times must be strictly increasing. Throws InputError like read_peer_at2.
GroundMotion read_two_column(const std::string& path, AccelUnits units);
// What a file that is not a PEER AT2 record holds, when it is not two columns "time acceleration" (the default).
struct RecordFormat {
    // Accelerations only, evenly spaced by dt [s] from t = 0 (OpenSees `timeSeries Path -dt`): every number of the
    // file in order, any number per line; with a header row, the column `accel_column`.
    std::optional<double> dt;
    // A header row names the columns (a CSV file, fields separated by commas, or else by blanks): the times' column
    // and the accelerations' column. A header of two columns needs neither name (time first); of one column, dt.
    std::optional<std::string> time_column, accel_column;
    bool is_default() const { return !dt && !time_column && !accel_column; }
};

// Chooses the reader by content: AT2 when line 4 holds NPTS (and `format` is the default: an AT2 header gives its
// own DT); otherwise a header row when the first data line is not all numbers, then `format`. `units` applies to the
// other files (default g) and overrides an AT2 header when given. Throws InputError naming the file, the line and the
// value, or the format setting that does not fit the file.
GroundMotion read_record(const std::string& path, const AccelUnits* units = nullptr, const RecordFormat& format = {});
// read_record on text already in memory (the fuzz harness, tests/fuzz/); `name` stands for the path in messages and
// names the record.
GroundMotion parse_record(const std::string& text, const std::string& name, const AccelUnits* units = nullptr,
                          const RecordFormat& format = {});

// Synthetic inputs ------------------------------------------------------------------------------------------------
// All amplitudes in m/s^2, times in s; each validates its arguments (finite, periods and durations > 0).
GroundMotion constant_motion(double amplitude, double duration);
// One-sine pulse a_p sin(2 pi t / T_p) on [0, T_p]   (Zhang & Makris 2001, type A).
GroundMotion sine_pulse(double amplitude, double period);
// One-cosine pulse a_p cos(2 pi t / T_p) on [0, T_p] (type B); it jumps at t = 0 and T_p (breakpoints).
GroundMotion cosine_pulse(double amplitude, double period);
// Ricker wavelet a_p (1 - 2 pi^2 f^2 tau^2) exp(-pi^2 f^2 tau^2), tau = t - 1.5 T_p, f = 1/T_p, on [0, 3 T_p].
GroundMotion ricker_wavelet(double amplitude, double period);
// Harmonic a_p sin(2 pi t / T) on [0, duration].
GroundMotion harmonic(double amplitude, double period, double duration);

}  // namespace vssw
