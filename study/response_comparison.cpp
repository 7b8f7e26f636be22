#include "study/response_comparison.hpp"

#include <memory>
#include <utility>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "study/measure.hpp"

namespace vssw::study {
namespace {

const std::vector<std::string> kMetrics = {"peak_rotation",       "peak_time",          "overturned",
                                           "t_overturn",          "base_slip",          "hinge_slip",
                                           "residual_base_slip",  "residual_hinge_slip", "slid_before_rocking",
                                           "base_friction_needed", "hinge_friction_needed"};

// The one case: the wall as built, the motion as the study's excitation keys would give it.
CaseSpec one_case(const multibody::WallScene& wall, const ResponseMotion& m) {
    CaseSpec c;
    c.scene = wall;
    describe_wall(c);
    if (!m.file.empty()) {
        c.file = m.file;
        c.record_key = m.file;
        scale_record(c, m.record, m.pga_g, m.scale.value_or(1.0));
    } else {
        c.shape = m.shape;
        c.amplitude_g = m.pga_g ? *m.pga_g : m.amplitude_g * m.scale.value_or(1.0);
        c.pulse_period = m.pulse_period;
        c.duration = m.duration;
    }
    return c;
}

// The engine's settings as a study file would give them: dt and iterations where they are not the defaults, then
// every knob.
std::string settings_text(const multibody::EngineSettings& given, const multibody::EngineSettings& defaults) {
    std::vector<std::string> parts;
    if (given.dt != defaults.dt) parts.push_back(fmt::format("dt={}", given.dt));
    if (given.iterations != defaults.iterations)
        parts.push_back(fmt::format("iterations={}", static_cast<double>(given.iterations)));
    for (const auto& [name, value] : given.knobs) parts.push_back(fmt::format("{}={}", name, value));
    return fmt::format("{}", fmt::join(parts, " "));
}

// The reference's run (left out, with the reason in `skipped`, when its assumptions are not a model), then every
// other engine's.
std::vector<RunSpec> runs_of(const multibody::AnalyticAssumptions& reference,
                             const std::vector<ResponseEngine>& engines, std::vector<std::string>& skipped) {
    std::vector<RunSpec> runs;
    RunSpec analytic;
    analytic.engine = "analytic";
    analytic.settings = multibody::make_engine("analytic")->default_settings();
    analytic.assumptions = assumption_levels(reference);
    if (apply_assumptions(analytic, reference, skipped)) runs.push_back(std::move(analytic));
    for (const ResponseEngine& e : engines) {
        if (e.name == "analytic") continue;  // the reference's own run
        RunSpec run;
        run.engine = e.name;
        run.settings = e.settings;
        run.settings_text = settings_text(e.settings, multibody::make_engine(e.name)->default_settings());
        runs.push_back(std::move(run));
    }
    return runs;
}

StudySpec one_part_study(const ResponseMotion& m, const std::vector<RunSpec>& runs) {
    StudySpec spec;
    spec.name = "compare";
    spec.base_dir = ".";
    spec.metrics = kMetrics;
    PartSpec part;
    part.kind = m.file.empty() ? ExcitationKind::pulse : ExcitationKind::record;
    part.metrics = kMetrics;
    for (const RunSpec& run : runs) part.engines.push_back({run.engine, {}});
    spec.engines = part.engines;
    spec.parts.push_back(std::move(part));
    return spec;
}

ResponseRun measured(const Grid& grid, const CaseSpec& c, std::size_t r) {
    const RunSpec& run = grid.runs()[r];
    const std::unique_ptr<multibody::Engine> engine = multibody::make_engine(run.engine);
    ResponseRun res;
    res.engine = run.engine;
    res.version = engine->version();
    res.settings = run.settings_text;
    for (const Measurement& m : measure(grid, c, r, *engine)) {
        const std::string& metric = kMetrics[m.metric];
        if (metric == "peak_rotation") res.peak = m.value;
        if (metric == "peak_time") res.peak_time = m.value;
        if (metric == "overturned") res.overturned = m.value;
        if (metric == "t_overturn") res.t_overturn = m.value;
        if (metric == "base_slip") res.base_slip = m.value;
        if (metric == "hinge_slip") res.hinge_slip = m.value;
        if (metric == "residual_base_slip") res.residual_base_slip = m.value;
        if (metric == "residual_hinge_slip") res.residual_hinge_slip = m.value;
        if (metric == "slid_before_rocking") res.slid_before_rocking = m.value;
        if (metric == "base_friction_needed") res.base_friction_needed = m.value;
        if (metric == "hinge_friction_needed") res.hinge_friction_needed = m.value;
        if (m.status != "ok") res.status = m.status;
        res.warnings = m.warnings;
    }
    return res;
}

}  // namespace

ResponseComparison compare_response(const multibody::WallScene& wall, const multibody::AnalyticAssumptions& reference,
                                    const ResponseMotion& motion, const std::vector<ResponseEngine>& engines) {
    std::vector<std::string> skipped;
    std::vector<RunSpec> runs = runs_of(reference, engines, skipped);
    if (runs.empty()) throw InputError(fmt::format("no run left: {}", fmt::join(skipped, "; ")));
    const Grid grid(one_part_study(motion, runs), one_case(wall, motion), std::move(runs), motion.record);
    const CaseSpec c = grid.make_case(1);
    // A step too coarse for the wall or the motion is bad input here, before any run (in a study: a failed row).
    for (const RunSpec& run : grid.runs()) require_run_resolves(grid, c, run, *multibody::make_engine(run.engine));
    ResponseComparison out{c, {}};
    for (std::size_t r = 0; r < grid.runs().size(); ++r) out.runs.push_back(measured(grid, c, r));
    return out;
}

}  // namespace vssw::study
