#include "study/suite_file.hpp"

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>

#include <fmt/format.h>

#include "analytic/data_dir.hpp"
#include "analytic/error.hpp"

namespace vssw::study {
namespace {

std::string fmt_number(double x) { return fmt::format("{}", x); }

// The scene's numbers, to tell whether two parts name the same wall alike.
std::string scene_key(const multibody::WallScene& s) {
    if (s.vssw) return fmt::format("vssw {} {} {} {} {} {}", s.vssw->b, s.vssw->h1, s.vssw->h2, s.vssw->xi, s.vssw->density, s.vssw->g);
    return fmt::format("parapet {} {} {} {} {}", s.parapet->b, s.parapet->h, s.parapet->xi, s.parapet->density, s.parapet->g);
}

}  // namespace

compare::Suite suite_from_study(const Grid& grid, const std::string& suite_name) {
    const StudySpec& spec = grid.spec();
    const auto fail = [&](const PartSpec& part, const std::string& why) {
        return InputError(fmt::format("suite file {}: {}: {}", spec.path, part.where.empty() ? "the study" : part.where, why));
    };
    compare::Suite suite;
    suite.name = suite_name;
    std::map<std::string, std::string> wall_scenes;  // id -> scene_key
    const auto add_wall = [&](const PartSpec& part, const CaseSpec& c) {
        const std::string id = grid.wall_name(c);
        const std::string key = scene_key(c.scene);
        const auto it = wall_scenes.find(id);
        if (it != wall_scenes.end()) {
            if (it->second != key) throw fail(part, fmt::format("the wall name '{}' is given to two different walls", id));
            return id;
        }
        wall_scenes.emplace(id, key);
        const std::string label = grid.wall_label(c);
        suite.walls.push_back({id, label.empty() ? id : label, c.scene});
        return id;
    };
    std::set<std::string> ids;
    const auto add_case = [&](const PartSpec& part, compare::SuiteCase sc) {
        if (!ids.insert(sc.id).second) throw fail(part, fmt::format("the case id '{}' comes twice", sc.id));
        suite.cases.push_back(std::move(sc));
    };

    for (std::size_t pi = 0; pi < spec.parts.size(); ++pi) {
        const PartSpec& part = spec.parts[pi];
        if (part.names.wall_name.empty()) throw fail(part, "a suite's part names its walls (wall_name)");
        std::vector<CaseSpec> cases;
        for (const int id : grid.case_ids()) {
            CaseSpec c = grid.make_case(id);
            if (c.part == pi) cases.push_back(std::move(c));
        }
        // Engines whose step varies in this part: a step study.
        std::vector<std::string> stepped;
        for (const EngineSpec& e : part.engines)
            for (const Axis& a : e.settings)
                if (a.key == "dt" && a.varied()) stepped.push_back(e.name);
        switch (part.kind) {
            case ExcitationKind::threshold:
                for (const CaseSpec& c : cases) {
                    const std::string w = add_wall(part, c);
                    add_case(part, {w, compare::CaseKind::threshold, w, 0.0, "", {}, ""});
                }
                break;
            case ExcitationKind::free:
                if (stepped.empty()) {
                    for (const CaseSpec& c : cases) {
                        const std::string w = add_wall(part, c);
                        add_case(part, {fmt::format("{}/r{}", w, fmt_number(c.theta0)), compare::CaseKind::free, w,
                                        c.theta0, "", {}, ""});
                    }
                    break;
                }
                for (const std::string& engine : stepped)
                    for (const CaseSpec& c : cases) {
                        const std::string w = add_wall(part, c);
                        for (const RunSpec& run : grid.runs()) {
                            if (run.part != pi || run.engine != engine) continue;
                            const double dt = run.settings.dt;
                            add_case(part, {fmt::format("{}/r{}/dt{}/{}", w, fmt_number(c.theta0), fmt_number(dt), engine),
                                            compare::CaseKind::step, w, c.theta0, "", dt, engine});
                            std::vector<double>& dts = suite.step_study[engine];
                            if (std::find(dts.begin(), dts.end(), dt) == dts.end()) dts.push_back(dt);
                        }
                    }
                break;
            case ExcitationKind::record:
                if (part.names.record_name.empty()) throw fail(part, "a suite's record part names its records (record_name)");
                // The report reads a suite's records in the units their files say (compare/suite.cpp): refuse others.
                if (part.excitation_axis("units"))
                    throw fail(part, "a suite's records are read in the units their files give: no 'units'");
                for (const CaseSpec& c : cases) {
                    const std::string w = add_wall(part, c);
                    const std::string r = grid.record_name(c);
                    const auto same = std::find_if(suite.records.begin(), suite.records.end(),
                                                   [&](const compare::SuiteRecord& x) { return x.id == r; });
                    if (same != suite.records.end() &&
                        (same->path != grid.record_path(c.file) || same->scale != c.scale))
                        throw fail(part, fmt::format("the record name '{}' is given to two different records", r));
                    if (same == suite.records.end()) {
                        const std::string label = grid.record_label(c);
                        suite.records.push_back({r, label.empty() ? r : label, grid.record_path(c.file), c.scale});
                    }
                    add_case(part, {fmt::format("{}/{}", w, r), compare::CaseKind::history, w, 0.0, r, {}, ""});
                }
                break;
            default:
                throw fail(part, fmt::format("a suite runs thresholds, free vibrations, step studies and records, not "
                                             "kind {}",
                                             to_string(part.kind)));
        }
    }
    return suite;
}

std::string suite_file(const std::string& name_or_path) {
    if (name_or_path == "default" || name_or_path == "full")
        return shipped_studies_dir() + "/validation-" + name_or_path + ".toml";
    return name_or_path;
}

compare::Suite read_suite(const std::string& name_or_path, const std::string& data_dir) {
    const std::string file = suite_file(name_or_path);
    std::error_code ec;
    if (file == name_or_path && !std::filesystem::is_regular_file(file, ec))
        throw InputError(fmt::format("unknown suite '{}' (valid: default, full, or a suite file)", name_or_path));
    const Grid grid(read_study_file(file));
    const bool shipped = file != name_or_path;
    compare::Suite suite = suite_from_study(grid, shipped ? name_or_path : grid.spec().name);
    if (!data_dir.empty())
        for (compare::SuiteRecord& r : suite.records)
            r.path = data_dir + "/" + std::filesystem::path(r.path).filename().string();
    return suite;
}

}  // namespace vssw::study
