#include "study/grid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <limits>
#include <memory>

#include <fmt/format.h>

#include "analytic/closed_forms.hpp"
#include "analytic/diaphragm.hpp"
#include "analytic/error.hpp"
#include "analytic/input_file.hpp"
#include "analytic/specimens.hpp"
#include "analytic/wall.hpp"
#include "io/fnv1a.hpp"
#include "io/json.hpp"
#include "study/name_bounds.hpp"
#include "multibody/host/analytic_engine.hpp"
#include "multibody/engine.hpp"
#include "multibody/kit/scene_geometry.hpp"

namespace vssw::study {

// What column_values writes in a column, by the column's name (column_code); other: the level the file gives, if any.
enum class ColumnCode : int {
    model, height, thickness, hinge, xi, density, g, kinematics, impact, roller, kind, theta0, file, scale, pga,
    level_key, intensity, intensity_unit, shape, amplitude, pulse_period, alpha, R, alpha1, alpha2, R1, settings,
    wall_name, record_name, other
};

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr const char* kWhat = "study file";

// Columns of results.csv between `engine` and `metric`: always these (the documented names, docs/guide/studies.md, so
// that scripts can rely on them), then alpha and R (every wall's, for rocking curves), then the keys the file uses
// beyond them, then settings.
const std::vector<std::string> kBaseColumns = {"model", "height",    "thickness", "hinge",  "xi",    "density",
                                               "g",     "kinematics", "impact",   "roller", "kind",  "theta0",
                                               "file",  "scale",     "pga",       "shape",  "amplitude",
                                               "pulse_period", "alpha", "R"};
const std::vector<std::string> kExtraColumns = {"alpha1", "alpha2", "R1", "specimen", "overburden_eccentricity",
                                                "friction", "hinge_friction", "units", "duration", "tolerance", "max_pga",
                                                "step", "perturbation", "pgv", "sa", "arias", "sa_period", "sa_damping",
                                                "response_tail", "corner_radius", "diaphragm_period",
                                                "diaphragm_damping"};
// After them, when a part scales its records to another measure than the PGA or reports its collapse in one: the
// measure's word ("pgv") and its unit ("m/s"), per case (intensity_of).
const std::vector<std::string> kIntensityColumns = {"intensity", "intensity_unit"};

ColumnCode column_code(const std::string& col) {
    static const std::map<std::string, ColumnCode> codes = {
        {"model", ColumnCode::model}, {"height", ColumnCode::height}, {"thickness", ColumnCode::thickness},
        {"hinge", ColumnCode::hinge}, {"xi", ColumnCode::xi}, {"density", ColumnCode::density},
        {"g", ColumnCode::g}, {"kinematics", ColumnCode::kinematics}, {"impact", ColumnCode::impact},
        {"roller", ColumnCode::roller}, {"kind", ColumnCode::kind}, {"theta0", ColumnCode::theta0},
        {"file", ColumnCode::file}, {"scale", ColumnCode::scale}, {"pga", ColumnCode::pga},
        {"intensity", ColumnCode::intensity}, {"intensity_unit", ColumnCode::intensity_unit},
        {"shape", ColumnCode::shape}, {"amplitude", ColumnCode::amplitude},
        {"pulse_period", ColumnCode::pulse_period}, {"alpha", ColumnCode::alpha}, {"R", ColumnCode::R},
        {"alpha1", ColumnCode::alpha1}, {"alpha2", ColumnCode::alpha2}, {"R1", ColumnCode::R1},
        {"settings", ColumnCode::settings}, {"wall_name", ColumnCode::wall_name},
        {"record_name", ColumnCode::record_name}};
    if (const auto it = codes.find(col); it != codes.end()) return it->second;
    const bool level_key = std::find(kLevelKeys.begin(), kLevelKeys.end(), col) != kLevelKeys.end();
    return level_key ? ColumnCode::level_key : ColumnCode::other;
}
// Then wall_name and record_name when a part names its walls or records, then settings.

std::string number(double x) { return std::isfinite(x) ? fmt::format("{}", x) : std::string(); }

double as_number(const Level& l) { return std::get<double>(l); }
const std::string& as_word(const Level& l) { return std::get<std::string>(l); }

// The levels of one case: digit i of `position` in the mixed radix of the axes' sizes, the last axis fastest.
std::vector<std::size_t> digits(std::size_t position, const std::vector<const Axis*>& axes) {
    std::vector<std::size_t> d(axes.size());
    for (std::size_t i = axes.size(); i-- > 0;) {
        d[i] = position % axes[i]->levels.size();
        position /= axes[i]->levels.size();
    }
    return d;
}

// The combination after `d` (levels, the last axis fastest) that leaves the first level in at most one of the axes
// varied alone: false after the last. Only these are visited: a product of 6 keys of 25 levels is 2.4e8 combinations
// for 145 cases.
bool next_combination(std::vector<std::size_t>& d, const std::vector<const Axis*>& axes,
                      const std::vector<bool>& alone) {
    for (std::size_t i = d.size(); i-- > 0;) {
        // Axis i steps up (those after it back to their first level) unless it is varied alone and one before it has
        // left its first level already: then every later combination of this prefix leaves two.
        bool two = false;
        for (std::size_t j = 0; j < i && alone[i]; ++j) two = two || (alone[j] && d[j] != 0);
        if (!two && d[i] + 1 < axes[i]->levels.size()) {
            ++d[i];
            return true;
        }
        d[i] = 0;
    }
    return false;
}

// The product of the axes' levels, each combination once (the last axis fastest).
std::vector<std::vector<Level>> combinations(const std::vector<Axis>& axes) {
    std::vector<std::vector<Level>> out = {{}};
    for (const Axis& a : axes) {
        std::vector<std::vector<Level>> next;
        for (const auto& prefix : out)
            for (const Level& l : a.levels) {
                next.push_back(prefix);
                next.back().push_back(l);
            }
        out = std::move(next);
    }
    return out;
}

std::string settings_text(const std::vector<Axis>& axes, const std::vector<Level>& levels) {
    std::string text;
    for (std::size_t i = 0; i < axes.size(); ++i)
        text += fmt::format("{}{}={}", text.empty() ? "" : " ", axes[i].key, to_text(levels[i]));
    return text;
}

// The key of a record read with given units ("" for the file's own): one file may be read in two parts' units.
std::string record_key(const std::string& file, const std::string& units) { return file + "\n" + units; }

bool perturbed(const CaseSpec& c) { return !c.perturbation.empty() && c.perturbation != "none"; }

// The intensity measure a part scales its records to or reports its collapse in, when it is not the PGA alone: the
// ensemble's `intensity`, or a record part's level key; "" otherwise.
std::string intensity_of(const PartSpec& part) {
    if (part.ensemble) return part.ensemble->intensity == "pga" ? "" : part.ensemble->intensity;
    for (const std::string& k : kLevelKeys)
        if (k != "pga" && part.excitation_axis(k)) return k;
    return "";
}

// A file read already (a record, Table 1), again for its bytes: still a regular file, however it changed meanwhile.
std::string read_bytes(const std::string& path) { return read_input_file(path, "the file", kMaxTextFileBytes); }

// Whether the analytic model (exact kinematics) released from rest at theta0 alpha falls rather than rocks: a heavy
// overburden with a high hinge puts the unstable equilibrium below 0.8 alpha1 (Table 1 #1, #10, #11 at xi 0.5), and
// a wall that falls has no period or restitution to compare (a suite's free cases leave such releases out).
bool falls_from(const multibody::WallScene& scene, double theta0) {
    SimulationOptions options;
    options.keep_samples = false;
    return free_vibration(*analytic_model(scene, Kinematics::exact), theta0 * scene.alpha(), options)
        .overturned;
}

}  // namespace

Grid::Grid(const StudySpec& spec) : spec_(spec) {
    std::string identity_text = io::dump_json(spec.as_read);
    // The assumptions as resolved, not only as written: a file without them runs the default set, which a build may
    // change, and a journal or a shard of the old default must not join the new one's.
    for (const Axis& a : spec.assumptions)
        for (const Level& l : a.levels) identity_text += "\n" + a.key + "=" + to_text(l);
    read_specimens(identity_text);
    size_parts();
    read_records(identity_text);
    build_runs();
    identity_ = io::fnv1a_hex(identity_text);
    list_cases();
    list_columns();
}

Grid::Grid(StudySpec spec, const CaseSpec& one, std::vector<RunSpec> runs, const GroundMotion& record)
    : spec_(std::move(spec)), product_size_(1), case_ids_{1}, runs_(std::move(runs)), one_case_(one) {
    parts_.emplace_back();
    if (!one.record_key.empty()) records_.emplace(one.record_key, record);
    one_case_->id = 1;
    one_case_->part = 0;
}

std::string Grid::where(const PartSpec& part, const std::string& key) const {
    return fmt::format("{} {}: {}{}", kWhat, spec_.path, part.where.empty() ? "" : part.where + ".", key);
}

void Grid::read_specimens(std::string& identity_text) {
    for (const PartSpec& part : spec_.parts)
        if (part.wall_axis("specimen") && table1_.empty()) {
            try {
                table1_ = read_table1(default_table1_path());
            } catch (const InputError& e) {
                throw InputError(fmt::format("{}: {}", where(part, "wall.specimen"), e.what()));
            }
            identity_text += "\n" + read_bytes(default_table1_path());
        }
}

// The grid's size first, before anything is read or built. Case ids are ints: a larger grid is a typo, not a study
// (vssw study's --force bound is far below). Each product is checked before it is formed: unchecked, six lists whose
// product is 2^64 + 418 wrapped to a grid of 418 cases that ran under --force. A part with keys varied one at a time
// whose product is beyond ints, but not its cases, numbers its cases (grid.hpp).
void Grid::size_parts() {
    constexpr std::size_t kMaxCases = static_cast<std::size_t>(std::numeric_limits<int>::max());
    product_size_ = 0;
    for (const PartSpec& part : spec_.parts) {
        PartGrid g;
        g.axes = part.axes();
        g.one_at_a_time = part.one_at_a_time;
        for (const Axis* a : g.axes)
            g.alone.push_back(std::find(g.one_at_a_time.begin(), g.one_at_a_time.end(), a->key) !=
                              g.one_at_a_time.end());
        const std::size_t room = kMaxCases - product_size_;
        const double cases = case_count(g.axes, g.one_at_a_time);
        if (!(cases <= static_cast<double>(room)))
            throw InputError(fmt::format("{} {}: a grid of more than {} cases (case ids are ints), even with --force",
                                         kWhat, spec_.path, kMaxCases));
        bool fits = true;
        for (const Axis* a : g.axes) {
            fits = fits && a->levels.size() <= room / g.size;
            if (fits) g.size *= a->levels.size();
        }
        g.numbered = !fits || g.size > room;
        if (g.numbered) g.size = static_cast<std::size_t>(cases);
        g.first = product_size_ + 1;
        product_size_ += g.size;
        parts_.push_back(std::move(g));
    }
}

// Records: read once, up front, so that a missing or malformed file is refused before anything runs.
void Grid::read_records(std::string& identity_text) {
    for (const PartSpec& part : spec_.parts) {
        const Axis* files = part.excitation_axis("file");
        if (!files) continue;
        std::optional<AccelUnits> units;
        if (const Axis* u = part.excitation_axis("units")) {
            if (u->varied()) throw InputError(where(part, "excitation.units: one unit for the part's records"));
            units = parse_units(as_word(u->levels.front()));
        }
        const std::string units_text = units ? as_word(part.excitation_axis("units")->levels.front()) : "";
        for (const Level& f : files->levels) {
            const std::string key = record_key(as_word(f), units_text);
            if (records_.count(key)) continue;
            try {
                GroundMotion r = read_record(record_path(as_word(f)), units ? &*units : nullptr);
                require_shakes(r, as_word(f));
                records_.emplace(key, std::move(r));
            } catch (const InputError& e) {
                throw InputError(fmt::format("{}: {}", where(part, "excitation.file"), e.what()));
            }
            // The record's bytes go into the study's identity: shards and a resume must have read the same record.
            identity_text += "\n" + read_bytes(record_path(as_word(f)));
        }
    }
}

// Where the study's roller comes from when the file does not give it: the set's (only the set mechanism's is
// unilateral), named in the reason a run of the paper's kinematics with it is left out. "" when the file gives it.
std::string Grid::roller_source() const {
    const std::vector<std::string>& given = spec_.assumptions_given;
    if (std::find(given.begin(), given.end(), "roller") != given.end()) return "";
    return fmt::format("the set {}'s roller: give roller = \"bilateral\" with kinematics = \"paper\", or set = "
                       "\"paper\"",
                       to_string(spec_.assumption_set));
}

// Runs, per part: the analytic model under each combination of assumptions and settings, each engine under each of
// its settings' combinations (a closed-form part runs the analytic model only).
void Grid::build_runs() {
    for (std::size_t pi = 0; pi < spec_.parts.size(); ++pi) {
        const PartSpec& part = spec_.parts[pi];
        for (const EngineSpec& e : part.engines) {
            if (part.kind == ExcitationKind::closed_form && e.name != "analytic") continue;
            const std::unique_ptr<multibody::Engine> engine = multibody::make_engine(e.name);
            const std::vector<std::vector<Level>> assumption_sets =
                e.name == "analytic" ? combinations(spec_.assumptions) : std::vector<std::vector<Level>>{{}};
            for (const std::vector<Level>& settings : combinations(e.settings))
                for (const std::vector<Level>& assumptions : assumption_sets) {
                    RunSpec run;
                    run.part = pi;
                    run.engine = e.name;
                    run.settings = engine->default_settings();
                    run.settings_text = settings_text(e.settings, settings);
                    for (std::size_t i = 0; i < e.settings.size(); ++i)
                        run.settings.set(e.settings[i].key, as_number(settings[i]));
                    run.assumptions = assumptions;
                    if (e.name == "analytic" &&
                        !apply_assumptions(run, assumptions_of(assumptions), skipped_runs_, roller_source()))
                        continue;
                    try {
                        engine->check_settings(run.settings);
                    } catch (const InputError& err) {
                        const std::string settings_key =
                            "settings of " + e.name + (run.settings_text.empty() ? "" : " (" + run.settings_text + ")");
                        throw InputError(fmt::format("{}: {}", where(part, settings_key), err.what()));
                    }
                    runs_.push_back(std::move(run));
                }
        }
    }
    for (const PartSpec& part : spec_.parts)
        if (part.excitation_axis("perturbation") &&
            std::any_of(part.engines.begin(), part.engines.end(), [](const EngineSpec& e) { return e.name != "analytic"; }))
            skipped_runs_.push_back(fmt::format(
                "the sensitivity band's perturbed cases (PGA x (1 +- {:g}), restitution x (1 +- {:g}), the wall's size "
                "x (1 +- {:g})): the analytic model's only; engines run each case unperturbed",
                kBandIntensityStep, kBandRestitutionStep, kBandSizeStep));
    std::sort(skipped_runs_.begin(), skipped_runs_.end());
    skipped_runs_.erase(std::unique(skipped_runs_.begin(), skipped_runs_.end()), skipped_runs_.end());
    if (runs_.empty())
        throw InputError(fmt::format("{} {}: no run left: {}", kWhat, spec_.path, fmt::join(skipped_runs_, "; ")));
}

// Cases: every combination of every part, each built (a wall out of range is refused here, naming the case), the
// repeats of a parapet's hinge, the combinations off the first level of two one_at_a_time keys and (where a part asks)
// the releases from which the analytic model falls left out.
void Grid::list_cases() {
    for (std::size_t pi = 0; pi < parts_.size(); ++pi) {
        const PartSpec& part = spec_.parts[pi];
        const auto axis_index = [&](const std::string& key) -> std::optional<std::size_t> {
            for (std::size_t i = 0; i < parts_[pi].axes.size(); ++i)
                if (parts_[pi].axes[i]->key == key) return i;
            return std::nullopt;
        };
        const std::optional<std::size_t> hinge = axis_index("hinge"), duration = axis_index("duration");
        // A parapet has neither kinematics nor roller: its analytic run is the part's first analytic run built.
        for (const RunSpec& r : runs_)
            if (r.part == pi && r.engine == "analytic") {
                parapet_run_.emplace(pi, std::make_pair(r.assumptions[0], r.assumptions[2]));
                break;
            }
        const PartGrid& g = parts_[pi];
        // Only the combinations asked for are visited (a combination no one asked for may be no wall at all).
        std::vector<std::size_t> d(g.axes.size(), 0);
        std::size_t n = 0;  // the combination's place among those visited
        for (bool more = true; more; more = next_combination(d, g.axes, g.alone), ++n) {
            std::size_t position = 0;
            for (std::size_t i = 0; i < d.size(); ++i) position = position * g.axes[i]->levels.size() + d[i];
            const CaseSpec c = make_case(static_cast<int>(g.first + (g.numbered ? n : position)));
            if (c.model == "parapet" && hinge && d[*hinge] != 0) continue;
            if (duration && c.shape != "harmonic" && d[*duration] != 0) continue;  // only a harmonic lasts `duration`
            if (part.skip_falling_releases && falls_from(c.scene, c.theta0)) continue;
            // Names are rendered now, so that a template that cannot format fails before anything runs.
            for (const auto& name : {wall_name(c), wall_label(c), record_name(c), record_label(c)}) (void)name;
            case_ids_.push_back(c.id);
        }
    }
}

void Grid::list_columns() {
    columns_ = kBaseColumns;
    const auto used = [&](const std::string& k) {
        for (const PartSpec& part : spec_.parts)
            if (part.wall_axis(k) || part.excitation_axis(k)) return true;
        return false;
    };
    for (const std::string& k : kExtraColumns)
        if (used(k)) columns_.push_back(k);
    if (std::any_of(spec_.parts.begin(), spec_.parts.end(), [](const PartSpec& p) { return !intensity_of(p).empty(); }))
        columns_.insert(columns_.end(), kIntensityColumns.begin(), kIntensityColumns.end());
    const auto named = [&](std::string NameTemplates::*field) {
        return std::any_of(spec_.parts.begin(), spec_.parts.end(),
                           [&](const PartSpec& p) { return !(p.names.*field).empty(); });
    };
    if (named(&NameTemplates::wall_name)) columns_.push_back("wall_name");
    if (named(&NameTemplates::record_name)) columns_.push_back("record_name");
    columns_.push_back("settings");
    // What each column holds and which axis of each part gives it, once: column_values writes every row's.
    for (const std::string& col : columns_) column_codes_.push_back(column_code(col));
    for (PartGrid& g : parts_)
        for (const std::string& col : columns_) {
            int axis = -1;
            for (std::size_t i = 0; i < g.axes.size() && axis < 0; ++i)
                if (g.axes[i]->key == col) axis = static_cast<int>(i);
            g.column_axis.push_back(axis);
        }
}

const Grid::PartGrid& Grid::part_of(int id, std::size_t& index) const {
    for (index = 0; index < parts_.size(); ++index)
        if (static_cast<std::size_t>(id) < parts_[index].first + parts_[index].size) return parts_[index];
    throw InputError(fmt::format("study {}: no case {} (1 to {})", spec_.name, id, product_size_));
}

// A case's levels by key, and how messages name them ("height 4, hinge 0.7").
struct Grid::CaseLevels {
    // The part's axes in order, each with the case's level: pointers into the study's axes, looked up by a key's
    // literal with no string, node or level copied (a part has a few axes: a scan costs less than a map's nodes).
    std::vector<std::pair<const std::string*, const Level*>> in_order;

    // Made only for a message: formatting it for every case cost more than building the case's wall.
    std::string described() const {
        std::string text;
        for (const auto& [key, value] : in_order)
            text += fmt::format("{}{} {}", text.empty() ? "" : ", ", *key, to_text(*value));
        return text;
    }

    // The level of key `k`, nullptr when no axis gives it (the last axis that gives it, as a map assigned in order).
    // A view: the literal's length is known where it is written, and unequal lengths compare at once.
    const Level* find(std::string_view k) const {
        for (auto it = in_order.rbegin(); it != in_order.rend(); ++it)
            if (*it->first == k) return it->second;
        return nullptr;
    }
    const Level& at(std::string_view k) const {
        const Level* l = find(k);
        if (l == nullptr) throw std::out_of_range("no level of " + std::string(k));
        return *l;
    }
    bool has(std::string_view k) const { return find(k) != nullptr; }
    double num(std::string_view k, double fallback) const {
        const Level* l = find(k);
        return l == nullptr ? fallback : as_number(*l);
    }
    const std::string& word(std::string_view k) const { return as_word(at(k)); }
};

CaseSpec Grid::make_case(int id) const {
    if (id < 1 || static_cast<std::size_t>(id) > product_size_)
        throw InputError(fmt::format("study {}: no case {} (1 to {})", spec_.name, id, product_size_));
    if (one_case_) return *one_case_;
    CaseSpec c;
    c.id = id;
    const CaseLevels l = case_levels(c);
    const PartSpec& part = spec_.parts[c.part];
    const auto refused = [&](const std::string& why) {
        return InputError(fmt::format("{} {}: {}case {} ({}): {}", kWhat, spec_.path,
                                      part.where.empty() ? "" : part.where + ", ", id, l.described(), why));
    };
    try {
        build_wall(c, l);
    } catch (const InputError& e) {
        throw refused(e.what());
    }
    describe_wall(c);
    c.theta0 = l.num("theta0", 0.0);
    if (c.theta0 > 0.0) {
        const double collapse = multibody::collapse_angle(c.scene);
        if (!(c.theta0 * c.scene.alpha() < collapse))
            throw refused(fmt::format("theta0 {} alpha is at or beyond the wall's collapse angle ({:.4g} alpha)",
                                      c.theta0, collapse / c.scene.alpha()));
    }
    try {
        set_excitation(c, l);
    } catch (const InputError& e) {
        throw refused(e.what());
    }
    // The band's wall of another size, the same shape: built after the wall's columns were described, which stay the
    // nominal wall's (the perturbed run is a repeat of the nominal case).
    if (const double f = band_factors(c.perturbation).size; f != 1.0) {
        if (c.model == "parapet")
            c.scene = multibody::WallScene::of(make_parapet(c.height * f, c.thickness * f, c.xi, c.density, c.g));
        else
            c.scene = multibody::WallScene::of(make_vssw(c.height * f, c.thickness * f, c.hinge, c.xi, c.density, c.g));
    }
    if (part.kind == ExcitationKind::scale_to_collapse && c.max_pga_g > 0.0) {
        // The search steps up from lift-off: a max_pga at or below the wall's rest threshold leaves nothing to search.
        const double threshold_g = analytic_model(c.scene, Kinematics::exact)->rest_threshold(0.0) / kStandardGravity;
        if (!(c.max_pga_g > threshold_g))
            throw refused(fmt::format("max_pga {:g} g is not above the wall's rest threshold, {:.4g} g: no scale up to "
                                      "it can lift the wall, let alone overturn it",
                                      c.max_pga_g, threshold_g));
    }
    if (part.kind == ExcitationKind::pulse) {
        // Built here, as every case is built before anything runs: a pulse the library refuses (a harmonic of more
        // than 1e6 cycles, as `vssw history` refuses it) is bad input, not a study whose every row fails.
        try {
            (void)pulse_motion(c);
        } catch (const InputError& e) {
            throw refused(e.what());
        }
    }
    return c;
}

// A position in the product: digit i in the mixed radix of the axes' sizes. A numbered part's n-th case: each axis in
// turn takes the level whose combinations after it (counted as case_count counts them) hold the n-th.
std::vector<std::size_t> Grid::levels_at(const PartGrid& g, std::size_t index) const {
    if (!g.numbered) return digits(index, g.axes);
    std::vector<std::size_t> d(g.axes.size(), 0);
    double n = static_cast<double>(index);
    bool left = false;  // a key varied alone has left its first level
    for (std::size_t i = 0; i < g.axes.size(); ++i)
        for (std::size_t l = 0; l < g.axes[i]->levels.size(); ++l) {
            const bool leaves = g.alone[i] && l != 0;
            if (leaves && left) break;
            const double after = case_count(g.axes, g.one_at_a_time, i + 1, left || leaves);
            if (n < after) {
                d[i] = l;
                left = left || leaves;
                break;
            }
            n -= after;
        }
    return d;
}

// The case's part, its levels (levels_at) and its wall's position: in the product of the wall axes, or (a numbered
// part, whose wall axes' product may be beyond any integer) among the walls its one-at-a-time keys give, in order.
// Cases that differ only in their excitation share it.
Grid::CaseLevels Grid::case_levels(CaseSpec& c) const {
    const PartGrid& g = part_of(c.id, c.part);
    const PartSpec& part = spec_.parts[c.part];
    const std::vector<const Axis*>& axes = g.axes;
    const std::vector<std::size_t> d = levels_at(g, static_cast<std::size_t>(c.id) - g.first);
    CaseLevels l;
    for (std::size_t i = 0; i < axes.size(); ++i) {
        c.levels.push_back(axes[i]->levels[d[i]]);
        l.in_order.emplace_back(&axes[i]->key, &axes[i]->levels[d[i]]);
    }
    std::size_t wall_index = 0;
    const std::vector<const Axis*> walls(axes.begin(), axes.begin() + static_cast<std::ptrdiff_t>(part.wall.size()));
    bool left = false;  // a key varied alone has left its first level
    for (std::size_t i = 0; i < walls.size(); ++i) {
        if (!g.numbered) {
            wall_index = wall_index * walls[i]->levels.size() + d[i];
            continue;
        }
        for (std::size_t lv = 0; lv < d[i]; ++lv) {
            const bool leaves = left || (g.alone[i] && lv != 0);
            wall_index += static_cast<std::size_t>(case_count(walls, g.one_at_a_time, i + 1, leaves));
        }
        left = left || (g.alone[i] && d[i] != 0);
    }
    c.wall_index = wall_index;
    return l;
}

// The wall from the levels: its geometry given one way (height and thickness, a specimen, alpha and R, or alpha1,
// alpha2 and R1), its hinge the number given, Eq. 15's at the case's xi, or the specimen's.
void Grid::build_wall(CaseSpec& c, const CaseLevels& l) const {
    c.model = l.has("model") ? l.word("model") : "vssw";
    c.xi = l.num("xi", 0.0);
    c.density = l.num("density", kDefaultDensity);
    c.g = l.num("g", kDefaultGravity);
    double height = 0.0, thickness = 0.0;
    std::optional<double> hinge;
    if (l.has("hinge")) {
        const Level& h = l.at("hinge");
        // Eq. (15), (15e) with N off-centre, (15r) with rounded corners as well (analytic/closed_forms.hpp).
        const double eccentricity = l.num("overburden_eccentricity", 0.0), corners = l.num("corner_radius", 0.0);
        hinge = std::holds_alternative<double>(h) ? as_number(h)
                                                  : eq15_optimal_hinge_ratio(c.xi, eccentricity, corners);
    }
    if (l.has("height")) {
        height = l.num("height", 0.0);
        thickness = l.num("thickness", 0.0);
    } else if (l.has("specimen")) {
        // Table 1 (data/table1.csv): its height and thickness, and its hinge unless the file gives one.
        const Specimen& s = table1_specimen(table1_, static_cast<int>(l.num("specimen", 0.0)));
        height = s.height;
        thickness = s.thickness;
        if (!hinge) hinge = s.hinge_ratio;
    } else if (l.has("alpha")) {
        // The whole wall's slenderness and half-diagonal: b = R sin(alpha), h = R cos(alpha).
        height = 2.0 * l.num("R", 0.0) * std::cos(l.num("alpha", 0.0));
        thickness = 2.0 * l.num("R", 0.0) * std::sin(l.num("alpha", 0.0));
    }
    const double eccentricity = l.num("overburden_eccentricity", 0.0);  // N's e/b (analytic/geometry.hpp)
    const double corners = l.num("corner_radius", 0.0);  // r/b of the rounded corners (analytic/wall.hpp)
    if (c.model == "parapet") {
        c.scene = multibody::WallScene::of(with_corner_radius(
            with_eccentricity(make_parapet(height, thickness, c.xi, c.density, c.g), eccentricity), corners));
    } else if (l.has("alpha1")) {
        c.scene = multibody::WallScene::of(with_corner_radius(
            with_eccentricity(make_vssw_from_angles(l.num("alpha1", 0.0), l.num("alpha2", 0.0), l.num("R1", 0.0),
                                                    c.xi, c.density, c.g),
                              eccentricity),
            corners));
    } else {
        if (!hinge) throw InputError("a VSSW needs a hinge ratio");
        c.scene = multibody::WallScene::of(with_corner_radius(
            with_eccentricity(make_vssw(height, thickness, *hinge, c.xi, c.density, c.g), eccentricity), corners));
    }
    // The contacts' friction, a property of the wall's joints that every engine of the case shares (and the analytic
    // model compares with what it needs): given, sliding is measured rather than a failure (multibody/engine.hpp).
    if (l.has("friction") || l.has("hinge_friction")) {
        c.scene.slip_measured = true;
        if (l.has("friction")) c.scene.friction = l.num("friction", 0.0);
        if (l.has("hinge_friction")) c.scene.hinge_friction = l.num("hinge_friction", 0.0);
    }
    // The VSSW's top support (analytic/diaphragm.hpp): rigid unless the file gives a period; a parapet has none.
    c.scene.diaphragm = {l.num("diaphragm_period", 0.0), l.num("diaphragm_damping", kDefaultDiaphragmDamping)};
    if (c.model == "parapet" && !c.scene.diaphragm.is_rigid())
        throw InputError(fmt::format("diaphragm_period = {:g} s: a parapet has no top support for a diaphragm to carry",
                                     c.scene.diaphragm.period));
}

// The record (scaled by the factor given or to the PGA given) or the pulse, and scale-to-collapse's search bounds.
void Grid::set_excitation(CaseSpec& c, const CaseLevels& l) const {
    const PartSpec& part = spec_.parts[c.part];
    if (l.has("perturbation")) c.perturbation = l.word("perturbation");
    if (l.has("file")) {
        c.file = l.word("file");
        c.record_key = record_key(c.file, part.excitation_axis("units")
                                              ? as_word(part.excitation_axis("units")->levels.front())
                                              : "");
        // The level of the measure the record is scaled to (a part gives at most one of kLevelKeys), and Sa's oscillator.
        std::optional<double> level;
        for (const std::string& k : kLevelKeys)
            if (l.has(k.c_str())) {
                level = l.num(k.c_str(), 0.0);
                c.intensity.measure = parse_intensity_measure(k);
            }
        c.intensity.sa_period = l.num("sa_period", 0.0);
        c.intensity.sa_damping = l.num("sa_damping", kDefaultSaDamping);
        // The band (an ensemble's stripes, so a level is given): the level nudged (the other factors: make_case, and
        // the restitution's in the run, study/measure.cpp).
        if (level) *level *= band_factors(c.perturbation).intensity;
        const GroundMotion& motion = record(c);
        if (c.intensity.measure == IntensityMeasure::pga) {
            scale_record(c, motion, level, l.num("scale", 1.0));
        } else {
            const double at_one = record_intensity(motion, c.intensity);
            if (!(at_one > 0.0)) throw InputError(fmt::format("'{}' has no {} to scale", c.file, to_string(c.intensity.measure)));
            scale_record(c, motion, std::nullopt, scale_to_intensity(c.intensity.measure, at_one, *level));
            c.intensity_value = intensity_at_scale(c.intensity.measure, at_one, c.scale);
        }
    }
    if (l.has("shape")) c.shape = l.word("shape");
    c.amplitude_g = l.num("amplitude", 0.0);
    c.pulse_period = l.num("pulse_period", 0.0);
    c.duration = l.num("duration", 0.0);
    c.tolerance = l.num("tolerance", 0.0);
    c.max_pga_g = l.num("max_pga", 0.0);
    c.step = l.num("step", 0.0);
    c.response_tail = l.num("response_tail", compare::kResponseTail);
}

void describe_wall(CaseSpec& c) {
    if (c.scene.vssw) {
        const VsswGeometry& w = *c.scene.vssw;
        c.model = "vssw";
        c.height = 2.0 * w.h();
        c.thickness = 2.0 * w.b;
        c.hinge = w.hinge_ratio();
        c.xi = w.xi;
        c.density = w.density;
        c.g = w.g;
        c.alpha = std::atan(w.b / w.h());
        c.R = std::hypot(w.b, w.h());
    } else {
        const ParapetGeometry& p = *c.scene.parapet;
        c.model = "parapet";
        c.height = 2.0 * p.h;
        c.thickness = 2.0 * p.b;
        c.hinge = kNaN;
        c.xi = p.xi;
        c.density = p.density;
        c.g = p.g;
        c.alpha = p.alpha;
        c.R = p.R;
    }
}

void scale_record(CaseSpec& c, const GroundMotion& record, std::optional<double> pga_g, double scale) {
    c.scale = pga_g ? *pga_g * kStandardGravity / record.pga() : scale;
    c.pga_g = c.scale * record.pga() / kStandardGravity;
    // The record's largest sample times the factor: finite exactly when every scaled sample is (GroundMotion::scaled,
    // which `vssw history --pga` and `--scale` call before anything runs).
    if (!std::isfinite(c.scale) || !std::isfinite(c.scale * record.pga()))
        throw InputError(fmt::format("{} {:g}: scaling the record '{}' (PGA {:.4g} g) to it overflows a double",
                                     pga_g ? "pga" : "scale", pga_g ? *pga_g : scale, c.file,
                                     record.pga() / kStandardGravity));
}

void require_shakes(const GroundMotion& record, const std::string& file) {
    // A record that is zero everywhere cannot be scaled to a PGA, nor shake anything.
    if (!(record.pga() > 0.0)) throw InputError(fmt::format("'{}' is zero everywhere", file));
}

multibody::AnalyticAssumptions assumptions_of(const std::vector<Level>& levels) {
    multibody::AnalyticAssumptions a;
    a.kinematics = parse_kinematics(as_word(levels[0]));
    a.impact = std::holds_alternative<double>(levels[1]) ? ImpactLaw{ImpactLaw::Kind::ratio, as_number(levels[1])}
                                                         : parse_impact_law(as_word(levels[1]));
    a.roller = parse_roller(as_word(levels[2]));
    return a;
}

std::vector<Level> assumption_levels(const multibody::AnalyticAssumptions& a) {
    const Level impact =
        a.impact.kind == ImpactLaw::Kind::ratio ? Level(a.impact.ratio) : Level(to_string(a.impact));
    return {std::string(to_string(a.kinematics)), impact, std::string(to_string(a.roller))};
}

bool apply_assumptions(RunSpec& run, const multibody::AnalyticAssumptions& a,
                       std::vector<std::string>& skipped, const std::string& roller_source) {
    run.kinematics = a.kinematics;
    run.impact = a.impact;
    run.roller = a.roller;
    if (run.roller == Roller::unilateral && run.kinematics == Kinematics::paper) {
        skipped.push_back(fmt::format("the paper's kinematics with the unilateral roller{}: not a model (Eq. 3 does "
                                      "not keep the top corner on the roller's line, so it can neither leave the "
                                      "roller nor land back on it); not run",
                                      roller_source.empty() ? "" : " (" + roller_source + ")"));
        return false;
    }
    multibody::set_assumptions(run.settings, a);
    return true;
}

GroundMotion pulse_motion(const CaseSpec& c) {
    const double a = c.amplitude_g * kStandardGravity;
    if (c.shape == "sine") return sine_pulse(a, c.pulse_period);
    if (c.shape == "cosine") return cosine_pulse(a, c.pulse_period);
    if (c.shape == "ricker") return ricker_wavelet(a, c.pulse_period);
    return harmonic(a, c.pulse_period, c.duration);
}

bool Grid::run_applies(const RunSpec& run, const CaseSpec& c) const {
    if (run.part != c.part) return false;
    if (perturbed(c) && run.engine != "analytic") return false;  // the band is the analytic model's
    if (run.engine != "analytic" || c.model != "parapet") return true;
    // A parapet has neither a roller nor two kinematics: one analytic run per impact law stands for all.
    const auto it = parapet_run_.find(run.part);
    return it != parapet_run_.end() && run.assumptions[0] == it->second.first && run.assumptions[2] == it->second.second;
}

const GroundMotion& Grid::record(const CaseSpec& c) const {
    const auto it = records_.find(c.record_key);
    if (it == records_.end()) throw InputError(fmt::format("study {}: no record '{}'", spec_.name, c.file));
    return it->second;
}

std::vector<std::string> Grid::column_values(const CaseSpec& c, const RunSpec& run) const {
    const bool vssw = c.model == "vssw";
    const bool analytic = run.engine == "analytic";
    const PartSpec& part = spec_.parts[c.part];
    const ExcitationKind kind = part.kind;
    const bool record_kind = kind == ExcitationKind::record;
    const bool pulse = kind == ExcitationKind::pulse;
    std::vector<std::string> v;
    v.reserve(columns_.size());
    const std::vector<int>& column_axis = parts_[c.part].column_axis;
    using C = ColumnCode;
    for (std::size_t k = 0; k < columns_.size(); ++k) {
        const std::string& col = columns_[k];
        const ColumnCode code = column_codes_[k];
        const Level* given = column_axis[k] < 0 ? nullptr : &c.levels[static_cast<std::size_t>(column_axis[k])];
        // A number the file gives is written as the file gives it (a derived one may differ in its last digit);
        // hinge "eq15" too: the resolved ratio follows from xi by Eq. 15, and the level groups the rows as the file
        // does.
        const bool level_key = code == C::pga || code == C::level_key;
        if (given && (std::holds_alternative<double>(*given) || code == C::hinge) && !level_key && code != C::scale) {
            v.push_back(code == C::hinge && !vssw ? "" : to_text(*given));
            continue;
        }
        switch (code) {
        case C::model: v.push_back(c.model); break;
        case C::height: v.push_back(number(c.height)); break;
        case C::thickness: v.push_back(number(c.thickness)); break;
        case C::hinge: v.push_back(vssw ? number(c.hinge) : ""); break;
        case C::xi: v.push_back(number(c.xi)); break;
        case C::density: v.push_back(number(c.density)); break;
        case C::g: v.push_back(number(c.g)); break;
        case C::kinematics: v.push_back(analytic && vssw ? to_text(run.assumptions[0]) : ""); break;
        case C::impact: v.push_back(analytic ? to_text(run.assumptions[1]) : ""); break;
        case C::roller: v.push_back(analytic && vssw ? to_text(run.assumptions[2]) : ""); break;
        case C::kind: v.push_back(part.kind_text()); break;
        case C::theta0: v.push_back(c.theta0 > 0.0 ? number(c.theta0) : ""); break;
        case C::file: v.push_back(c.file); break;
        case C::scale: v.push_back(record_kind ? number(c.scale) : ""); break;
        case C::pga: v.push_back(record_kind ? number(c.pga_g) : ""); break;
        case C::level_key:
            v.push_back(record_kind && col == to_string(c.intensity.measure) ? number(c.intensity_value) : "");
            break;
        case C::intensity: v.push_back(part.ensemble ? part.ensemble->intensity : intensity_of(part)); break;
        case C::intensity_unit: {
            const std::string word = part.ensemble ? part.ensemble->intensity : intensity_of(part);
            v.push_back(word.empty() ? "" : intensity_unit(parse_intensity_measure(word)));
            break;
        }
        case C::shape: v.push_back(c.shape); break;
        case C::amplitude: v.push_back(pulse ? number(c.amplitude_g) : ""); break;
        case C::pulse_period: v.push_back(pulse ? number(c.pulse_period) : ""); break;
        case C::alpha: v.push_back(number(c.alpha)); break;
        case C::R: v.push_back(number(c.R)); break;
        case C::alpha1: v.push_back(vssw ? number(c.scene.vssw->alpha1) : ""); break;
        case C::alpha2: v.push_back(vssw ? number(c.scene.vssw->alpha2) : ""); break;
        case C::R1: v.push_back(vssw ? number(c.scene.vssw->R1) : ""); break;
        case C::settings: v.push_back(run.settings_text); break;
        case C::wall_name: v.push_back(wall_name(c)); break;
        case C::record_name: v.push_back(record_name(c)); break;
        case C::other: v.push_back(given ? to_text(*given) : ""); break;  // units, duration, tolerance, max_pga, ...
        }
    }
    return v;
}

std::vector<std::string> Grid::varied_parameters() const {
    std::vector<std::string> out;
    const auto varied = [&](const std::string& col) {
        if (col == "kind") return spec_.kind_text() == "mixed";
        for (const PartSpec& part : spec_.parts) {
            for (const Axis& a : part.wall)
                if (a.key == col && a.varied()) return true;
            for (const Axis& a : part.excitation)
                if (a.key == col && a.varied()) return true;
        }
        for (const Axis& a : spec_.assumptions)
            if (a.key == col && a.varied()) return true;
        return false;
    };
    for (const std::string& col : columns_)
        if (varied(col)) out.push_back(col);
    // alpha and R given as alpha/R vary under their own names; specimen under its.
    return out;
}

std::string Grid::record_path(const std::string& file) const {
    const std::filesystem::path given = file;
    return (given.is_absolute() ? given : std::filesystem::path(spec_.base_dir) / given).string();
}

std::string Grid::wall_name(const CaseSpec& c) const {
    return render(spec_.parts[c.part].names.wall_name, c, "wall_name");
}
std::string Grid::wall_label(const CaseSpec& c) const {
    return render(spec_.parts[c.part].names.wall_label, c, "wall_label");
}
std::string Grid::record_name(const CaseSpec& c) const {
    return render(spec_.parts[c.part].names.record_name, c, "record_name");
}
std::string Grid::record_label(const CaseSpec& c) const {
    return render(spec_.parts[c.part].names.record_label, c, "record_label");
}

// "{key}" or "{key:spec}" replaced by the case's value of key (a whole number formatted as an integer, so that
// "{specimen:02}" gives "07"); "{{" and "}}" are braces.
std::string Grid::render(const std::string& tmpl, const CaseSpec& c, const char* key) const {
    if (tmpl.empty()) return "";
    const PartSpec& part = spec_.parts[c.part];
    const std::vector<const Axis*>& axes = parts_[c.part].axes;
    const auto value = [&](const std::string& name) -> std::optional<Level> {
        for (std::size_t i = 0; i < axes.size(); ++i)
            if (axes[i]->key == name && std::holds_alternative<double>(c.levels[i])) return c.levels[i];
        if (name == "model") return c.model;
        if (name == "height") return c.height;
        if (name == "thickness") return c.thickness;
        if (name == "hinge" && c.scene.vssw) return c.hinge;
        if (name == "xi") return c.xi;
        if (name == "density") return c.density;
        if (name == "g") return c.g;
        if (name == "alpha") return c.alpha;
        if (name == "R") return c.R;
        if (name == "theta0" && c.theta0 > 0.0) return c.theta0;
        if (name == "file" && !c.file.empty()) return c.file;
        if (name == "scale" && !c.file.empty()) return c.scale;
        if (name == "pga" && !c.file.empty()) return c.pga_g;
        if (name == "kind") return part.kind_text();
        return std::nullopt;
    };
    const auto fail = [&](const std::string& why) {
        return InputError(fmt::format("{} {}: {}{}: \"{}\": {}", kWhat, spec_.path,
                                      part.where.empty() ? "" : part.where + ".", key, tmpl, why));
    };
    if (const auto why = template_too_wide(tmpl)) throw fail(*why);  // for a grid not read from a file
    std::string out;
    for (std::size_t i = 0; i < tmpl.size(); ++i) {
        const char ch = tmpl[i];
        if ((ch == '{' || ch == '}') && i + 1 < tmpl.size() && tmpl[i + 1] == ch) {
            out += ch;
            ++i;
            continue;
        }
        if (ch == '}') throw fail("a '}' without its '{'");
        if (ch != '{') {
            out += ch;
            continue;
        }
        const std::size_t close = tmpl.find('}', i);
        if (close == std::string::npos) throw fail("a '{' without its '}'");
        const std::string field = tmpl.substr(i + 1, close - i - 1);
        const std::size_t colon = field.find(':');
        const std::string name = field.substr(0, colon);
        const std::string format = colon == std::string::npos ? "" : field.substr(colon + 1);
        const std::optional<Level> v = value(name);
        if (!v) throw fail(fmt::format("no value '{}' for this case", name));
        try {
            if (const auto* x = std::get_if<double>(&*v)) {
                const bool whole = *x == std::floor(*x) && std::abs(*x) < 1e15 &&
                                   format.find_first_of("eEfFgG%") == std::string::npos;
                out += whole ? fmt::format(fmt::runtime("{:" + format + "}"), static_cast<long long>(*x))
                             : fmt::format(fmt::runtime("{:" + format + "}"), *x);
            } else {
                out += fmt::format(fmt::runtime("{:" + format + "}"), std::get<std::string>(*v));
            }
        } catch (const fmt::format_error& e) {
            throw fail(fmt::format("format '{}' of '{}': {}", format, name, e.what()));
        }
        i = close;
    }
    if (out.size() > kMaxNameBytes)
        throw fail(fmt::format("names this case with {} bytes, more than {}", out.size(), kMaxNameBytes));
    return out;
}

std::vector<int> Grid::shard_case_ids(int k, int n) const {
    require(n >= 1, "shard count", ">= 1", n);
    require(k >= 1 && k <= n, "shard", "from 1 to the shard count", k);
    std::vector<int> out;
    for (std::size_t i = static_cast<std::size_t>(k - 1); i < case_ids_.size(); i += static_cast<std::size_t>(n))
        out.push_back(case_ids_[i]);
    return out;
}

}  // namespace vssw::study
