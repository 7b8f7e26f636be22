#pragma once
// The ground-motion options of `vssw history`: a record file or a synthetic pulse, optionally scaled.
#include <optional>
#include <string>

#include "analytic/ground_motion.hpp"

namespace CLI {
class App;
}

namespace vssw::cli {

struct GroundMotionOptions {
    std::optional<std::string> record;   // file path (PEER AT2, two columns, one column with --record-dt, a CSV)
    // The record as samples already in memory (the Python module's record=(t, values)), read in place of the file;
    // `record` then only names it in messages and outputs.
    std::optional<GroundMotion> samples;
    std::optional<std::string> units;    // overrides the record's units
    RecordFormat format;                 // --record-dt, --time-column, --accel-column
    std::optional<std::string> vertical_record;  // `vssw history` only: the vertical component, read as --record
    std::optional<double> scale;         // factor on the record
    std::optional<double> pga_g;         // target PGA [g]
    std::optional<std::string> pulse;    // sine | cosine | ricker | harmonic
    std::optional<double> amplitude_g;   // pulse amplitude [g]
    std::optional<double> pulse_period;  // [s]
    std::optional<double> duration;      // [s], harmonic only
};

// --record, --units, --record-dt, --time-column, --accel-column, --scale, --pga, --pulse, --amplitude,
// --pulse-period, --duration; and --vertical-record when `vertical` (the analytic model's commands: the engines are
// driven horizontally only).
void add_ground_motion_options(CLI::App& cmd, GroundMotionOptions& options, bool vertical = false);

struct LoadedMotion {
    GroundMotion motion;  // after scaling, in m/s^2
    GroundMotion unscaled;  // as read or built, before --scale or --pga (vssw compare scales it as a study does)
    GroundMotion vertical = GroundMotion::none();  // --vertical-record, scaled by the same factor; none without it
    double scale_factor;  // what multiplied the input (1 when not scaled)
    double sample_dt;     // the record's mean sample spacing, or T_p / 100 for a pulse [s]
};

// InputError unless exactly one of record/pulse is given, on a bad file, bad units, bad pulse parameters, or both
// --scale and --pga.
LoadedMotion load_ground_motion(const GroundMotionOptions& options);

}  // namespace vssw::cli
