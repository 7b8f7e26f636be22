#pragma once
// A study's grid: its cases and its runs.
//
// A case is one wall under one excitation: a combination of the levels of the [wall] and [excitation] keys (the
// Cartesian product, the last key varying fastest in kWallKeys then kExcitationKeys order). Its id is its 1-based
// position in that product (a study of several parts numbers each part's cases after the previous part's), so ids and
// order depend on the file alone, never on threads, shards or processes. Keys varied one at a time (one_at_a_time)
// leave out the combinations off the first level of two of them, their ids unused; a part whose product is beyond
// ints, but not its cases (8 keys of 16 levels: 121 cases of 16^8), numbers its cases one after the other instead, in
// the same order. A case that would repeat another is left out and its id unused: a parapet has no hinge, so only
// the first hinge level gives parapet cases; a part that asks for it leaves out the releases from which the analytic
// model (exact kinematics) falls.
//
// A run is what is done to every case: the analytic model under one combination of the assumptions (and of its
// settings), or one engine under one combination of its settings. Engines ignore the assumptions (their physics is
// their own), so each engine runs once per case, its assumption columns empty. The paper's kinematics with the
// unilateral roller is not a model (the roller needs Eq. 2) and is not run (Grid::skipped_runs says so); on a parapet
// only the first kinematics and roller levels run (it has neither). An ensemble's sensitivity band (spec.hpp) is the
// analytic model's alone: its perturbed cases are not run by engines (run_applies; skipped_runs says so).
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "analytic/ground_motion.hpp"
#include "analytic/intensity_measures.hpp"
#include "analytic/model.hpp"
#include "analytic/simulate.hpp"
#include "analytic/specimens.hpp"
#include "compare/experiments.hpp"
#include "multibody/host/analytic_engine.hpp"
#include "multibody/engine.hpp"
#include "study/spec.hpp"

namespace vssw::study {

struct RunSpec {
    std::size_t part = 0;  // the part whose cases it runs on (StudySpec::parts)
    std::string engine;
    std::vector<Level> assumptions;  // the analytic model's, one per StudySpec::assumptions; empty for an engine
    multibody::EngineSettings settings;  // the engine's defaults with the file's settings (and assumptions) applied
    std::string settings_text;           // the file's settings of this run, "dt=0.0002 iterations=10"; "" if none
    // For the analytic model: the assumptions as the model takes them.
    Kinematics kinematics = Kinematics::paper;
    ImpactLaw impact;
    Roller roller = Roller::bilateral;
};

struct CaseSpec {
    int id = 0;                     // 1-based position in the product (of all parts; see above)
    std::size_t part = 0;           // StudySpec::parts
    std::vector<Level> levels;      // one per wall axis, then one per excitation axis (StudySpec order)
    multibody::WallScene scene;
    std::string model;              // "vssw" or "parapet"
    double height = 0.0, thickness = 0.0, hinge = 0.0;  // full dimensions [m], h1/h (NaN for a parapet)
    double xi = 0.0, density = 0.0, g = 0.0;
    double alpha = 0.0, R = 0.0;    // the whole wall's slenderness atan(b/h) and half-diagonal (Fig. 10's alpha, R)
    double theta0 = 0.0;            // release, a fraction of alpha (free, closed-form; 0 when not given)
    std::string file;               // record or scale-to-collapse: the record as the file names it
    std::string record_key;         // the record as read (the file and its units): Grid::record
    double scale = 1.0;             // record: the factor applied to it
    double pga_g = 0.0;             // record: its peak ground acceleration after scaling [g]
    // record, scale-to-collapse: the intensity measure its level is given in (pga, or the part's pgv, sa, arias key)
    // with Sa's oscillator (sa_period, sa_damping), and the record's value of it after scaling (a record scaled to a
    // pgv, sa or arias level; NaN otherwise), in the measure's unit.
    Intensity intensity;
    double intensity_value = std::numeric_limits<double>::quiet_NaN();
    std::string shape;              // pulse
    double amplitude_g = 0.0, pulse_period = 0.0, duration = 0.0;  // pulse [g], [s], harmonic [s]
    double tolerance = 0.0, max_pga_g = 0.0, step = 0.0;  // scale-to-collapse; 0: the defaults (measure.cpp)
    std::string perturbation;       // an ensemble's band: a kPerturbations level ("" without a band)
    // pulse, record, scale-to-collapse: how long a run goes on after the motion ends [s] (earlier at rest or
    // overturning): the file's [excitation] response_tail, else a study's answer, compare::kResponseTail; the
    // validation suite's is kSuiteResponseTail (compare/experiments.hpp says why two).
    double response_tail = compare::kResponseTail;
    // The wall's position among its part's wall axes alone (cases that differ only in their excitation share it):
    // with the part and the run, the key of a threshold task (study/runner.cpp: one per wall and run in a shard).
    std::size_t wall_index = 0;
};

// The ground motion of a pulse case (its shape, amplitude in g, period and duration), as `vssw history` builds it:
// InputError where the library refuses it.
GroundMotion pulse_motion(const CaseSpec& c);

// The steps of building a case that a case built outside a study file (vssw compare under a ground motion) shares:
// the wall's columns from its scene (model, height, thickness, hinge, xi, density, g, alpha, R); a record's scale
// (the factor given, or the one that brings it to pga_g) and its PGA after scaling; InputError naming the file when
// a record is zero everywhere; an analytic run's assumptions set in its RunSpec and its settings, false (and why in
// `skipped`, with `roller_source` when given: how the unilateral roller came to be chosen) when they are not a model;
// the assumptions of a run's levels (kinematics, impact, roller) and back.
void describe_wall(CaseSpec& c);
void scale_record(CaseSpec& c, const GroundMotion& record, std::optional<double> pga_g, double scale);
void require_shakes(const GroundMotion& record, const std::string& file);
bool apply_assumptions(RunSpec& run, const multibody::AnalyticAssumptions& assumptions,
                       std::vector<std::string>& skipped, const std::string& roller_source = "");
multibody::AnalyticAssumptions assumptions_of(const std::vector<Level>& levels);
std::vector<Level> assumption_levels(const multibody::AnalyticAssumptions& assumptions);

// What the grid writes in a results column (defined in grid.cpp, where the columns are written).
enum class ColumnCode : int;

class Grid {
public:
    // Builds every case's wall and every run's settings, checking them (InputError naming the file, the case's
    // levels and the bad value), and reads every record once (a missing or malformed one: InputError).
    explicit Grid(const StudySpec& spec);
    // A grid of one case built and checked by the caller (vssw compare under a record or a pulse): `spec` holds one
    // part, of that excitation's kind, with no axes; `runs` are run as given; `record` is the case's record as read
    // (unscaled), found by the case's record_key (none for a pulse). make_case(1) gives the case back.
    Grid(StudySpec spec, const CaseSpec& one, std::vector<RunSpec> runs, const GroundMotion& record);
    // Not copied: its parts' axes point into its own study.
    Grid(const Grid&) = delete;
    Grid& operator=(const Grid&) = delete;

    const StudySpec& spec() const { return spec_; }
    std::size_t product_size() const { return product_size_; }  // every part's ids: its product, or its cases
    const std::vector<int>& case_ids() const { return case_ids_; }  // the cases that run, in order
    CaseSpec make_case(int id) const;
    const std::vector<RunSpec>& runs() const { return runs_; }
    bool run_applies(const RunSpec& run, const CaseSpec& c) const;
    const std::vector<std::string>& skipped_runs() const { return skipped_runs_; }  // why, one line each
    // The case's record (read once, unscaled, in m/s^2).
    const GroundMotion& record(const CaseSpec& c) const;

    // The parameter columns (between `engine` and `metric` in results.csv) and their values for a case and a run.
    const std::vector<std::string>& columns() const { return columns_; }
    std::vector<std::string> column_values(const CaseSpec& c, const RunSpec& run) const;
    // The parameters that vary: the varied axes of the wall, the excitation and the assumptions, in column order.
    std::vector<std::string> varied_parameters() const;

    // A part's names of the case's wall and record, from its templates ("" when the part has none; InputError naming
    // the part and the key on a template that does not format).
    std::string wall_name(const CaseSpec& c) const;
    std::string wall_label(const CaseSpec& c) const;
    std::string record_name(const CaseSpec& c) const;
    std::string record_label(const CaseSpec& c) const;
    // The record as a path (relative ones from the study file's folder).
    std::string record_path(const std::string& file) const;

    // A hash of the study as read (FNV-1a 64 of its canonical JSON): results, journals and shards name the study by
    // it, so that a resume or a merge cannot mix two studies.
    const std::string& identity() const { return identity_; }

    // Deterministic 1/n of the cases for shard k (1-based): every n-th case from the k-th.
    std::vector<int> shard_case_ids(int k, int n) const;

private:
    struct PartGrid {
        std::vector<const Axis*> axes;  // wall axes, then excitation axes
        std::vector<std::string> one_at_a_time;  // the part's keys varied one at a time
        std::vector<bool> alone;                 // per axis: whether it is one of them
        std::size_t size = 1, first = 1;  // its ids: how many (its product's size, or its cases') and the first
        bool numbered = false;            // its ids are its cases one after the other, not positions in the product
        std::vector<int> column_axis;     // per column of columns(): the axis that gives it, -1 when none does
    };
    // The levels (an index into each axis's) of a part's case `index` (its id - first).
    std::vector<std::size_t> levels_at(const PartGrid& g, std::size_t index) const;
    struct CaseLevels;
    std::string render(const std::string& tmpl, const CaseSpec& c, const char* key) const;
    const PartGrid& part_of(int id, std::size_t& index) const;
    std::string where(const PartSpec& part, const std::string& key) const;  // "study file s.toml: part[2].key"
    // The constructor's steps, in order.
    void read_specimens(std::string& identity_text);
    void size_parts();
    void read_records(std::string& identity_text);
    void build_runs();
    std::string roller_source() const;
    void list_cases();
    void list_columns();
    // make_case's steps.
    CaseLevels case_levels(CaseSpec& c) const;
    void build_wall(CaseSpec& c, const CaseLevels& levels) const;
    void set_excitation(CaseSpec& c, const CaseLevels& levels) const;

    StudySpec spec_;
    std::vector<PartGrid> parts_;
    std::size_t product_size_ = 0;
    std::vector<int> case_ids_;
    std::vector<RunSpec> runs_;
    std::vector<std::string> skipped_runs_;
    std::map<std::string, GroundMotion> records_;
    std::vector<Specimen> table1_;  // read when the study names specimens
    std::map<std::size_t, std::pair<Level, Level>> parapet_run_;  // per part: the kinematics and roller levels a
                                                                  // parapet's analytic runs use
    std::vector<std::string> columns_;
    std::vector<ColumnCode> column_codes_;  // per column: what column_values writes in it
    std::string identity_;
    std::optional<CaseSpec> one_case_;  // a grid of one case built by the caller
};

}  // namespace vssw::study
