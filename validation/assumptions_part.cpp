#include "validation/assumptions_part.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include <fmt/format.h>

#include "analytic/data_dir.hpp"
#include "analytic/error.hpp"
#include "multibody/engine.hpp"
#include "study/effects.hpp"
#include "study/ensemble_measures.hpp"
#include "study/grid.hpp"
#include "study/outputs.hpp"
#include "study/runner.hpp"
#include "study/spec.hpp"
#include "study/study_data.hpp"
#include "validation/study_engines.hpp"

namespace vssw::validation {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr const char* kShippedStudy = "assumptions-report.toml";
constexpr const char* kShippedFullStudy = "assumptions-physical.toml";

bool varies_a_physical_assumption(const study::StudySpec& spec) {
    for (const study::PartSpec& part : spec.parts)
        for (const std::string& key : study::kPhysicalAssumptionKeys)
            if (const study::Axis* a = part.wall_axis(key); a && a->varied()) return true;
    return false;
}

// The relaxations the model's motion cannot follow at all: it has no friction, so its rocking at any coefficient is
// the paper's and a change of 0 would read as a prediction (it says where it would slide: a warning on its rows).
bool model_cannot_follow(const std::string& key) { return key == "friction" || key == "hinge_friction"; }

// The study's rows of the analytic model alone, or of the engines alone: each pairs within itself. The model's rows
// that warn (outside its validity: it would slide, a pivot would pull) are no predictions: their values are left out.
study::StudyData rows_of(const study::StudyData& d, bool analytic) {
    study::StudyData out = d;
    const std::size_t engine = d.column("engine");
    out.rows.erase(std::remove_if(out.rows.begin(), out.rows.end(),
                                  [&](const study::StudyRow& r) { return (d.text(r, engine) == "analytic") != analytic; }),
                   out.rows.end());
    if (analytic)
        for (study::StudyRow& r : out.rows)
            if (r.warning != 0) r.value = kNaN;
    return out;
}

// The slips (metrics in b) of the engines' runs at each relaxed level: the range of the values themselves.
void add_slips(const study::StudyData& d, std::vector<RelaxationEffect>& out) {
    const std::size_t engine = d.column("engine");
    for (const std::string& key : study::kPhysicalAssumptionKeys) {
        const std::size_t column = d.column(key);
        if (column == std::string::npos || !d.columns[column].varied) continue;
        const study::ColumnLevels& c = d.columns[column];
        for (std::size_t level = 1; level < c.order.size(); ++level)
            for (std::size_t m = 0; m < d.metrics.size(); ++m) {
                if (!d.metrics[m].is_slip()) continue;
                RelaxationEffect e;
                e.parameter = key;
                e.from = c.texts[c.order.front()];
                e.to = c.texts[c.order[level]];
                e.metric = d.metrics[m].name;
                e.absolute = true;
                e.model = kNaN;
                e.engines_lo = std::numeric_limits<double>::infinity();
                e.engines_hi = -e.engines_lo;
                for (const study::StudyRow& r : d.rows)
                    if (r.metric == m && r.levels[column] == c.order[level] && d.text(r, engine) != "analytic" &&
                        std::isfinite(r.value)) {
                        e.engines_lo = std::min(e.engines_lo, r.value);
                        e.engines_hi = std::max(e.engines_hi, r.value);
                        ++e.engine_pairs;
                    }
                if (e.engine_pairs > 0) out.push_back(e);
            }
    }
}

// The physical assumptions' effects of the model and of the engines, one entry per (parameter level, metric) that
// either has pairs for, in the study's order.
std::vector<RelaxationEffect> relaxation_effects(const study::StudyData& d) {
    const std::vector<study::Effect> model = study::parameter_effects(rows_of(d, true));
    const std::vector<study::Effect> engines = study::parameter_effects(rows_of(d, false));
    std::vector<RelaxationEffect> out;
    const auto entry = [&](const study::Effect& e) -> RelaxationEffect& {
        for (RelaxationEffect& r : out)
            if (r.parameter == e.parameter && r.to == e.to && r.metric == d.metrics[e.metric].name) return r;
        RelaxationEffect r;
        r.parameter = e.parameter;
        r.from = e.from;
        r.to = e.to;
        r.metric = d.metrics[e.metric].name;
        r.binary = e.binary;
        r.model = r.engines_lo = r.engines_hi = kNaN;
        out.push_back(r);
        return out.back();
    };
    const auto relative = [&](const study::Effect& e) {
        return e.physical && e.pairs > 0 && !d.metrics[e.metric].is_slip();
    };
    for (const study::Effect& e : model)
        if (relative(e) && !model_cannot_follow(e.parameter)) {
            RelaxationEffect& r = entry(e);
            r.model = e.median;
            r.model_pairs = e.pairs;
        }
    for (const study::Effect& e : engines)
        if (relative(e)) {
            RelaxationEffect& r = entry(e);
            r.engines_lo = e.lo + 0.0;  // + 0: a binary metric's -down / pairs with none down is -0
            r.engines_hi = e.hi;
            r.engine_pairs = e.pairs;
        }
    add_slips(d, out);
    // The study's order: the parameter's column, its level's position, the metric's.
    const auto rank = [&](const RelaxationEffect& r) {
        const study::ColumnLevels& c = d.columns[d.column(r.parameter)];
        std::size_t level = 0;
        while (level < c.order.size() && c.texts[c.order[level]] != r.to) ++level;
        std::size_t metric = 0;
        while (metric < d.metrics.size() && d.metrics[metric].name != r.metric) ++metric;
        return std::tuple(d.column(r.parameter), level, metric);
    };
    std::stable_sort(out.begin(), out.end(),
                     [&](const RelaxationEffect& a, const RelaxationEffect& b) { return rank(a) < rank(b); });
    return out;
}

// The reason of a failed row without the engine's own name before it ("ode: the wall did not lift" is ODE's).
std::string reason_of(const std::string& status, const std::string& engine) {
    const std::string reason = study::failure_reason(status);
    const std::string own = engine + ": ";
    return reason.rfind(own, 0) == 0 ? reason.substr(own.size()) : reason;
}

// "<engine>: <text> (n rows)" per engine and text, in engine then text order.
std::vector<std::string> counted_lines(const std::map<std::pair<std::string, std::string>, long>& count) {
    std::vector<std::string> out;
    for (const auto& [key, n] : count)
        out.push_back(fmt::format("{}: {} ({} row{})", multibody::engine_display_name(key.first), key.second, n,
                                  n == 1 ? "" : "s"));
    return out;
}

// The failed rows, by engine and reason: what an engine (or the model) refused to express, and what it failed to
// measure; the statuses do not tell the two apart.
std::vector<std::string> failed_runs(const study::StudyData& d) {
    const std::size_t engine = d.column("engine");
    std::map<std::pair<std::string, std::string>, long> count;
    for (const study::StudyRow& r : d.rows)
        if (study::is_failed(d.statuses[r.status])) {
            const std::string& name = d.text(r, engine);
            ++count[{name, reason_of(d.statuses[r.status], name)}];
        }
    return counted_lines(count);
}

// The analytic model's warnings, by text: the runs whose changes the model does not give (rows_of).
std::vector<std::string> model_warnings(const study::StudyData& d) {
    const std::size_t engine = d.column("engine");
    std::map<std::pair<std::string, std::string>, long> count;
    for (const study::StudyRow& r : d.rows)
        if (r.warning != 0 && d.text(r, engine) == "analytic") ++count[{"analytic", d.warnings[r.warning]}];
    return counted_lines(count);
}

}  // namespace

std::string assumptions_study_file(const std::string& name_or_path, const std::vector<std::string>& engines) {
    if (name_or_path == "none") return "";
    const std::string file = name_or_path == "default" ? shipped_studies_dir() + "/" + kShippedStudy
                             : name_or_path == "full"  ? shipped_studies_dir() + "/" + kShippedFullStudy
                                                       : name_or_path;
    if (!varies_a_physical_assumption(with_engines(file, engines)))
        throw InputError(fmt::format("--relaxations {}: the study varies none of the paper's physical assumptions "
                                     "(wall keys {})",
                                     file, fmt::join(study::kPhysicalAssumptionKeys, ", ")));
    return file;
}

std::string default_assumptions_for_suite(const std::string& suite) { return suite == "full" ? "full" : "default"; }

AssumptionsPart run_assumptions_part(const std::string& study_file, const std::vector<std::string>& engines,
                                     const std::filesystem::path& dir, const PartRunOptions& options) {
    const study::StudySpec spec = with_engines(study_file, engines);
    const study::Grid grid(spec);
    const study::StudyRunOptions run = study_run_options(options);
    study::StudyRunResult result;
    {
        const io::FolderLock lock = study::prepare_study_dir(grid, dir, run);
        result = study::run_study(grid, dir, run);
    }
    study::OutputOptions output;
    output.plots = options.plots;
    output.gnuplot = options.gnuplot;
    const study::StudyData d = study::take_study_data(result, dir);  // once: the study's outputs and the section read it
    study::write_study_outputs(dir, output, d, study::ensemble_measures(d));

    AssumptionsPart part;
    static_cast<StudyPartRun&>(part) = study_part_run(study_file, spec, dir, result);
    part.effects = relaxation_effects(d);
    part.refusals = failed_runs(d);
    part.model_warnings = model_warnings(d);
    for (const study::MetricMeta& m : d.metrics) {
        const std::string name = "tornado_physical_" + m.name;
        if (std::filesystem::exists(dir / "plots" / (name + ".svg"))) {
            part.tornadoes.push_back("../" + dir.filename().string() + "/plots/" + name);
            part.tornado_titles.push_back(fmt::format(
                "What the paper's physical assumptions cost: {} (bar: smallest to largest change over walls and "
                "backends; dot: median)",
                m.name));
        }
    }
    return part;
}

}  // namespace vssw::validation
