#include "cli/ground_motion_options.hpp"

#include <cmath>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "analytic/error.hpp"
#include "cli/wall_options.hpp"

namespace vssw::cli {
namespace {

// Output samples per pulse period when --output-dt is not given: enough to draw the pulse.
constexpr double kPulseSamplesPerPeriod = 100.0;

template <class T>
void bind_optional(CLI::App& cmd, const std::string& name, std::optional<T>& target, const std::string& help) {
    cmd.add_option_function<T>(
        name, [&target](const T& value) { target = value; }, help);
}

// Names a given option with its value, for messages: "--scale 2".
template <class T>
std::string given(const char* name, const std::optional<T>& value) {
    return fmt::format("{} {}", name, *value);
}

double mean_spacing(const GroundMotion& record) {
    const auto& t = record.sample_times();
    return (t.back() - t.front()) / static_cast<double>(t.size() - 1);
}

GroundMotion make_pulse(const GroundMotionOptions& o) {
    const std::string& kind = *o.pulse;
    if (kind != "sine" && kind != "cosine" && kind != "ricker" && kind != "harmonic")
        throw InputError("pulse must be one of sine, cosine, ricker, harmonic; got '" + kind + "'");
    if (!o.amplitude_g) throw InputError("--pulse " + kind + " needs --amplitude (in g)");
    if (!o.pulse_period) throw InputError("--pulse " + kind + " needs --pulse-period (in s)");
    if (kind != "harmonic" && o.duration)
        throw InputError(given("--duration", o.duration) + " applies to --pulse harmonic only, not to " + kind);
    const double amplitude = *o.amplitude_g * kStandardGravity;
    const double period = *o.pulse_period;
    if (kind == "sine") return sine_pulse(amplitude, period);
    if (kind == "cosine") return cosine_pulse(amplitude, period);
    if (kind == "ricker") return ricker_wavelet(amplitude, period);
    if (!o.duration) throw InputError("--pulse harmonic needs --duration (in s)");
    return harmonic(amplitude, period, *o.duration);
}

}  // namespace

void add_ground_motion_options(CLI::App& cmd, GroundMotionOptions& o, bool vertical) {
    bind_optional(cmd, "--record", o.record,
                  "ground-motion file: PEER AT2 (units from its header), two columns 'time acceleration', "
                  "accelerations alone with --record-dt, or a table with a header row (CSV); units g unless --units");
    bind_optional(cmd, "--units", o.units,
                  "units of the record's accelerations: g, m/s2 or cm/s2 (overrides an AT2 header)");
    bind_optional(cmd, "--record-dt", o.format.dt,
                  "the record holds accelerations only, evenly spaced by this step [s] from t = 0 (OpenSees "
                  "'Path -dt'): every number of the file in order, or the --accel-column of a table");
    bind_optional(cmd, "--time-column", o.format.time_column,
                  "the record is a table with a header row: the name of its time column (not needed for a table of "
                  "two columns, time first)");
    bind_optional(cmd, "--accel-column", o.format.accel_column,
                  "the record is a table with a header row: the name of its acceleration column");
    if (vertical)
        bind_optional(cmd, "--vertical-record", o.vertical_record,
                      "the vertical component (up positive), a file read as --record is (same units and format "
                      "options) and scaled by the same factor");
    bind_optional(cmd, "--scale", o.scale, "multiply the ground motion by this factor (not with --pga)");
    bind_optional(cmd, "--pga", o.pga_g,
                  "scale the ground motion to this peak ground acceleration [g] (not with --scale)");
    bind_optional(cmd, "--pulse", o.pulse, "synthetic input instead of --record: sine, cosine, ricker or harmonic");
    bind_optional(cmd, "--amplitude", o.amplitude_g, "pulse amplitude [g] (required with --pulse)");
    bind_optional(cmd, "--pulse-period", o.pulse_period, "pulse period T_p [s] (required with --pulse)");
    bind_optional(cmd, "--duration", o.duration,
                  "duration of the harmonic input [s] (--pulse harmonic only, required)");
}

LoadedMotion load_ground_motion(const GroundMotionOptions& o) {
    if (o.record && o.pulse)
        throw InputError(fmt::format("give either --record or --pulse, not both (got --record '{}' and --pulse {})",
                                     *o.record, *o.pulse));
    if (!o.record && !o.pulse) throw InputError("a ground motion is required: give --record FILE or --pulse KIND");
    if (o.scale && o.pga_g)
        throw InputError(fmt::format("{} and {} cannot be used together: give one of them", given("--scale", o.scale),
                                     given("--pga", o.pga_g)));
    if (o.record) {
        for (const auto* pulse_option : {&o.amplitude_g, &o.pulse_period, &o.duration})
            if (*pulse_option)
                throw InputError("--amplitude, --pulse-period and --duration describe a --pulse, not a --record");
    } else {
        if (o.units) throw InputError("--units '" + *o.units + "' applies to --record only (pulse amplitudes are in g)");
        if (!o.format.is_default())
            throw InputError("--record-dt, --time-column and --accel-column describe a --record file, not a --pulse");
        if (o.vertical_record)
            throw InputError("--vertical-record '" + *o.vertical_record + "' goes with --record, not with a --pulse");
    }

    double sample_dt = 0.0;
    GroundMotion motion = GroundMotion::none();
    GroundMotion vertical = GroundMotion::none();
    if (o.record) {
        std::optional<AccelUnits> units;
        if (o.units) units = parse_units(*o.units);
        motion = o.samples ? *o.samples : read_record(*o.record, units ? &*units : nullptr, o.format);
        sample_dt = mean_spacing(motion);
        if (o.vertical_record) vertical = read_record(*o.vertical_record, units ? &*units : nullptr, o.format);
    } else {
        motion = make_pulse(o);
        sample_dt = *o.pulse_period / kPulseSamplesPerPeriod;
    }

    GroundMotion unscaled = motion;
    double factor = 1.0;
    if (o.scale) {
        factor = *o.scale;
        motion = motion.scaled(factor);
    } else if (o.pga_g) {
        // Checked here too, so that the message shows the value as typed (in g), not converted to m/s^2.
        require(std::isfinite(*o.pga_g) && *o.pga_g > 0.0, "target PGA (--pga)", "a positive finite number in g",
                *o.pga_g);
        const double before = motion.pga();
        motion = motion.scaled_to_pga(*o.pga_g * kStandardGravity);
        factor = *o.pga_g * kStandardGravity / before;
    }
    // The two components of one record take the same factor (--pga: the horizontal's PGA sets it).
    if (o.vertical_record) vertical = vertical.scaled(factor);
    return {std::move(motion), std::move(unscaled), std::move(vertical), factor, sample_dt};
}

}  // namespace vssw::cli
