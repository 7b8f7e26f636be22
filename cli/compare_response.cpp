#include "cli/compare_response.hpp"

#include <cmath>
#include <ostream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "io/json.hpp"
#include "cli/friction_option.hpp"
#include "cli/simulation_failure.hpp"
#include "cli/table.hpp"

namespace vssw::cli {
namespace {

using RunResult = study::ResponseRun;


// With the wall's friction given (docs/guide/program.md "Finite friction"): an engine's slips at the base and the
// hinge (largest and residual, in m and in b) and whether it slid before it rocked; the analytic model's friction
// needed and whether it exceeds the given one (the model would slide).
void add_friction_fields(const RunResult& r, const study::CaseSpec& c, io::Json& e) {
    const double b = 0.5 * c.thickness;
    if (r.engine != "analytic") {
        auto contact = [&](double largest, double residual) {
            return io::Json{{"largest_b", io::finite_or_null(largest)}, {"largest_m", io::finite_or_null(largest * b)},
                            {"residual_b", io::finite_or_null(residual)}, {"residual_m", io::finite_or_null(residual * b)}};
        };
        e["slip"] = {{"base", contact(r.base_slip, r.residual_base_slip)},
                     {"hinge", c.scene.vssw ? contact(r.hinge_slip, r.residual_hinge_slip) : io::Json(nullptr)},
                     {"slid_before_rocking", std::isfinite(r.slid_before_rocking)
                                                 ? io::Json(r.slid_before_rocking == 1.0) : io::Json(nullptr)},
                     // An engine's only warning: the wall slid off its support, which ended the run.
                     {"slid_off", r.warnings.empty() ? io::Json(nullptr) : io::Json(r.warnings)}};
        return;
    }
    const multibody::WallScene& s = c.scene;
    auto exceeds = [](double needed, double mu) { return std::isfinite(needed) ? io::Json(needed > mu) : io::Json(nullptr); };
    e["friction_needed"] = {{"base", io::finite_or_null(r.base_friction_needed)},
                            {"hinge", io::finite_or_null(r.hinge_friction_needed)}};
    e["would_slide"] = {{"base", exceeds(r.base_friction_needed, s.base_mu())},
                        {"hinge", exceeds(r.hinge_friction_needed, s.hinge_mu())}};
}

// The table's line of a run's sliding (friction given).
std::string friction_line(const RunResult& r, bool vssw) {
    if (r.engine == "analytic") {
        if (!std::isfinite(r.base_friction_needed)) return "friction needed: not computed (a parapet)";
        return fmt::format("friction needed: base {:.3g}, hinge {:.3g}", r.base_friction_needed,
                           r.hinge_friction_needed);
    }
    const std::string hinge =
        vssw ? fmt::format(", hinge {:.3g} b (residual {:+.3g} b)", r.hinge_slip, r.residual_hinge_slip) : "";
    return fmt::format("slip: base {:.3g} b (residual {:+.3g} b){}{}{}", r.base_slip, r.residual_base_slip, hinge,
                       r.slid_before_rocking == 1.0 ? ", slid before it rocked" : "",
                       r.warnings.empty() ? "" : ", slid off its support (the run ended there)");
}

}  // namespace

void print_response_comparison(const study::ResponseComparison& result, const ChosenModel& chosen, double seconds,
                               bool json, bool strict, std::ostream& out) {
    const study::CaseSpec& c = result.the_case;
    const std::vector<RunResult>& runs = result.runs;
    const RunResult& ref = runs.front();
    const std::string motion = c.file.empty()
                                   ? fmt::format("{} pulse, amplitude {} g, period {} s", c.shape, c.amplitude_g,
                                                 c.pulse_period)
                                   : fmt::format("{} scaled by {:.6g} (PGA {:.4g} g)", c.file, c.scale, c.pga_g);
    const std::string model = describe_assumptions(chosen);

    if (json) {
        io::Json j;
        j["ground_motion"] = {{"description", motion},
                              {"record", c.file.empty() ? io::Json(nullptr) : io::Json(c.file)},
                              {"scale", c.file.empty() ? io::Json(nullptr) : io::Json(c.scale)},
                              {"pga_g", c.file.empty() ? io::Json(c.amplitude_g) : io::Json(c.pga_g)}};
        j["analytic_model"] = assumptions_json(chosen);
        if (c.scene.slip_measured) j["friction"] = friction_json(c.scene);
        io::Json list = io::Json::array();
        for (const RunResult& r : runs) {
            io::Json e = {{"engine", r.engine},
                      {"version", r.version},
                      {"settings", r.settings},
                      {"peak_rotation", io::finite_or_null(r.peak)},
                      {"peak_time", io::finite_or_null(r.peak_time)},
                      {"overturned", std::isfinite(r.overturned) ? io::Json(r.overturned == 1.0) : io::Json(nullptr)},
                      {"t_overturn", io::finite_or_null(r.t_overturn)},
                      {"status", r.status}};
            if (r.engine != "analytic")
                e["peak_rotation_rel_error"] = io::finite_or_null(r.peak / ref.peak - 1.0);
            else
                e["warnings"] = r.warnings;
            if (c.scene.slip_measured) add_friction_fields(r, c, e);
            list.push_back(e);
        }
        j["runs"] = list;
        j["wall_time_s"] = seconds;
        out << io::dump_json(j, 2) << '\n';
    } else {
        Table t(fmt::format("Engines against the analytic model ({}) from rest under {}", model, motion));
        for (const RunResult& r : runs) {
            const std::string name = r.engine == "analytic" ? "analytic model" : r.version;
            if (r.status != "ok") {
                t.text(name, r.status);
                // A wall that slid off its support fails its rocking metrics, but its slips were measured.
                if (c.scene.slip_measured && std::isfinite(r.base_slip))
                    t.text("", friction_line(r, c.scene.vssw.has_value()));
                continue;
            }
            const std::string fell = r.overturned == 1.0 ? fmt::format("overturned at {:.4g} s", r.t_overturn)
                                                         : "stands";
            const std::string error =
                r.engine == "analytic" ? "" : fmt::format(", peak {:+.2f} % against the analytic model",
                                                          100.0 * (r.peak / ref.peak - 1.0));
            t.add(name, fmt::format("{:.6g}", r.peak), "alpha",
                  fmt::format("peak at {:.4g} s, {}{}", r.peak_time, fell, error));
            // The model's need or the engine's slips.
            if (c.scene.slip_measured) t.text("", friction_line(r, c.scene.vssw.has_value()));
        }
        if (!ref.warnings.empty()) t.text("analytic model warns", ref.warnings);
        t.add("wall time", fmt::format("{:.1f}", seconds), "s");
        t.print(out);
    }
    std::vector<std::string> failed;
    for (const RunResult& r : runs)
        if (r.status != "ok") failed.push_back(r.engine + ": " + r.status);
    if (!failed.empty()) throw SimulationFailure(fmt::format("{}", fmt::join(failed, "; ")));
    // The study rows carry the warnings joined into one text (a warning may hold a "; " itself): no count here.
    if (strict && !ref.warnings.empty())
        throw SimulationFailure("--strict: the analytic model's assumptions failed along the run: " + ref.warnings);
}

// The ground motion of a comparison, from its options as `vssw history` reads them, with a study's rules besides
// (a record with its own times and one that shakes, a pulse of positive amplitude), each message naming the option.
study::ResponseMotion response_motion(const GroundMotionOptions& m, LoadedMotion loaded) {
    require(!m.scale || (std::isfinite(*m.scale) && *m.scale > 0.0), "--scale (vssw compare)",
            "a positive finite factor", m.scale.value_or(0.0));
    study::ResponseMotion r;
    r.scale = m.scale;
    r.pga_g = m.pga_g;
    if (m.record) {
        // compare has taken records with their own times only, as a study does (AT2 headers, two columns, a CSV with
        // a time column). The record read above could now be one of values at --record-dt or of named columns; taking
        // those widens what compare accepts, a change of its own.
        if (!m.format.is_default())
            throw InputError("--record-dt, --time-column and --accel-column are read by history and free, not yet by "
                             "compare: give compare a record with its times (an AT2 file, two columns, or a CSV whose "
                             "first two columns are time and acceleration)");
        try {
            study::require_shakes(loaded.unscaled, *m.record);
        } catch (const InputError& e) {
            throw InputError(fmt::format("--record: {}", e.what()));
        }
        r.file = *m.record;
        r.record = std::move(loaded.unscaled);
        return r;
    }
    // `vssw history` takes a negative amplitude as a pulse the other way; a study's amplitude is positive (--pga
    // replaces it).
    if (!m.pga_g && !(*m.amplitude_g > 0.0))
        throw InputError(fmt::format("--amplitude: must be a positive number, got {}", *m.amplitude_g));
    r.shape = *m.pulse;
    r.amplitude_g = *m.amplitude_g;
    r.pulse_period = *m.pulse_period;
    r.duration = m.duration.value_or(0.0);
    return r;
}

study::ResponseComparison compare_under_motion(const ChosenModel& chosen, const GroundMotionOptions& motion,
                                               const std::vector<study::ResponseEngine>& engines,
                                               const std::optional<std::string>& friction) {
    const study::ResponseMotion m = response_motion(motion, load_ground_motion(motion));
    return study::compare_response(with_friction(multibody::WallScene(chosen.wall), friction), chosen.assumptions, m,
                                   engines);
}

}  // namespace vssw::cli
