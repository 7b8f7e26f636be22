#include "study/spec.hpp"

#include <algorithm>
#include <map>
#include <cmath>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>

#include <fmt/format.h>

#include "analytic/diaphragm.hpp"
#include "analytic/error.hpp"
#include "analytic/input_file.hpp"
#include "analytic/ground_motion.hpp"
#include "analytic/intensity_measures.hpp"
#include "analytic/wall.hpp"
#include "io/config_file.hpp"
#include "io/csv.hpp"
#include "io/json.hpp"
#include "io/text.hpp"
#include "study/name_bounds.hpp"
#include "study/record_files.hpp"
#include "study/metric_catalog.hpp"
#include "compare/experiments.hpp"
#include "multibody/host/analytic_engine.hpp"
#include "multibody/engine.hpp"
#include "multibody/host/engine_names.hpp"

namespace vssw::study {

const std::vector<std::string> kWallKeys = {"model", "specimen", "height", "thickness", "alpha", "R",      "alpha1",
                                            "alpha2", "R1",      "hinge",  "xi",        "overburden_eccentricity",
                                            "density", "g", "corner_radius", "friction", "hinge_friction",
                                            "diaphragm_period", "diaphragm_damping"};
const std::vector<std::string> kAssumptionKeys = {"kinematics", "impact", "roller"};
const std::vector<std::string> kPhysicalAssumptionKeys = {"overburden_eccentricity", "friction", "hinge_friction",
                                                         "corner_radius", "diaphragm_period"};
const std::vector<std::string> kExcitationKeys = {"theta0",       "file",     "units",     "scale",
                                                  "pga",          "pgv",      "sa",        "arias",
                                                  "shape",        "amplitude", "pulse_period",
                                                  "duration",     "tolerance", "max_pga",  "step",
                                                  "sa_period",    "sa_damping", "perturbation", "response_tail"};
const std::vector<std::string> kLevelKeys = {"pga", "pgv", "sa", "arias"};
// The names say the factors (kBandIntensityStep, kBandRestitutionStep, kBandSizeStep).
const std::vector<std::string> kPerturbations = {"none",          "pga+1e-2", "pga-1e-2", "restitution+2e-2",
                                                 "restitution-2e-2", "size+1e-2", "size-1e-2"};

BandFactors band_factors(const std::string& perturbation) {
    BandFactors f;
    if (perturbation == "pga+1e-2") f.intensity = 1.0 + kBandIntensityStep;
    if (perturbation == "pga-1e-2") f.intensity = 1.0 - kBandIntensityStep;
    if (perturbation == "restitution+2e-2") f.restitution_error = kBandRestitutionStep;
    if (perturbation == "restitution-2e-2") f.restitution_error = -kBandRestitutionStep;
    if (perturbation == "size+1e-2") f.size = 1.0 + kBandSizeStep;
    if (perturbation == "size-1e-2") f.size = 1.0 - kBandSizeStep;
    return f;
}

namespace {

using nlohmann::json;

constexpr const char* kWhat = "study file";
const std::vector<std::string> kTopKeys = {"name",        "description", "metrics",  "engines", "wall",
                                           "assumptions", "excitation",  "settings", "part", "one_at_a_time"};
const std::vector<std::string> kPartKeys = {"wall",        "excitation", "metrics",     "settings",
                                            "wall_name",   "wall_label", "record_name", "record_label",
                                            "skip_falling_releases", "one_at_a_time"};
// The smallest release and the most iterations, as vssw compare's (compare/experiments.hpp, multibody/engine.hpp).
constexpr double kMinTheta0 = compare::kMinRelease;
constexpr double kMinCollapseStep = 1e-3;  // scale-to-collapse's smallest relative step (read_value, "step")
constexpr double kMinCollapseTolerance = 1e-12;  // and its smallest relative bisection width ("tolerance")
using multibody::kMaxIterations;
// The most values one list may hold: ten times the tasks a study runs without --force, on one key alone. A longer list
// is a generated file gone wrong, refused before each value is checked.
constexpr std::size_t kMaxLevels = 100000;
// Table 1's numbers are below this; a larger one cannot be a specimen (and would not fit an int).
constexpr double kMaxSpecimen = 1000.0;

// The position of the first value that repeats an earlier one, if any. Sorted, not pairwise: a list of 400,000 values
// took minutes pairwise. 0.0 and -0.0 are equal (neither sorts before the other, and == holds).
std::optional<std::size_t> first_repeat(const std::vector<Level>& levels) {
    std::vector<std::size_t> order(levels.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return levels[a] < levels[b]; });
    std::optional<std::size_t> first;
    for (std::size_t k = 1; k < order.size(); ++k)
        if (levels[order[k]] == levels[order[k - 1]] && (!first || order[k] < *first)) first = order[k];
    return first;
}

bool contains(const std::vector<std::string>& list, const std::string& x) {
    return std::find(list.begin(), list.end(), x) != list.end();
}

// Messages name the file and the key: "study file s.toml: wall.thickness: ...".
class Reader {
public:
    explicit Reader(std::string name) : name_(std::move(name)) {}

    [[noreturn]] void fail(const std::string& key, const std::string& message) const {
        throw InputError(fmt::format("{} {}: {}{}", kWhat, name_, key.empty() ? "" : key + ": ", message));
    }

    // doc[key] as a table of known keys; `where` names it in messages (default: key).
    const json& table(const json& doc, const std::string& key, const std::vector<std::string>& known,
                      const std::string& where = "") const {
        const json& t = doc.at(key);
        const std::string name = where.empty() ? key : where;
        if (!t.is_object()) fail(name, fmt::format("must be a table of keys, got {}", io::dump_json(t)));
        unknown_keys(t, name, known);
        return t;
    }

    void unknown_keys(const json& t, const std::string& where, const std::vector<std::string>& known) const {
        for (const auto& item : t.items())
            if (!contains(known, item.key()))
                fail(where, fmt::format("unknown key '{}' (known: {})", item.key(), fmt::join(known, ", ")));
    }

    // A scalar or a non-empty list of at most kMaxLevels scalars, each checked by `check` (which returns the level or
    // calls fail), each listed once.
    template <class Check>
    Axis axis(const json& value, const std::string& key, Check check) const {
        Axis a{key.substr(key.rfind('.') + 1), {}};
        if (value.is_array()) {
            if (value.empty()) fail(key, "an empty list: give at least one value");
            if (value.size() > kMaxLevels)
                fail(key, fmt::format("a list of {} values, more than {} (the grid would be far beyond any study)",
                                      value.size(), kMaxLevels));
            for (const json& v : value) a.levels.push_back(check(v));
        } else {
            a.levels.push_back(check(value));
        }
        if (const std::optional<std::size_t> twice = first_repeat(a.levels))
            fail(key, fmt::format("lists {} twice (each value once: the grid would repeat cases)",
                                  to_text(a.levels[*twice])));
        return a;
    }

    double number(const json& v, const std::string& key, const std::string& rule) const {
        // JSON has no NaN; TOML's nan and inf come through the JSON formatter as text or non-numbers.
        if (!v.is_number() || !std::isfinite(v.get<double>()))
            fail(key, fmt::format("must be a finite number ({}), got {}", rule, io::dump_json(v)));
        return v.get<double>();
    }
    double positive(const json& v, const std::string& key, const std::string& rule) const {
        const double x = number(v, key, rule);
        if (!(x > 0.0)) fail(key, fmt::format("must be {}, got {}", rule, io::dump_json(v)));
        return x;
    }
    std::string word(const json& v, const std::string& key, const std::vector<std::string>& allowed) const {
        if (!v.is_string() || (!allowed.empty() && !contains(allowed, v.get<std::string>())))
            fail(key, fmt::format("must be one of {}, got {}", fmt::join(allowed, ", "), io::dump_json(v)));
        return v.get<std::string>();
    }

    const std::string& name() const { return name_; }

private:
    std::string name_;
};

Level wall_level(const Reader& r, const std::string& key, const json& v) {
    const std::string k = key.substr(key.rfind('.') + 1);
    if (k == "model") return r.word(v, key, {"vssw", "parapet"});
    if (k == "hinge") {
        if (v.is_string()) return r.word(v, key, {"eq15"});
        return r.number(v, key, "h1/h in (0, 1), or \"eq15\" for Eq. (15)'s hinge");
    }
    if (k == "specimen") {
        const double x = r.number(v, key, "a Table 1 specimen number");
        if (x != std::floor(x) || x < 1.0 || x > kMaxSpecimen)
            r.fail(key, fmt::format("must be a Table 1 specimen number, got {}", io::dump_json(v)));
        return x;
    }
    if (k == "diaphragm_period" || k == "diaphragm_damping") {  // the VSSW's top support (analytic/diaphragm.hpp)
        const bool period = k == "diaphragm_period";
        const double limit = period ? kMaxDiaphragmPeriod : kMaxDiaphragmDamping;
        const double x = r.number(v, key, period ? "T_d in s" : "zeta_d");
        if (!(x >= 0.0 && x <= limit))
            r.fail(key, fmt::format("must be {} in [0, {:g}], got {}", period ? "the diaphragm's period T_d [s]"
                                                                              : "the diaphragm's damping ratio",
                                    limit, io::dump_json(v)));
        return x;
    }
    if (k == "overburden_eccentricity") {
        const double x = r.number(v, key, "e/b in [-1, 1]");
        if (!(x >= -1.0 && x <= 1.0))
            r.fail(key, fmt::format("must be N's eccentricity e/b in [-1, 1] (the top face's corners), got {}",
                                    io::dump_json(v)));
        return x;
    }
    if (k == "corner_radius") {
        const double x = r.number(v, key, fmt::format("r/b in [0, {:g}]", kMaxCornerRadius));
        if (!(x >= 0.0 && x <= kMaxCornerRadius))
            r.fail(key, fmt::format("must be the corners' radius r/b in [0, {:g}] (0: sharp), got {}",
                                    kMaxCornerRadius, io::dump_json(v)));
        return x;
    }
    if (k == "friction" || k == "hinge_friction") {  // the contacts' Coulomb coefficient (multibody/engine.hpp)
        const double x = r.number(v, key, "a friction coefficient > 0");
        if (!(x > 0.0 && std::isfinite(x)))
            r.fail(key, fmt::format("must be a friction coefficient > 0, got {}", io::dump_json(v)));
        return x;
    }
    if (k == "xi") {
        const double x = r.number(v, key, "N/W >= 0");
        if (x < 0.0) r.fail(key, fmt::format("must be N/W >= 0, got {}", io::dump_json(v)));
        return x;
    }
    // Lengths, angles, density, g: positive; their ranges are the wall constructors' (analytic/wall.hpp), checked
    // when the grid's walls are built, naming the value.
    return r.positive(v, key, "a positive number");
}

Level assumption_level(const Reader& r, const std::string& key, const json& v) {
    const std::string k = key.substr(key.rfind('.') + 1);
    if (k == "kinematics") return r.word(v, key, {"paper", "exact"});
    if (k == "roller") return r.word(v, key, {"bilateral", "unilateral"});
    // impact: a law by name or an impact ratio.
    if (v.is_string()) return r.word(v, key, {"eq19", "whole-mechanism"});
    const double e = r.number(v, key, "eq19, whole-mechanism or a ratio in [0, 1]");
    if (e < 0.0 || e > 1.0) r.fail(key, fmt::format("an impact ratio must be in [0, 1], got {}", io::dump_json(v)));
    return e;
}

// A set's three parts as a study file writes them (analytic/assumption_sets.hpp defines the sets; a test holds these
// words to assumptions_of(set)). Words, not the model's to_string: the file reader links no model.
std::vector<Axis> set_levels(AssumptionSet set) {
    const bool paper = set == AssumptionSet::paper;
    return {{"kinematics", {std::string(paper ? "paper" : "exact")}},
            {"impact", {std::string(paper ? "eq19" : "whole-mechanism")}},
            {"roller", {std::string(paper ? "bilateral" : "unilateral")}}};
}

// [assumptions]: the set (one name) gives every key's default; a key the file gives overrides the set's, as a value or
// an axis. A list of sets is refused: the keys vary one part at a time, and the product of all three holds both sets.
void read_assumptions(const Reader& r, const json& doc, StudySpec& s) {
    static const std::vector<std::string> known = [] {
        std::vector<std::string> k = {"set"};
        k.insert(k.end(), kAssumptionKeys.begin(), kAssumptionKeys.end());
        return k;
    }();
    const json empty = json::object();
    const json& a = doc.contains("assumptions") ? r.table(doc, "assumptions", known) : empty;
    if (a.contains("set")) {
        const json& set = a["set"];
        if (set.is_array())
            r.fail("assumptions.set", fmt::format("one set per study, got {}: vary kinematics, impact or roller (the "
                                                  "three varied hold both sets), or run one study per set",
                                                  io::dump_json(set)));
        s.assumption_set = parse_assumption_set(r.word(set, "assumptions.set", {"paper", "mechanism"}));
    }
    s.assumptions = set_levels(s.assumption_set);
    for (Axis& axis : s.assumptions)
        if (a.contains(axis.key)) {
            const std::string key = "assumptions." + axis.key;
            axis = r.axis(a[axis.key], key, [&](const json& v) { return assumption_level(r, key, v); });
            s.assumptions_given.push_back(axis.key);
        }
}

Level excitation_level(const Reader& r, const std::string& key, const json& v) {
    const std::string k = key.substr(key.rfind('.') + 1);
    if (k == "file") {
        if (!v.is_string() || v.get<std::string>().empty())
            r.fail(key, fmt::format("must be the path of a record file, got {}", io::dump_json(v)));
        return v.get<std::string>();
    }
    if (k == "units") {
        const std::string u = r.word(v, key, {});
        try {
            (void)parse_units(u);
        } catch (const InputError& e) {
            r.fail(key, e.what());
        }
        return u;
    }
    if (k == "shape") return r.word(v, key, {"sine", "cosine", "ricker", "harmonic"});
    if (k == "perturbation") return r.word(v, key, kPerturbations);
    if (k == "theta0") {
        const double x = r.number(v, key, "a fraction of alpha");
        if (x < kMinTheta0) r.fail(key, fmt::format("must be at least {} (a fraction of alpha), got {}", kMinTheta0, io::dump_json(v)));
        return x;
    }
    if (k == "step") {
        // From 0.1 %: the scales grow geometrically up to max_pga (ln(20) / ln(1.001) = 3,000 runs at most under the
        // default max_pga), and the bisection after them sets the precision (`tolerance`); a step of 1e-9 asked for
        // 2e9 runs and never ended.
        const double x = r.number(v, key, "a relative increment in [0.001, 1]");
        if (!(x >= kMinCollapseStep && x <= 1.0))
            r.fail(key, fmt::format("must be a relative increment in [{}, 1], got {}", kMinCollapseStep, io::dump_json(v)));
        return x;
    }
    if (k == "response_tail") {
        // 0 ends the run with the motion; a run also ends at rest or overturning, and a tail too long for the step
        // is refused before anything runs (require_runs_resolve: 1e8 steps).
        const double x = r.number(v, key, "a time in s, 0 or more");
        if (!(x >= 0.0)) r.fail(key, fmt::format("must be a time in s, 0 or more, got {}", io::dump_json(v)));
        return x;
    }
    if (k == "sa_damping") {
        const double x = r.number(v, key, "a damping ratio in [0, 1)");
        if (!(x >= 0.0 && x < 1.0)) r.fail(key, fmt::format("must be a damping ratio in [0, 1), got {}", io::dump_json(v)));
        return x;
    }
    if (k == "tolerance") {
        // From 1e-12: below ~1e-16 the bisection's mid-point rounds onto an end and the width never falls (1e-17 ran
        // without end).
        const double x = r.number(v, key, "a relative width in [1e-12, 0.1]");
        if (!(x >= kMinCollapseTolerance && x <= 0.1))
            r.fail(key, fmt::format("must be a relative width in [{:g}, 0.1], got {}", kMinCollapseTolerance, io::dump_json(v)));
        return x;
    }
    return r.positive(v, key, "a positive number");
}

// The keys each kind reads besides `kind`, and those it needs.
struct KindKeys {
    std::vector<std::string> allowed, required;
};
KindKeys kind_keys(ExcitationKind kind) {
    switch (kind) {
        case ExcitationKind::closed_form: return {{"theta0"}, {}};
        case ExcitationKind::threshold: return {{}, {}};
        case ExcitationKind::free: return {{"theta0"}, {"theta0"}};
        case ExcitationKind::pulse:
            return {{"shape", "amplitude", "pulse_period", "duration", "response_tail"},
                    {"shape", "amplitude", "pulse_period"}};
        case ExcitationKind::record:
            return {{"file", "units", "scale", "pga", "pgv", "sa", "arias", "sa_period", "sa_damping", "response_tail"},
                    {"file"}};
        case ExcitationKind::scale_to_collapse:
            return {{"file", "units", "tolerance", "max_pga", "step", "sa_period", "sa_damping", "response_tail"},
                    {"file"}};
    }
    return {};
}

ExcitationKind parse_kind(const Reader& r, const json& v, const std::string& key) {
    // (An ensemble is read into a record or scale-to-collapse part before its kind is parsed: read_ensemble.)
    const std::string k = r.word(
        v, key, {"closed-form", "threshold", "free", "pulse", "record", "scale-to-collapse", "ensemble"});
    if (k == "closed-form") return ExcitationKind::closed_form;
    if (k == "threshold") return ExcitationKind::threshold;
    if (k == "free") return ExcitationKind::free;
    if (k == "pulse") return ExcitationKind::pulse;
    if (k == "record") return ExcitationKind::record;
    return ExcitationKind::scale_to_collapse;
}

// An ensemble folder's records: every file whose name ends in .at2 (any case), and every file a records.csv or
// motions.csv in it lists in its `file` column (data/records/records.csv, vssw motions generate's motions.csv); each
// once, sorted by name (byte order), each as the folder joined with its name (so relative to the study file's folder
// when the folder is).
std::vector<std::string> ensemble_files(const Reader& r, const std::string& key, const std::string& folder,
                                        const std::string& base_dir) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::path(folder).is_absolute() ? fs::path(folder) : fs::path(base_dir) / folder;
    std::error_code ec;
    if (!fs::is_directory(dir, ec))
        r.fail(key, fmt::format("no folder \"{}\" (looked for {})", folder, dir.string()));
    std::set<std::string> names;
    // Stepped with error codes (a range-for's ++ throws): a folder that cannot be listed is one line. An entry named
    // *.at2 that is no file (a dangling link, as a git-annex or DVC folder not fully fetched holds; a link loop, a
    // FIFO, a device, a folder) is refused by name: skipped, the ensemble would shrink without a word.
    fs::directory_iterator it(dir, ec), end;
    for (; !ec && it != end; it.increment(ec)) {
        std::string ext = it->path().extension().string();
        std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char ch) { return std::tolower(ch); });
        if (ext != ".at2") continue;
        if (const std::string why = not_a_record_file(it->path()); !why.empty())
            r.fail(key, fmt::format("\"{}\" in \"{}\" is {}, not a record file: fetch or remove it", it->path().filename().string(),
                                    folder, why));
        names.insert(it->path().filename().string());
    }
    if (ec) r.fail(key, fmt::format("cannot list the folder \"{}\": {}", folder, ec.message()));
    for (const char* table : {"records.csv", "motions.csv"}) {
        std::error_code table_ec;
        if (!fs::exists(fs::symlink_status(dir / table, table_ec))) continue;
        std::ifstream in = open_input_file(dir / table, fmt::format("{}: the table", key), kMaxTextFileBytes);
        std::vector<std::string> fields;
        if (!io::read_csv_record(in, fields)) continue;
        const auto column = std::find(fields.begin(), fields.end(), "file");
        if (column == fields.end()) continue;
        const std::size_t at = static_cast<std::size_t>(column - fields.begin());
        while (io::read_csv_record(in, fields)) {
            if (fields.size() <= at || fields[at].empty()) continue;
            if (fs::path(fields[at]).has_parent_path() || fields[at] == "..")
                r.fail(key, fmt::format("\"{}\" lists \"{}\", which is not a file name in \"{}\" (a folder's table "
                                        "names files in it)",
                                        table, fields[at], folder));
            if (const std::string why = not_a_record_file(dir / fields[at]); !why.empty())
                r.fail(key, fmt::format("\"{}\" lists \"{}\", which is not a file in \"{}\" ({})", table, fields[at],
                                        folder, why));
            names.insert(fields[at]);
        }
    }
    for (const std::string& name : names)  // a name goes into results.json and the pages, both UTF-8
        if (const auto mistake = io::not_utf8(name))
            r.fail(key, fmt::format("the record {} in \"{}\": rename it", *mistake, io::printable(folder)));
    if (names.empty())
        r.fail(key, fmt::format("no records in \"{}\" (*.at2 files, or a records.csv or motions.csv naming them in "
                                "its 'file' column)",
                                folder));
    std::vector<std::string> out;
    for (const std::string& name : names) out.push_back((fs::path(folder) / name).generic_string());
    return out;
}

const std::vector<std::string> kEnsembleKeys = {"kind",  "files",    "ensemble",  "intensity", "levels",    "collapse",
                                                "band",  "units",    "max_pga",   "tolerance", "step",      "sa_period",
                                                "sa_damping"};

bool flag(const Reader& r, const json& ex, const std::string& ex_key, const char* name) {
    if (!ex.contains(name)) return false;
    if (!ex[name].is_boolean())
        r.fail(ex_key + "." + name, fmt::format("must be true or false, got {}", io::dump_json(ex[name])));
    return ex[name].get<bool>();
}

// Two entries of an ensemble that name one file, however spelled (study/record_files.hpp), refused naming both.
void refuse_one_record_twice(const Reader& r, const std::string& key, const json& files, const std::string& base_dir) {
    std::vector<std::filesystem::path> paths;
    for (const json& f : files) {
        const std::filesystem::path given = f.get<std::string>();
        paths.push_back(given.is_absolute() ? given : std::filesystem::path(base_dir) / given);
    }
    if (const auto twice = same_file_twice(paths))
        r.fail(key, fmt::format("\"{}\" and \"{}\" are one file (the same device and inode): each record once, or "
                                "the ensemble would count it as two independent records",
                                files[twice->first].get<std::string>(), files[twice->second].get<std::string>()));
}

// What an ensemble's level is, for messages: "a PGA in g, > 0".
std::string level_rule(const std::string& intensity) {
    if (intensity == "pgv") return "a PGV in m/s, > 0";
    if (intensity == "sa") return "an Sa in g, > 0";
    if (intensity == "arias") return "an Arias intensity in m/s, > 0";
    return "a PGA in g, > 0";
}

// kind = "ensemble" read into the record or scale-to-collapse excitation it stands for (spec.hpp): the records as
// `file`, the levels as `pga`, band's `perturbation` axis; `e` says what it was.
json read_ensemble(const Reader& r, const json& ex, const std::string& ex_key, const std::string& base_dir,
                   EnsembleSpec& e) {
    const auto key = [&](const char* k) { return ex_key + "." + k; };
    r.unknown_keys(ex, ex_key + " (kind ensemble)", kEnsembleKeys);
    if (ex.contains("files") == ex.contains("ensemble"))
        r.fail(ex_key, "give the records one way: 'files' (a list of record files) or 'ensemble' (a folder of "
                       "them), not both and not neither");
    json out = json::object();
    if (ex.contains("files")) {
        const Axis files = r.axis(ex["files"], key("files"), [&](const json& v) -> Level {
            if (!v.is_string() || v.get<std::string>().empty())
                r.fail(key("files"), fmt::format("must list paths of record files, got {}", io::dump_json(v)));
            return v.get<std::string>();
        });
        for (const Level& f : files.levels) out["file"].push_back(std::get<std::string>(f));
    } else {
        if (!ex["ensemble"].is_string() || ex["ensemble"].get<std::string>().empty())
            r.fail(key("ensemble"), fmt::format("must be the path of a folder of records, got {}", io::dump_json(ex["ensemble"])));
        e.folder = ex["ensemble"].get<std::string>();
        out["file"] = ensemble_files(r, key("ensemble"), e.folder, base_dir);
    }
    const std::string files_key = ex.contains("files") ? key("files") : key("ensemble");
    refuse_one_record_twice(r, files_key, out["file"], base_dir);
    if (out["file"].size() < 2)
        r.fail(files_key,
               fmt::format("an ensemble needs at least two records, got {}", out["file"].size()));
    if (!ex.contains("intensity")) r.fail(ex_key, "kind ensemble needs 'intensity' (\"pga\", \"pgv\", \"sa\", \"arias\")");
    e.intensity = r.word(ex["intensity"], key("intensity"), kLevelKeys);
    const bool sa = e.intensity == "sa";
    if (sa && !ex.contains("sa_period")) r.fail(ex_key, "intensity \"sa\" needs 'sa_period' (the oscillator's period, s)");
    for (const char* k : {"sa_period", "sa_damping"}) {
        if (!ex.contains(k)) continue;
        if (!sa) r.fail(key(k), "is for intensity = \"sa\" (the spectral acceleration's oscillator)");
        out[k] = ex[k];
    }
    e.collapse = flag(r, ex, ex_key, "collapse");
    e.band = flag(r, ex, ex_key, "band");
    const std::string unit = intensity_unit(parse_intensity_measure(e.intensity));
    if (ex.contains("levels") == e.collapse)
        r.fail(ex_key, fmt::format("give 'levels' ({}: each record scaled so that its {} equals each level, a stripe "
                                   "analysis) or 'collapse = true' (each record scaled until the wall overturns, "
                                   "incremental dynamic analysis): one of them",
                                   unit, e.intensity));
    if (ex.contains("units")) out["units"] = ex["units"];
    if (e.collapse) {
        if (e.band) r.fail(key("band"), "is for a stripe analysis (levels), not collapse = true");
        out["kind"] = "scale-to-collapse";
        for (const char* k : {"max_pga", "tolerance", "step"})
            if (ex.contains(k)) out[k] = ex[k];
        return out;
    }
    for (const char* k : {"max_pga", "tolerance", "step"})
        if (ex.contains(k)) r.fail(key(k), "is for collapse = true (a search for the overturning scale)");
    out["kind"] = "record";
    const Axis levels = r.axis(ex["levels"], key("levels"), [&](const json& v) -> Level {
        return r.positive(v, key("levels"), level_rule(e.intensity));
    });
    // agreement.csv names a column per level by its value to 6 significant digits (study/ensemble_outputs.cpp): two
    // levels that print alike there would share one.
    std::map<std::string, double> printed;
    for (const Level& l : levels.levels) {
        const double level = std::get<double>(l);
        const auto [at, added] = printed.emplace(fmt::format("{:.6g}", level), level);
        if (!added)
            r.fail(key("levels"), fmt::format("{} and {} are one level to 6 significant digits (agreement.csv names "
                                              "its columns by them): give levels that differ there",
                                              at->second, level));
        out[e.intensity].push_back(level);
    }
    if (e.band) out["perturbation"] = kPerturbations;
    return out;
}

// The wall's geometry must come one way: height and thickness, alpha and R, alpha1-alpha2-R1, or a specimen.
void check_wall_routes(const Reader& r, const json& wall, const std::string& where) {
    const auto has = [&](const char* k) { return wall.contains(k); };
    const int routes = (has("height") || has("thickness") ? 1 : 0) + (has("alpha") || has("R") ? 1 : 0) +
                       (has("alpha1") || has("alpha2") || has("R1") ? 1 : 0) + (has("specimen") ? 1 : 0);
    if (routes != 1)
        r.fail(where, "give the geometry one way: height and thickness; alpha and R (the whole wall's slenderness "
                       "and half-diagonal); alpha1, alpha2 and R1 (the paper's parameters); or specimen (Table 1)");
    const auto pair = [&](const char* a, const char* b) {
        if (has(a) != has(b)) r.fail(where, fmt::format("'{}' needs '{}' too", has(a) ? a : b, has(a) ? b : a));
    };
    pair("height", "thickness");
    pair("alpha", "R");
    if ((has("alpha1") || has("alpha2") || has("R1")) && !(has("alpha1") && has("alpha2") && has("R1")))
        r.fail(where, "alpha1, alpha2 and R1 go together (the paper's parameters of a VSSW)");
    if (has("alpha1") && has("hinge"))
        r.fail(where, "alpha1, alpha2 and R1 fix the hinge (h1/h = tan(alpha2) / (tan(alpha1) + tan(alpha2))): no 'hinge'");
}

std::vector<Axis> read_axes(const Reader& r, const json& t, const std::string& table,
                            const std::vector<std::string>& order, Level (*level)(const Reader&, const std::string&,
                                                                                  const json&)) {
    std::vector<Axis> axes;
    for (const std::string& k : order) {
        if (!t.contains(k)) continue;
        const std::string key = table + "." + k;
        axes.push_back(r.axis(t.at(k), key, [&](const json& v) { return level(r, key, v); }));
    }
    return axes;
}

// [settings.NAME] or [engines.NAME]: dt, iterations, knobs; each a number or a list of numbers.
std::vector<Axis> read_settings(const Reader& r, const json& t, const std::string& where, const std::string& engine) {
    if (!t.is_object()) r.fail(where, fmt::format("must be a table of settings, got {}", io::dump_json(t)));
    std::vector<Axis> axes;
    // dt, iterations, then the knobs by name (a JSON object's keys come sorted).
    std::vector<std::string> keys;
    for (const char* first : {"dt", "iterations"})
        if (t.contains(first)) keys.push_back(first);
    for (const auto& item : t.items()) {
        if (item.key().empty()) r.fail(where, "a setting without a name (\"\"): give the knob's name");
        if (multibody::is_knob(item.key())) keys.push_back(item.key());
    }
    for (const std::string& k : keys) {
        const std::string key = where + "." + k;
        if (engine == "analytic" && !multibody::is_knob(k))
            r.fail(key, "the analytic model has no step or iterations to set (its tolerance is rtol; its free "
                        "vibrations are sampled every 1e-4 s, like an engine's, for the metric code)");
        // The knobs that stand for the analytic model's assumptions: the file gives those in [assumptions], where
        // they vary and have columns of their own.
        if (engine == "analytic" && contains(multibody::assumption_knobs(), k))
            r.fail(key, "the analytic model's assumptions go in [assumptions] (kinematics, impact, roller), where they "
                        "can vary and have columns of their own");
        axes.push_back(r.axis(t.at(k), key, [&](const json& v) -> Level {
            if (k == "dt") return r.positive(v, key, "the engine step in s, > 0");
            const double x = r.number(v, key, "a number");
            if (k == "iterations" && (x != std::floor(x) || x < 1.0 || x > kMaxIterations))
                r.fail(key, fmt::format("must be an integer from 1 to {}, got {}", kMaxIterations, io::dump_json(v)));
            return x;
        }));
        axes.back().key = k;  // the knob's own name: a name with a dot ("d.") is not cut at it, and is refused later
    }
    return axes;
}

std::vector<EngineSpec> read_engines(const Reader& r, const json& doc) {
    std::vector<EngineSpec> engines;
    const std::vector<std::string> available = multibody::available_engines();
    // A name as given ("ODE", "Simbody-Rigid") read as its backend's canonical name, the one the outputs print.
    auto canonical = [&](const std::string& name, const std::string& key) {
        const std::optional<std::string> known = multibody::canonical_engine(name);
        if (!known)
            r.fail(key, fmt::format("no engine '{}' in this build{} (available: {})", name,
                                    multibody::engine_name_hint(name), fmt::join(available, ", ")));
        return *known;
    };
    auto add = [&](const std::string& name, const std::string& key) {
        if (std::any_of(engines.begin(), engines.end(), [&](const EngineSpec& e) { return e.name == name; }))
            r.fail(key, fmt::format("names engine '{}' twice", name));
        engines.push_back({name, {}});
    };
    if (!doc.contains("engines")) {
        engines.push_back({"analytic", {}});
    } else if (doc["engines"].is_array()) {
        if (doc["engines"].empty()) r.fail("engines", "an empty list: name at least one engine");
        for (const json& v : doc["engines"]) {
            if (!v.is_string()) r.fail("engines", fmt::format("must list engine names, got {}", io::dump_json(v)));
            add(canonical(v.get<std::string>(), "engines"), "engines");
        }
    } else if (doc["engines"].is_object()) {
        if (doc["engines"].empty()) r.fail("engines", "an empty table: name at least one engine");
        std::map<std::string, const json*> tables;  // canonical name -> its table
        for (const auto& item : doc["engines"].items()) {
            const std::string name = canonical(item.key(), "engines");
            if (!tables.emplace(name, &item.value()).second)
                r.fail("engines", fmt::format("names engine '{}' twice", name));
        }
        // A table's keys have no order in TOML: the build's order of engines.
        for (const std::string& name : available)
            if (const auto it = tables.find(name); it != tables.end()) {
                add(name, "engines");
                engines.back().settings = read_settings(r, *it->second, "engines." + name, name);
            }
    } else {
        r.fail("engines", fmt::format("must be a list of engine names or a table of engines, got {}",
                                      io::dump_json(doc["engines"])));
    }
    if (doc.contains("settings")) {
        const json& s = doc["settings"];
        if (!s.is_object()) r.fail("settings", fmt::format("must be a table of engines, got {}", io::dump_json(s)));
        for (const auto& item : s.items()) {
            const std::string name = multibody::canonical_engine(item.key()).value_or(item.key());
            const auto it = std::find_if(engines.begin(), engines.end(),
                                         [&](const EngineSpec& e) { return e.name == name; });
            if (it == engines.end())
                r.fail("settings." + item.key(), "settings for an engine the study does not run (add it to engines)");
            if (!it->settings.empty())
                r.fail("settings." + item.key(), "settings given twice (in [engines." + item.key() + "] too)");
            it->settings = read_settings(r, item.value(), "settings." + item.key(), name);
        }
    }
    return engines;
}

std::vector<std::string> read_metrics(const Reader& r, const json& m, const std::string& key) {
    if (!m.is_array() || m.empty()) r.fail(key, fmt::format("must be a non-empty list of metric names, got {}", io::dump_json(m)));
    std::vector<std::string> out;
    for (const json& v : m) {
        if (!v.is_string()) r.fail(key, fmt::format("must list metric names, got {}", io::dump_json(v)));
        const std::string metric = v.get<std::string>();
        try {
            (void)metric_info(metric);
        } catch (const InputError& e) {
            r.fail(key, e.what());
        }
        if (contains(out, metric)) r.fail(key, fmt::format("names '{}' twice", metric));
        out.push_back(metric);
    }
    return out;
}

// Whether the part varies a wall or excitation key.
auto varied_in(const PartSpec& p) {
    return [&p](const std::string& k) {
        const Axis* a = p.wall_axis(k) ? p.wall_axis(k) : p.excitation_axis(k);
        return a && a->varied();
    };
}

// one_at_a_time = [KEY, ...]: wall or excitation keys, each once. `varied(key)` says whether the grid varies it: a key it
// does not vary is refused when `strict` (a part's own list), skipped otherwise (the study's list, read for each part).
template <class Varied>
std::vector<std::string> read_one_at_a_time(const Reader& r, const json& v, const std::string& key, Varied varied,
                                            bool strict) {
    if (!v.is_array() || v.size() < 2)
        r.fail(key, fmt::format("must list two or more wall or excitation keys that vary (one key alone is the "
                                "product), got {}",
                                io::dump_json(v)));
    std::vector<std::string> out;
    for (const json& k : v) {
        if (!k.is_string()) r.fail(key, fmt::format("must list key names, got {}", io::dump_json(k)));
        const std::string name = k.get<std::string>();
        if (!contains(kWallKeys, name) && !contains(kExcitationKeys, name))
            r.fail(key, fmt::format("'{}' is not a wall or excitation key", name));
        if (contains(out, name)) r.fail(key, fmt::format("names '{}' twice", name));
        if (varied(name)) out.push_back(name);
        else if (strict) r.fail(key, fmt::format("'{}' is not given as a list: nothing to vary one at a time", name));
    }
    return out;
}

// One grid: the whole study's [wall] and [excitation] (where ""), or a [[part]]'s (where "part[N]").
// A record is scaled one way: by a factor (scale) or to a level of one intensity measure (pga, pgv, sa, arias); Sa's
// oscillator (sa_period, needed; sa_damping) goes with sa, or with a search that reports collapse_sa.
void check_record_scaling(const Reader& r, const json& ex, const std::string& ex_key) {
    std::vector<std::string> given;
    for (const char* k : {"scale", "pga", "pgv", "sa", "arias"})
        if (ex.contains(k)) given.push_back(k);
    if (given.size() > 1)
        r.fail(ex_key, fmt::format("give one of 'scale', 'pga', 'pgv', 'sa', 'arias' (how the record is scaled), not "
                                   "'{}' and '{}'",
                                   given[0], given[1]));
    const bool record = ex.value("kind", "") == "record";
    if (record && ex.contains("sa") && !ex.contains("sa_period"))
        r.fail(ex_key, "'sa' needs 'sa_period' (the oscillator's period, s)");
    for (const char* k : {"sa_period", "sa_damping"})
        if (record && ex.contains(k) && !ex.contains("sa"))
            r.fail(ex_key + "." + k, "is for 'sa' (the spectral acceleration's oscillator)");
}

// An ensemble's search reports its collapse intensity in its measure too (collapse_pga stays); a search's Sa
// oscillator (sa_period, needed; sa_damping) goes with the metric collapse_sa.
void add_collapse_intensity(const Reader& r, PartSpec& p, const json& ex, const std::string& ex_key) {
    if (p.ensemble && p.ensemble->collapse && p.ensemble->intensity != "pga" &&
        !contains(p.metrics, "collapse_" + p.ensemble->intensity))
        p.metrics.push_back("collapse_" + p.ensemble->intensity);
    if (p.kind != ExcitationKind::scale_to_collapse) return;
    const bool sa = contains(p.metrics, "collapse_sa");
    if (sa && !ex.contains("sa_period"))
        r.fail(ex_key, "the metric collapse_sa needs 'sa_period' (the oscillator's period, s)");
    for (const char* k : {"sa_period", "sa_damping"})
        if (!sa && ex.contains(k)) r.fail(ex_key + "." + k, "is for the metric collapse_sa (the search's Sa)");
}

PartSpec read_part(const Reader& r, const json& t, const std::string& where, const StudySpec& study) {
    PartSpec p;
    p.where = where;
    const auto key = [&](const std::string& k) { return where.empty() ? k : where + "." + k; };

    if (!t.contains("excitation")) r.fail(where, "no [excitation] table (kind = closed-form, threshold, free, ...)");
    const json& given = t["excitation"];
    const std::string ex_key = key("excitation");
    if (!given.is_object()) r.fail(ex_key, fmt::format("must be a table of keys, got {}", io::dump_json(given)));
    if (!given.contains("kind")) r.fail(ex_key, "'kind' is missing");
    json expanded;
    if (given["kind"] == "ensemble") {
        p.ensemble.emplace();
        expanded = read_ensemble(r, given, ex_key, study.base_dir, *p.ensemble);
    }
    const json& ex = p.ensemble ? expanded : given;
    p.kind = parse_kind(r, ex["kind"], ex_key + ".kind");
    const KindKeys keys = kind_keys(p.kind);
    std::vector<std::string> known = {"kind"};
    known.insert(known.end(), keys.allowed.begin(), keys.allowed.end());
    if (p.ensemble && p.ensemble->band) known.push_back("perturbation");
    r.unknown_keys(ex, fmt::format("{} (kind {})", ex_key, to_string(p.kind)), known);
    for (const std::string& k : keys.required)
        if (!ex.contains(k)) r.fail(ex_key, fmt::format("kind {} needs '{}'", to_string(p.kind), k));
    check_record_scaling(r, ex, ex_key);
    p.excitation = read_axes(r, ex, ex_key, kExcitationKeys, excitation_level);
    if (const Axis* shape = p.excitation_axis("shape")) {
        const bool harmonic = std::find(shape->levels.begin(), shape->levels.end(), Level{"harmonic"}) !=
                              shape->levels.end();
        if (harmonic != ex.contains("duration"))
            r.fail(ex_key, harmonic ? "shape harmonic needs 'duration' (s)"
                                    : "'duration' is for shape harmonic only (the pulses last one period, the "
                                      "Ricker wavelet three)");
    }

    const std::string wall_key = key("wall");
    if (!t.contains("wall")) r.fail(where, "no [wall] table");
    const json& wall = r.table(t, "wall", kWallKeys, wall_key);
    check_wall_routes(r, wall, wall_key);
    p.wall = read_axes(r, wall, wall_key, kWallKeys, wall_level);
    const Axis* model = p.wall_axis("model");
    const bool parapet_only = model && model->levels.size() == 1 && model->levels[0] == Level{"parapet"};
    const bool angles = wall.contains("alpha1") || wall.contains("specimen");
    if (!parapet_only && !angles && !wall.contains("hinge"))
        r.fail(wall_key, "a VSSW needs 'hinge' (h1/h, or \"eq15\")");
    if (model && angles &&
        std::find(model->levels.begin(), model->levels.end(), Level{"parapet"}) != model->levels.end())
        r.fail(wall_key, "alpha1-alpha2-R1 and specimen describe a VSSW: model must be vssw");

    // What the part measures: its own list, else the study's that its kind measures, else the kind's defaults.
    if (!where.empty() && t.contains("metrics")) {
        p.metrics = read_metrics(r, t["metrics"], key("metrics"));
        for (const std::string& metric : p.metrics)
            if (!kind_measures(p.kind, metric_info(metric)))
                r.fail(key("metrics"), fmt::format("'{}' is not measured by an excitation of kind {}", metric,
                                                   to_string(p.kind)));
    } else if (where.empty() && !study.metrics.empty()) {
        p.metrics = study.metrics;  // a study of one grid measures all it names (study_from_json checks it can)
    } else if (!study.metrics.empty()) {
        for (const std::string& metric : study.metrics)
            if (kind_measures(p.kind, metric_info(metric))) p.metrics.push_back(metric);
    } else {
        p.metrics = default_metrics(p.kind);
    }
    if (p.metrics.empty())
        r.fail(where, where.empty() ? "a closed-form study must name its metrics"
                                    : "measures none of the study's metrics: give it its own metrics");
    add_collapse_intensity(r, p, ex, ex_key);

    // The study's engines, with this part's settings where it gives them.
    p.engines = study.engines;
    if (!where.empty() && t.contains("settings")) {
        const json& st = t["settings"];
        if (!st.is_object()) r.fail(key("settings"), fmt::format("must be a table of engines, got {}", io::dump_json(st)));
        for (const auto& item : st.items()) {
            const auto it = std::find_if(p.engines.begin(), p.engines.end(),
                                         [&](const EngineSpec& e) { return e.name == item.key(); });
            const std::string k = key("settings." + item.key());
            if (it == p.engines.end()) r.fail(k, "settings for an engine the study does not run (add it to engines)");
            // Added to the study-wide settings of the engine; a setting given at both levels is refused.
            for (Axis& a : read_settings(r, item.value(), k, item.key())) {
                if (std::any_of(it->settings.begin(), it->settings.end(), [&](const Axis& x) { return x.key == a.key; }))
                    r.fail(k + "." + a.key, "given in the study's [settings." + item.key() + "] too: give it once");
                it->settings.push_back(std::move(a));
            }
            // dt, iterations, then the knobs by name, as read_settings orders them.
            std::stable_sort(it->settings.begin(), it->settings.end(), [](const Axis& a, const Axis& b) {
                const auto rank = [](const Axis& x) { return x.key == "dt" ? 0 : x.key == "iterations" ? 1 : 2; };
                return rank(a) != rank(b) ? rank(a) < rank(b) : (rank(a) == 2 && a.key < b.key);
            });
        }
    }

    if (t.contains("one_at_a_time"))  // a part's own, or a study of one grid's (the study's list is the part's)
        p.one_at_a_time = read_one_at_a_time(r, t["one_at_a_time"], key("one_at_a_time"), varied_in(p), true);
    if (!where.empty()) {
        for (auto [name, target] : {std::pair{"wall_name", &p.names.wall_name}, std::pair{"wall_label", &p.names.wall_label},
                                    std::pair{"record_name", &p.names.record_name},
                                    std::pair{"record_label", &p.names.record_label}})
            if (t.contains(name)) {
                if (!t[name].is_string() || t[name].get<std::string>().empty())
                    r.fail(key(name), fmt::format("must be a non-empty template, got {}", io::dump_json(t[name])));
                *target = t[name].get<std::string>();
                if (const auto why = template_too_wide(*target)) r.fail(key(name), fmt::format("\"{}\": {}", *target, *why));
            }
        if (t.contains("skip_falling_releases")) {
            if (!t["skip_falling_releases"].is_boolean())
                r.fail(key("skip_falling_releases"),
                       fmt::format("must be true or false, got {}", io::dump_json(t["skip_falling_releases"])));
            p.skip_falling_releases = t["skip_falling_releases"].get<bool>();
            if (p.skip_falling_releases && p.kind != ExcitationKind::free)
                r.fail(key("skip_falling_releases"), "is for kind free (a release from theta0)");
        }
    }
    return p;
}

}  // namespace

std::string to_text(const Level& level) {
    if (const auto* x = std::get_if<double>(&level)) return fmt::format("{}", *x);
    return std::get<std::string>(level);
}

const char* to_string(ExcitationKind kind) {
    switch (kind) {
        case ExcitationKind::closed_form: return "closed-form";
        case ExcitationKind::threshold: return "threshold";
        case ExcitationKind::free: return "free";
        case ExcitationKind::pulse: return "pulse";
        case ExcitationKind::record: return "record";
        case ExcitationKind::scale_to_collapse: return "scale-to-collapse";
    }
    return "unknown";
}

const Axis* PartSpec::wall_axis(const std::string& key) const {
    for (const Axis& a : wall)
        if (a.key == key) return &a;
    return nullptr;
}

const Axis* PartSpec::excitation_axis(const std::string& key) const {
    for (const Axis& a : excitation)
        if (a.key == key) return &a;
    return nullptr;
}

std::string PartSpec::kind_text() const { return ensemble ? "ensemble" : to_string(kind); }

std::vector<const Axis*> PartSpec::axes() const {
    std::vector<const Axis*> out;
    for (const Axis& a : wall) out.push_back(&a);
    for (const Axis& a : excitation) out.push_back(&a);
    return out;
}

double case_count(const std::vector<const Axis*>& axes, const std::vector<std::string>& one_at_a_time,
                  std::size_t from, bool left_baseline) {
    double others = 1.0, further = 0.0;
    for (std::size_t i = from; i < axes.size(); ++i) {
        const double n = static_cast<double>(axes[i]->levels.size());
        if (std::find(one_at_a_time.begin(), one_at_a_time.end(), axes[i]->key) != one_at_a_time.end())
            further += n - 1.0;
        else
            others *= n;
    }
    return others * (left_baseline ? 1.0 : 1.0 + further);
}

double case_count(const PartSpec& part) { return case_count(part.axes(), part.one_at_a_time); }

std::string StudySpec::kind_text() const {
    for (const PartSpec& p : parts)
        if (p.kind_text() != parts.front().kind_text()) return "mixed";
    return parts.empty() ? "" : parts.front().kind_text();
}

StudySpec study_from_json(const json& doc, const std::string& name, const std::string& base_dir) {
    const Reader r(name);
    if (!doc.is_object()) r.fail("", "the top level must be a table of keys");
    r.unknown_keys(doc, "", kTopKeys);

    StudySpec s;
    s.path = name;
    s.base_dir = base_dir;
    s.as_read = doc;
    if (doc.contains("name")) {
        if (!doc["name"].is_string() || doc["name"].get<std::string>().empty())
            r.fail("name", fmt::format("must be a non-empty string, got {}", io::dump_json(doc["name"])));
        s.name = doc["name"].get<std::string>();
    } else {
        s.name = std::filesystem::path(name).stem().string();
    }
    if (doc.contains("description")) {
        if (!doc["description"].is_string())
            r.fail("description", fmt::format("must be a string, got {}", io::dump_json(doc["description"])));
        s.description = doc["description"].get<std::string>();
    }

    read_assumptions(r, doc, s);
    s.engines = read_engines(r, doc);
    if (doc.contains("metrics")) s.metrics = read_metrics(r, doc["metrics"], "metrics");
    const bool analytic = std::any_of(s.engines.begin(), s.engines.end(),
                                      [](const EngineSpec& e) { return e.name == "analytic"; });

    if (doc.contains("part")) {
        if (doc.contains("wall") || doc.contains("excitation"))
            r.fail("", "give [wall] and [excitation], or [[part]] tables each with its own: not both");
        const json& parts = doc["part"];
        if (!parts.is_array() || parts.empty())
            r.fail("part", "must be a non-empty list of tables ([[part]] in TOML)");
        for (std::size_t i = 0; i < parts.size(); ++i) {
            const std::string where = fmt::format("part[{}]", i + 1);
            if (!parts[i].is_object()) r.fail(where, "must be a table of keys");
            r.unknown_keys(parts[i], where, kPartKeys);
            s.parts.push_back(read_part(r, parts[i], where, s));
        }
        // The study's one_at_a_time: each key varied in some part, applied to every part without its own list.
        if (doc.contains("one_at_a_time")) {
            std::vector<std::string> seen;
            for (std::size_t i = 0; i < s.parts.size(); ++i) {
                PartSpec& p = s.parts[i];
                const std::vector<std::string> keys =
                    read_one_at_a_time(r, doc["one_at_a_time"], "one_at_a_time", varied_in(p), false);
                for (const std::string& k : keys)
                    if (!contains(seen, k)) seen.push_back(k);
                if (!parts[i].contains("one_at_a_time")) p.one_at_a_time = keys;
            }
            for (const json& k : doc["one_at_a_time"])
                if (!contains(seen, k.get<std::string>()))
                    r.fail("one_at_a_time", fmt::format("'{}' is given as a list in no part: nothing to vary one at "
                                                        "a time", k.get<std::string>()));
        }
        // Every metric the study names is measured somewhere.
        for (const std::string& metric : s.metrics)
            if (std::none_of(s.parts.begin(), s.parts.end(), [&](const PartSpec& p) { return contains(p.metrics, metric); }))
                r.fail("metrics", fmt::format("'{}' is measured by no part's excitation", metric));
    } else {
        s.parts.push_back(read_part(r, doc, "", s));
        const PartSpec& only = s.parts.front();
        for (const std::string& metric : s.metrics)
            if (!kind_measures(only.kind, metric_info(metric)))
                r.fail("metrics", fmt::format("'{}' is not measured by an excitation of kind {}", metric,
                                              to_string(only.kind)));
        if (only.kind == ExcitationKind::closed_form &&
            std::any_of(s.engines.begin(), s.engines.end(), [](const EngineSpec& e) { return e.name != "analytic"; }))
            r.fail("engines", "a closed-form study runs no simulation: its engine is \"analytic\" only");
    }
    // The study's metrics: its own list first, then those parts add, each once.
    for (const PartSpec& part : s.parts)
        for (const std::string& metric : part.metrics)
            if (!contains(s.metrics, metric)) s.metrics.push_back(metric);
    for (const std::string& metric : s.metrics)
        if (metric_info(metric).analytic_only && !analytic)
            r.fail("metrics", fmt::format("'{}' is the analytic model's: add \"analytic\" to engines", metric));
    // An impact ratio of 0 stops the wall at its first return to upright. `vssw free` lists that impact from the
    // model's events, but a study measures impacts from the samples, as crossings of upright (the same code for every
    // engine), and finds none: every row failed "no impact within the run". Refused, saying why.
    const Axis& impact = s.assumptions[1];
    const bool stops = analytic && std::find(impact.levels.begin(), impact.levels.end(), Level{0.0}) != impact.levels.end();
    for (const PartSpec& part : s.parts)
        for (const std::string& metric : part.metrics)
            if (stops && metric_info(metric).source == compare::MetricSource::free)
                r.fail("assumptions.impact",
                       fmt::format("0 stops the wall at its first return to upright, where a study finds no impact "
                                   "to measure '{}' from (impacts are crossings of upright); use vssw free --impact 0 "
                                   "for that run, or a ratio above 0",
                                   metric));
    return s;
}

StudySpec read_study_file(const std::string& path) {
    const json doc = io::read_config_file(path, kWhat);
    const std::filesystem::path dir = std::filesystem::path(path).parent_path();
    return study_from_json(doc, path, dir.empty() ? std::string(".") : dir.string());
}

}  // namespace vssw::study
