#include "apps/compare_response.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <ostream>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "apps/model_validity.hpp"
#include "apps/json.hpp"
#include "apps/simulation_failure.hpp"
#include "apps/table.hpp"
#include "study/grid.hpp"
#include "study/measure.hpp"
#include "study/spec.hpp"

namespace vssw::cli {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
const std::vector<std::string> kMetrics = {"peak_rotation", "peak_time", "overturned", "t_overturn"};

// The options as the study file a user would write for them.
nlohmann::json study_document(const ResponseCompareRequest& r) {
    nlohmann::json doc;
    doc["name"] = "compare";
    doc["metrics"] = kMetrics;
    nlohmann::json engines = {"analytic"};  // the reference; "analytic" named as an engine is the same run
    for (const std::string& e : r.engines)
        if (e != "analytic") engines.push_back(e);
    doc["engines"] = engines;

    nlohmann::json wall = {{"model", r.model.model}, {"height", r.wall.height}, {"thickness", r.wall.thickness},
                           {"xi", r.wall.xi}, {"density", r.wall.density}, {"g", r.wall.g}};
    if (r.model.model == "vssw" && r.wall.hinge) wall["hinge"] = *r.wall.hinge;
    doc["wall"] = wall;
    const ImpactLaw impact = parse_impact_law(r.model.impact);
    doc["assumptions"] = {{"kinematics", r.model.kinematics},
                          {"impact", impact.kind == ImpactLaw::Kind::ratio ? nlohmann::json(impact.ratio)
                                                                            : nlohmann::json(r.model.impact)},
                          {"roller", r.model.roller}};

    const GroundMotionOptions& m = r.motion;
    // Checked here, as typed: a pulse's scale goes into its amplitude below, and the study machinery's message would
    // then name the amplitude.
    if (m.scale)
        require(std::isfinite(*m.scale) && *m.scale > 0.0, "--scale (vssw compare)", "a positive finite factor",
                *m.scale);
    nlohmann::json ex;
    if (m.record) {
        // The run goes through the study machinery, whose records carry their own times (AT2 headers, two columns,
        // a CSV with a time column): a file that needs --record-dt or named columns was read as two columns and
        // refused with a message about its numbers. Said as it is instead.
        if (!m.format.is_default())
            throw InputError("--record-dt, --time-column and --accel-column are read by history and free, not yet by "
                             "compare: give compare a record with its times (an AT2 file, two columns, or a CSV whose "
                             "first two columns are time and acceleration)");
        ex = {{"kind", "record"}, {"file", *m.record}};
        if (m.units) ex["units"] = *m.units;
        if (m.scale) ex["scale"] = *m.scale;
        if (m.pga_g) ex["pga"] = *m.pga_g;
    } else {
        // A pulse's scale multiplies its amplitude; --pga sets it (the pulses' peak is their amplitude).
        double amplitude = m.amplitude_g.value_or(0.0);
        if (m.scale) amplitude *= *m.scale;
        if (m.pga_g) amplitude = *m.pga_g;
        ex = {{"kind", "pulse"}, {"shape", *m.pulse}, {"amplitude", amplitude}, {"pulse_period", *m.pulse_period}};
        if (m.duration) ex["duration"] = *m.duration;
    }
    doc["excitation"] = ex;

    nlohmann::json settings = nlohmann::json::object();
    for (std::size_t i = 0; i < r.engines.size(); ++i) {
        if (r.engines[i] == "analytic") continue;
        nlohmann::json s = nlohmann::json::object();
        const multibody::EngineSettings defaults = multibody::make_engine(r.engines[i])->default_settings();
        const multibody::EngineSettings& given = r.settings[i];
        if (given.dt != defaults.dt) s["dt"] = given.dt;
        if (given.iterations != defaults.iterations) s["iterations"] = given.iterations;
        for (const auto& [k, v] : given.knobs) s[k] = v;
        if (!s.empty()) settings[r.engines[i]] = s;
    }
    if (!settings.empty()) doc["settings"] = settings;
    return doc;
}

struct RunResult {
    std::string engine, version, settings;
    double peak = kNaN, peak_time = kNaN, overturned = kNaN, t_overturn = kNaN;
    std::string status = "ok", warnings;
};

Json number_or_null(double x) { return finite_or_null(x); }

constexpr const char* kOptionsName = "(vssw compare options)";

// The study machinery names its keys ("study file (vssw compare options): excitation.scale: ..."); the user typed
// options: name those ("--scale: ...").
std::string as_option_message(const std::string& message) {
    // (--scale is checked as typed in study_document, before the machinery sees it.)
    static const std::pair<const char*, const char*> kKeys[] = {
        {"excitation.pga: ", "--pga: "},           {"excitation.amplitude: ", "--amplitude: "},
        {"excitation.pulse_period: ", "--pulse-period: "}, {"excitation.duration: ", "--duration: "},
        {"excitation.file: ", "--record: "},       {"excitation.units: ", "--units: "},
        {"excitation.shape: ", "--pulse: "},
    };
    const std::string prefix = fmt::format("study file {}: ", kOptionsName);
    if (message.rfind(prefix, 0) != 0) return message;
    const std::string rest = message.substr(prefix.size());
    for (const auto& [key, option] : kKeys)
        if (rest.rfind(key, 0) == 0) return option + rest.substr(std::string(key).size());
    return rest;
}

}  // namespace

void compare_response(const ResponseCompareRequest& request, std::ostream& out) {
    const auto start = std::chrono::steady_clock::now();
    const study::Grid grid = [&] {
        try {
            return study::Grid(study::study_from_json(study_document(request), kOptionsName, "."));
        } catch (const InputError& e) {
            throw InputError(as_option_message(e.what()));
        }
    }();
    const study::CaseSpec c = grid.make_case(grid.case_ids().front());
    // A step too coarse for the wall or the motion is bad input here, before any run (in a study: a failed row).
    for (const study::RunSpec& run : grid.runs())
        study::require_run_resolves(grid, c, run, *multibody::make_engine(run.engine));

    std::vector<RunResult> runs;
    for (std::size_t r = 0; r < grid.runs().size(); ++r) {
        const study::RunSpec& run = grid.runs()[r];
        const std::unique_ptr<multibody::Engine> engine = multibody::make_engine(run.engine);
        RunResult res;
        res.engine = run.engine;
        res.version = engine->version();
        res.settings = run.settings_text;
        for (const study::Measurement& m : study::measure(grid, c, r, *engine)) {
            const std::string& metric = kMetrics[m.metric];
            if (metric == "peak_rotation") res.peak = m.value;
            if (metric == "peak_time") res.peak_time = m.value;
            if (metric == "overturned") res.overturned = m.value;
            if (metric == "t_overturn") res.t_overturn = m.value;
            if (m.status != "ok") res.status = m.status;
            res.warnings = m.warnings;
        }
        runs.push_back(res);
    }
    const RunResult& ref = runs.front();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::string motion = c.file.empty()
                                   ? fmt::format("{} pulse, amplitude {} g, period {} s", c.shape, c.amplitude_g,
                                                 c.pulse_period)
                                   : fmt::format("{} scaled by {:.6g} (PGA {:.4g} g)", c.file, c.scale, c.pga_g);
    const std::string model = c.scene.vssw ? fmt::format("{} kinematics, impact {}, {} roller", request.model.kinematics,
                                                         request.model.impact, request.model.roller)
                                           : fmt::format("parapet, impact {}", request.model.impact);

    if (request.json) {
        Json j;
        j["ground_motion"] = {{"description", motion},
                              {"record", c.file.empty() ? Json(nullptr) : Json(c.file)},
                              {"scale", c.file.empty() ? Json(nullptr) : Json(c.scale)},
                              {"pga_g", c.file.empty() ? Json(c.amplitude_g) : Json(c.pga_g)}};
        j["analytic_model"] = {{"kinematics", c.scene.vssw ? Json(request.model.kinematics) : Json(nullptr)},
                               {"impact", request.model.impact},
                               {"roller", c.scene.vssw ? Json(request.model.roller) : Json(nullptr)}};
        Json list = Json::array();
        for (const RunResult& r : runs) {
            Json e = {{"engine", r.engine},
                      {"version", r.version},
                      {"settings", r.settings},
                      {"peak_rotation", number_or_null(r.peak)},
                      {"peak_time", number_or_null(r.peak_time)},
                      {"overturned", std::isfinite(r.overturned) ? Json(r.overturned == 1.0) : Json(nullptr)},
                      {"t_overturn", number_or_null(r.t_overturn)},
                      {"status", r.status}};
            if (r.engine != "analytic")
                e["peak_rotation_rel_error"] = number_or_null(r.peak / ref.peak - 1.0);
            else
                e["warnings"] = r.warnings;
            list.push_back(e);
        }
        j["runs"] = list;
        j["wall_time_s"] = seconds;
        out << j.dump(2) << '\n';
    } else {
        Table t(fmt::format("Engines against the analytic model ({}) from rest under {}", model, motion));
        for (const RunResult& r : runs) {
            const std::string name = r.engine == "analytic" ? "analytic model" : r.version;
            if (r.status != "ok") {
                t.text(name, r.status);
                continue;
            }
            const std::string fell = r.overturned == 1.0 ? fmt::format("overturned at {:.4g} s", r.t_overturn)
                                                         : "stands";
            const std::string error =
                r.engine == "analytic" ? "" : fmt::format(", peak {:+.2f} % against the analytic model",
                                                          100.0 * (r.peak / ref.peak - 1.0));
            t.add(name, fmt::format("{:.6g}", r.peak), "alpha",
                  fmt::format("peak at {:.4g} s, {}{}", r.peak_time, fell, error));
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
    if (request.strict && !ref.warnings.empty())
        throw SimulationFailure("--strict: the analytic model's assumptions failed along the run: " + ref.warnings);
}

}  // namespace vssw::cli
