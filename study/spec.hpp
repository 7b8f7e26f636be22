#pragma once
// A study file as the program holds it: what varies (walls, the analytic model's assumptions, the excitation, the
// engines' settings), what is run (engines) and what is measured (metrics). Read from TOML or JSON (the same keys);
// every key given as a list varies, a scalar is fixed, and the grid is their Cartesian product (study/grid.hpp).
//
//   name = "hinge-and-overburden"
//   metrics = ["threshold_g", "period", "restitution"]
//   engines = ["analytic", "ode"]            # or [engines.ode] dt = 2e-4 (a table of engines with their settings)
//   [wall]          model, height, thickness, hinge, xi, overburden_eccentricity, density, g, corner_radius, friction (the
//                   base's, and the hinge's unless hinge_friction; given, the engines measure sliding), diaphragm_period,
//                   diaphragm_damping (the VSSW's top support: analytic/diaphragm.hpp) (or alpha and R;
//                   alpha1, alpha2 and R1;
//                   specimen: a Table 1 number, data/table1.csv)
//   [assumptions]   set (paper | mechanism, default mechanism: analytic/assumption_sets.hpp), one name, never a list;
//                   kinematics (paper | exact), impact (eq19 | whole-mechanism | a number in [0, 1]), roller
//                   (bilateral | unilateral), each the set's unless given: the analytic model's; engines ignore them
//   [excitation]    kind = closed-form | threshold | free | pulse | record | scale-to-collapse | ensemble, and its keys
//   [settings.ode]  dt = 2e-4, iterations, knobs by name (a list varies them)
//
// one_at_a_time = ["overburden_eccentricity", "xi"] (the study's or a part's): those keys vary one at a time from
// their first level, the rest of the grid crossed with each: a baseline and one case per other level of each, not their
// product (what a sensitivity or tornado study needs: study/effects.hpp pairs each case with its baseline).
//
// A study may instead be several grids, each a [[part]] with its own [part.wall], [part.excitation] (any kind),
// optional metrics and [part.settings.ENGINE], sharing the study's engines and assumptions; its cases follow the
// previous part's. A part can name its walls and records (wall_name, wall_label, record_name, record_label: templates
// such as "t1-{specimen:02}-xi{xi}") and leave out the releases from which the analytic model falls
// (skip_falling_releases): what a validation suite needs (studies/validation-default.toml; validation/suite_file.hpp).
//
// kind = "ensemble" is a record study over many records, read here into the kinds that run it: files = [...] (from the
// study file's folder) or ensemble = "DIR" (DIR's *.at2 files, any case, and the files a records.csv or motions.csv
// in DIR lists in its `file` column; each once, in name order), intensity = "pga" | "pgv" | "sa" | "arias" (sa with
// sa_period and optional sa_damping), and levels = [...] in the measure's unit (a stripe analysis: kind record with
// file x the measure's key, e.g. pgv) or collapse = true (incremental dynamic analysis: kind scale-to-collapse over
// the files, with its max_pga, step, tolerance, which stay a PGA ceiling and relative steps of the scale; the
// metrics gain collapse_<intensity>, collapse_pga stays). The ids, runs and rows are those of that study but for the `kind`
// column ("ensemble"); PartSpec::ensemble remembers the rest. band = true (stripes only) adds the excitation axis
// `perturbation` (kPerturbations): the analytic model's repeats of each case perturbed as the free-vibration targets
// allow (band_factors below), which engines do not run (Grid::run_applies).
//
// Everything is checked here or when the grid is built, before any case runs: an unknown key, a value of the wrong
// type, an empty list, an engine not built, a metric the excitation cannot measure, a record that does not read:
// InputError naming the file, the key and the value.
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "analytic/assumption_sets.hpp"

namespace vssw::study {

// One level of a parameter: a number, or a word (a model, a kinematics, an impact law, a file, "eq15").
using Level = std::variant<double, std::string>;
// As written in results: a number in its shortest exact form ("0.356", "2e-04" becomes "0.0002"), a word as it is.
std::string to_text(const Level& level);

// A parameter and its levels, in the file's order (one level when the file gives a scalar).
struct Axis {
    std::string key;
    std::vector<Level> levels;
    bool varied() const { return levels.size() > 1; }
};

enum class ExcitationKind { closed_form, threshold, free, pulse, record, scale_to_collapse };
const char* to_string(ExcitationKind kind);  // as in the file: "closed-form", "scale-to-collapse", ...

// An engine of the study and the settings the file gives it (dt, iterations, knobs by name), each an axis.
struct EngineSpec {
    std::string name;
    std::vector<Axis> settings;  // dt first, then iterations, then knobs by name
};

// The keys each table may hold, in the order their columns appear in results.csv.
// kWallKeys is the order of the product too: geometry first (model, specimen, height, thickness, alpha, R, alpha1,
// alpha2, R1), then hinge, xi, density, g.
extern const std::vector<std::string> kWallKeys;
extern const std::vector<std::string> kAssumptionKeys;  // kinematics, impact, roller
// The wall keys that relax one of the paper's physical assumptions (N at the centreline, ...), whose first level in a
// study is the paper's: model and engines both follow them, and their tornado charts say what each assumption costs.
extern const std::vector<std::string> kPhysicalAssumptionKeys;
extern const std::vector<std::string> kExcitationKeys;  // theta0, file, units, scale, pga, pgv, sa, arias, shape, ...
// The keys that scale a record to a level of an intensity measure (analytic/intensity_measures.hpp), each the measure's
// word: pga [g], pgv [m/s], sa [g] at sa_period [s] and sa_damping (default 0.05), arias [m/s]. A record part gives at
// most one of them or `scale`; an ensemble's `intensity` names one, and its levels become that key's.
extern const std::vector<std::string> kLevelKeys;

// The sensitivity band's perturbations of an ensemble's stripe case, the `perturbation` axis's levels in order: none,
// "as close as the free-vibration targets allow" (docs/earthquakes.md, "Verdicts": the band): the intensity x (1 +- kBandIntensityStep), every impact's
// velocity ratio x (1 +- kBandRestitutionStep) (the analytic backend's restitution_error) and the wall's height and
// thickness x (1 +- kBandSizeStep) at the same slenderness and hinge (R x (1 +- 1 %): the rocking frequency
// p ~ R^-1/2 moves -+0.5 %, the threshold stays). Engines run "none" only.
extern const std::vector<std::string> kPerturbations;
constexpr double kBandIntensityStep = 1e-2;    // the intensity's own uncertainty (docs/earthquakes.md)
constexpr double kBandRestitutionStep = 2e-2;  // the free-vibration restitution target, +-2 %
constexpr double kBandSizeStep = 1e-2;         // the period target +-0.5 %, as R +-1 %
// A perturbation's factors: on the PGA, on every impact's ratio (1 + restitution_error), on the wall's size.
struct BandFactors {
    double intensity = 1.0, restitution_error = 0.0, size = 1.0;
};
BandFactors band_factors(const std::string& perturbation);

// What an ensemble part was in the file (kind = "ensemble"), read into a record or scale-to-collapse part.
struct EnsembleSpec {
    std::string intensity = "pga";  // the intensity measure of the levels or the collapse: a kLevelKeys word
    bool collapse = false;          // true: incremental dynamic analysis (scale-to-collapse); false: stripes at levels
    bool band = false;              // stripes: the perturbation axis (the analytic model's sensitivity band)
    std::string folder;             // ensemble = "DIR" as given; "" when the file lists its records (files)
};

// Templates naming a part's walls and records ("" when not given): {key} or {key:format} (fmt's format spec) with the
// case's wall and excitation values (height, thickness, hinge, xi, specimen, scale, ... as results.csv has them).
struct NameTemplates {
    std::string wall_name, wall_label, record_name, record_label;
};

// One grid: the whole study, or one [[part]] of it.
struct PartSpec {
    std::string where;  // how messages name it: "" for a study of one grid, "part[2]" for the second part
    ExcitationKind kind = ExcitationKind::free;
    std::vector<Axis> wall;        // in kWallKeys order, only the keys given (defaults are the grid's)
    std::vector<Axis> excitation;  // in kExcitationKeys order, only the keys given
    std::vector<std::string> metrics;  // what this part measures: its own list, else the study's that its kind measures
    std::vector<EngineSpec> engines;   // the study's engines, each with this part's settings where it gives them
    NameTemplates names;
    bool skip_falling_releases = false;  // free: leave out a release from which the analytic model (exact) falls
    // Wall and excitation keys varied one at a time from their first level (a sensitivity design): a case whose levels
    // leave the first level in more than one of them is left out of the product (Grid::list_cases). The study's
    // `one_at_a_time`, else the part's own. Empty: the whole product.
    std::vector<std::string> one_at_a_time;
    std::optional<EnsembleSpec> ensemble;  // kind = "ensemble" in the file (kind is then record or scale-to-collapse)

    // As results.csv's `kind` column and results.json say it: "ensemble" for an ensemble, else to_string(kind).
    std::string kind_text() const;
    // Its wall axes, then its excitation axes: the order of its grid (the last fastest).
    std::vector<const Axis*> axes() const;

    const Axis* wall_axis(const std::string& key) const;        // nullptr when not given
    const Axis* excitation_axis(const std::string& key) const;  // nullptr when not given
};

// The cases of a grid before repeats are left out: the product of the axes' levels, but the keys varied one at a time
// give a baseline and one case per further level of each: (the product of the other axes' levels) x (1 + the sum of
// their levels - 1). The cases still to list after the first `from` axes are chosen count the same way, the keys
// varied one at a time held at their first level when one of them before `from` has left it (`left_baseline`). A
// double: exact below 2^53, far beyond any grid that is run (case ids are ints).
double case_count(const std::vector<const Axis*>& axes, const std::vector<std::string>& one_at_a_time,
                  std::size_t from = 0, bool left_baseline = false);
double case_count(const PartSpec& part);

struct StudySpec {
    std::string name;
    std::string description;
    std::string path;      // the file as named ("" for a study built in memory)
    std::string base_dir;  // where relative record paths start: the study file's folder
    nlohmann::json as_read;  // the file's content as read (TOML as the JSON it stands for): results.json keeps it
    std::vector<std::string> metrics;  // every part's, the study's own list first
    std::vector<EngineSpec> engines;   // in the file's order, with the study-wide settings
    AssumptionSet assumption_set = kDefaultAssumptionSet;  // [assumptions] set: the defaults of the keys below
    std::vector<Axis> assumptions;     // every key of kAssumptionKeys, the set's where the file gives none
    std::vector<std::string> assumptions_given;  // the keys of kAssumptionKeys the file gives (the rest: the set's)
    std::vector<PartSpec> parts;       // one for a study of one grid

    // The excitation kind of every part ("free", "ensemble"), or "mixed".
    std::string kind_text() const;
};

// Reads and checks a study file (.toml or .json).
StudySpec read_study_file(const std::string& path);
// The same from a document already parsed; `name` stands for the file in messages, `base_dir` for its folder.
StudySpec study_from_json(const nlohmann::json& doc, const std::string& name, const std::string& base_dir);

}  // namespace vssw::study
