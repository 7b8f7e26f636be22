#include "validation/suite_file.hpp"

#include <algorithm>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <set>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "analytic/data_dir.hpp"
#include "analytic/error.hpp"
#include "multibody/engine.hpp"

namespace vssw::validation {
namespace {

std::string fmt_number(double x) { return fmt::format("{}", x); }

// The scene's numbers, to tell whether two parts name the same wall alike.
std::string scene_key(const multibody::WallScene& s) {
    if (s.vssw) return fmt::format("vssw {} {} {} {} {} {}", s.vssw->b, s.vssw->h1, s.vssw->h2, s.vssw->xi, s.vssw->density, s.vssw->g);
    return fmt::format("parapet {} {} {} {} {}", s.parapet->b, s.parapet->h, s.parapet->xi, s.parapet->density, s.parapet->g);
}

// The report's reference is the analytic model under one assumption set (analytic/assumption_sets.hpp): a suite file
// that gives assumptions names that set, none when it gives none. Assumptions that vary, or that are not one set's
// (e.g. exact kinematics with Eq. 19's impact), are refused, not ignored: the engines are measured against one model.
std::optional<AssumptionSet> reference_set(const study::StudySpec& spec) {
    if (!spec.as_read.contains("assumptions")) return std::nullopt;
    std::vector<study::Level> levels;
    std::vector<std::string> given;
    for (const study::Axis& a : spec.assumptions) {
        if (a.levels.size() != 1)
            throw InputError(fmt::format("suite file {}: assumptions.{} varies: a suite's reference is one assumption "
                                         "set, paper or mechanism",
                                         spec.path, a.key));
        levels.push_back(a.levels.front());
        given.push_back(fmt::format("{} {}", a.key, study::to_text(a.levels.front())));
    }
    const std::optional<AssumptionSet> set = set_of(study::assumptions_of(levels));
    if (!set)
        throw InputError(fmt::format("suite file {}: assumptions ({}) are neither set paper nor mechanism: a suite's "
                                     "reference is one assumption set",
                                     spec.path, fmt::join(given, ", ")));
    return set;
}

// The settings of one engine's single run in a part (its [settings] and [part.settings], one level each); a part
// whose engine settings vary is a step study (dt of a free part) or refused: the report runs each engine at one
// setting a case and would otherwise run it at its defaults without a word.
std::optional<multibody::EngineSettings> single_settings(const study::Grid& grid, std::size_t pi, const study::EngineSpec& e,
                                                         bool step_study,
                                                         const std::function<InputError(const std::string&)>& fail) {
    if (e.settings.empty()) return std::nullopt;
    if (e.name == "analytic")
        throw fail("settings of analytic: the report's reference, the analytic model, runs at its own settings; a "
                   "suite cannot change them");
    for (const study::Axis& a : e.settings)
        if (a.varied() && !(a.key == "dt" && step_study))
            throw fail(fmt::format("the settings of {} vary ({}): a suite runs each engine at one setting a case "
                                   "(a varied dt of a free part is a step study)",
                                   e.name, a.key));
    for (const study::RunSpec& run : grid.runs())
        if (run.part == pi && run.engine == e.name) return run.settings;
    return std::nullopt;
}

// The engines' settings a suite gives once for all its parts ([settings.<engine>], one level each), as the grid
// applies them (Grid: dt, iterations, the knobs by name); a part may add its own per case.
std::map<std::string, multibody::EngineSettings> suite_engine_settings(const study::StudySpec& spec) {
    std::map<std::string, multibody::EngineSettings> out;
    for (const study::EngineSpec& e : spec.engines) {
        if (e.settings.empty()) continue;
        // The analytic model is the reference (reference_set); its settings are the report's own.
        if (e.name == "analytic")
            throw InputError(fmt::format("suite file {}: settings.analytic: the report's reference, the analytic model, "
                                         "runs at its own settings; a suite cannot change them",
                                         spec.path));
        if (std::any_of(e.settings.begin(), e.settings.end(), [](const study::Axis& a) { return a.varied(); })) continue;
        multibody::EngineSettings s = multibody::make_engine(e.name)->default_settings();
        for (const study::Axis& a : e.settings) s.set(a.key, std::get<double>(a.levels.front()));
        out[e.name] = s;
    }
    return out;
}

// A suite built part by part from a study grid: walls and records named once each, case ids unique.
class SuiteBuilder {
public:
    SuiteBuilder(const study::Grid& grid, const std::string& name) : grid_(grid), spec_(grid.spec()) {
        suite_.name = name;
        if (const std::optional<AssumptionSet> set = reference_set(spec_)) {
            suite_.reference = *set;
            suite_.reference_named = true;
        }
        suite_.engine_settings = suite_engine_settings(spec_);
    }

    void add_part(std::size_t pi) {
        const study::PartSpec& part = spec_.parts[pi];
        if (part.names.wall_name.empty()) throw fail(part, "a suite's part names its walls (wall_name)");
        std::vector<study::CaseSpec> cases;
        for (const int id : grid_.case_ids()) {
            study::CaseSpec c = grid_.make_case(id);
            if (c.part == pi) cases.push_back(std::move(c));
        }
        // Engines whose step varies in this part: a step study.
        std::vector<std::string> stepped;
        for (const study::EngineSpec& e : part.engines)
            for (const study::Axis& a : e.settings)
                if (a.key == "dt" && a.varied()) stepped.push_back(e.name);
        // The other engines' settings in this part, one set each (single_settings refuses more).
        std::map<std::string, multibody::EngineSettings> settings;
        const auto part_fail = [&](const std::string& why) { return fail(part, why); };
        const bool free = part.kind == study::ExcitationKind::free;
        for (const study::EngineSpec& e : part.engines) {
            const auto s = single_settings(grid_, pi, e, free, part_fail);  // checked for a step study's engine too
            if (s && std::find(stepped.begin(), stepped.end(), e.name) == stepped.end()) settings[e.name] = *s;
        }
        switch (part.kind) {
            case study::ExcitationKind::threshold:
                for (const study::CaseSpec& c : cases) {
                    const std::string w = add_wall(part, c);
                    add_case(part, {w, CaseKind::threshold, w, 0.0, "", {}, "", settings});
                }
                break;
            case study::ExcitationKind::free:
                if (stepped.empty()) {
                    for (const study::CaseSpec& c : cases) {
                        const std::string w = add_wall(part, c);
                        add_case(part, {fmt::format("{}/r{}", w, fmt_number(c.theta0)), CaseKind::free, w,
                                        c.theta0, "", {}, "", settings});
                    }
                } else {
                    add_step_cases(pi, cases, stepped);
                }
                break;
            case study::ExcitationKind::record: add_record_cases(part, cases, settings); break;
            default:
                throw fail(part, fmt::format("a suite runs thresholds, free vibrations, step studies and records, not "
                                             "kind {}",
                                             to_string(part.kind)));
        }
    }

    Suite take() { return std::move(suite_); }

private:
    InputError fail(const study::PartSpec& part, const std::string& why) const {
        return InputError(
            fmt::format("suite file {}: {}: {}", spec_.path, part.where.empty() ? "the study" : part.where, why));
    }

    // The wall's id, adding the wall the first time it is named; one name given to two walls is refused.
    std::string add_wall(const study::PartSpec& part, const study::CaseSpec& c) {
        const std::string id = grid_.wall_name(c);
        const std::string key = scene_key(c.scene);
        const auto it = wall_scenes_.find(id);
        if (it != wall_scenes_.end()) {
            if (it->second != key)
                throw fail(part, fmt::format("the wall name '{}' is given to two different walls", id));
            return id;
        }
        wall_scenes_.emplace(id, key);
        const std::string label = grid_.wall_label(c);
        suite_.walls.push_back({id, label.empty() ? id : label, c.scene});
        return id;
    }

    void add_case(const study::PartSpec& part, SuiteCase sc) {
        if (!ids_.insert(sc.id).second) throw fail(part, fmt::format("the case id '{}' comes twice", sc.id));
        suite_.cases.push_back(std::move(sc));
    }

    // A free part whose engines' dt varies: one case per engine, release and step.
    void add_step_cases(std::size_t pi, const std::vector<study::CaseSpec>& cases, const std::vector<std::string>& stepped) {
        const study::PartSpec& part = spec_.parts[pi];
        for (const std::string& engine : stepped)
            for (const study::CaseSpec& c : cases) {
                const std::string w = add_wall(part, c);
                for (const study::RunSpec& run : grid_.runs()) {
                    if (run.part != pi || run.engine != engine) continue;
                    const double dt = run.settings.dt;
                    add_case(part, {fmt::format("{}/r{}/dt{}/{}", w, fmt_number(c.theta0), fmt_number(dt), engine),
                                    CaseKind::step, w, c.theta0, "", dt, engine, {{engine, run.settings}}});
                    std::vector<double>& dts = suite_.step_study[engine];
                    if (std::find(dts.begin(), dts.end(), dt) == dts.end()) dts.push_back(dt);
                }
            }
    }

    // A record part: one case per wall and record, each record named once.
    void add_record_cases(const study::PartSpec& part, const std::vector<study::CaseSpec>& cases,
                          const std::map<std::string, multibody::EngineSettings>& settings) {
        if (part.names.record_name.empty())
            throw fail(part, "a suite's record part names its records (record_name)");
        // The report reads a suite's records in the units their files say (validation/suite.cpp): refuse others.
        if (part.excitation_axis("units"))
            throw fail(part, "a suite's records are read in the units their files give: no 'units'");
        for (const study::CaseSpec& c : cases) {
            const std::string w = add_wall(part, c);
            const std::string r = grid_.record_name(c);
            const auto same = std::find_if(suite_.records.begin(), suite_.records.end(),
                                           [&](const SuiteRecord& x) { return x.id == r; });
            if (same != suite_.records.end() && (same->path != grid_.record_path(c.file) || same->scale != c.scale))
                throw fail(part, fmt::format("the record name '{}' is given to two different records", r));
            if (same == suite_.records.end()) {
                const std::string label = grid_.record_label(c);
                suite_.records.push_back({r, label.empty() ? r : label, grid_.record_path(c.file), c.scale});
            }
            // The suite's own tail unless the part gives one (compare/experiments.hpp says why the two differ).
            const double tail = part.excitation_axis("response_tail") ? c.response_tail : compare::kSuiteResponseTail;
            add_case(part, {fmt::format("{}/{}", w, r), CaseKind::history, w, 0.0, r, {}, "", settings, tail});
        }
    }

    const study::Grid& grid_;
    const study::StudySpec& spec_;
    Suite suite_;
    std::map<std::string, std::string> wall_scenes_;  // id -> scene_key
    std::set<std::string> ids_;
};

}  // namespace

Suite suite_from_study(const study::Grid& grid, const std::string& suite_name) {
    SuiteBuilder builder(grid, suite_name);
    for (std::size_t pi = 0; pi < grid.spec().parts.size(); ++pi) builder.add_part(pi);
    return builder.take();
}

std::string suite_file(const std::string& name_or_path) {
    if (name_or_path == "default" || name_or_path == "full")
        return shipped_studies_dir() + "/validation-" + name_or_path + ".toml";
    return name_or_path;
}

Suite read_suite(const std::string& name_or_path, const std::string& data_dir) {
    const std::string file = suite_file(name_or_path);
    std::error_code ec;
    if (file == name_or_path && !std::filesystem::is_regular_file(file, ec))
        throw InputError(fmt::format("unknown suite '{}' (valid: default, full, or a suite file)", name_or_path));
    const study::Grid grid(study::read_study_file(file));
    const bool shipped = file != name_or_path;
    Suite suite = suite_from_study(grid, shipped ? name_or_path : grid.spec().name);
    if (!data_dir.empty())
        for (SuiteRecord& r : suite.records)
            r.path = data_dir + "/" + std::filesystem::path(r.path).filename().string();
    return suite;
}

}  // namespace vssw::validation
