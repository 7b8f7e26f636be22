#pragma once
// A study's results as its plots, prose and results.json read them: the manifest and the rows of results.csv, never
// the Grid, so that one run, a resumed run and a merge of shards are written by the same code from the same data. The
// rows come from DIR/results.csv (read_study_data: a merge, a resumed study whose results were complete) or from the
// run that has just written that file (StudyDataBuilder fed by write_results_csv): one builder, two sources of rows.
//
// Rows keep their parameter columns as level ids (the columns repeat a few texts over many rows). An empty column is
// a parameter that does not apply to the row: a parapet has no hinge, kinematics or roller; an engine has none of the
// analytic model's assumptions. The writers let such a row stand at every level of that parameter where they draw or
// match lines (a parapet's value in every hinge panel, an engine's in every kinematics series), and leave it out where
// they pair runs that differ in that parameter alone (it has no such pair).
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "io/json.hpp"

namespace vssw::study {

// The level id of an empty field in every column.
constexpr std::uint32_t kEmptyLevel = 0;

struct ColumnLevels {
    std::string key;                  // as in results.csv: "engine", "hinge", "kinematics", "settings", ...
    std::vector<std::string> texts;   // by level id; texts[kEmptyLevel] is ""
    std::vector<double> values;       // the texts as numbers (NaN for words and "")
    std::vector<std::uint32_t> order; // the non-empty levels in the study's order (the file's: first appearance;
                                      // assumptions in the order of the manifest's runs)
    bool numeric = false;             // every non-empty level a number, and the column a quantity (not an id)
    bool assumption = false;          // kinematics, impact, roller
    bool physical = false;            // one of the paper's physical assumptions relaxed (kPhysicalAssumptionKeys)
    bool varied = false;              // in the manifest's "varied"
};

struct MetricMeta {
    std::string name, unit, description;
    bool binary = false;  // every finite value 0 or 1 (overturned): effects are shares of runs that flip
    bool any_value = false;
    // A slip (in b): about 0 at the paper's friction, so a change relative to it is noise, not a cost; the tornado
    // charts and the report's relaxations show its values instead.
    bool is_slip() const { return unit == "b"; }
};

// A run of the study (the manifest's "runs"): one line in a plot.
struct Series {
    std::string engine, settings;
    std::vector<std::string> assumptions;  // one per kAssumptionKeys; all "" for an engine
    std::string set;                       // the manifest's: paper, mechanism or custom; "" for an engine
    std::string label;                     // "analytic kinematics=exact", "ODE dt=0.0002"
    bool analytic() const { return engine == "analytic"; }
};

// A field of results.csv kept as the file gives it (every column but case_id, metric, value, status and warnings):
// results.json writes it as it is, where the parameter columns' levels are made canonical.
struct RawColumn {
    std::size_t field = 0;                    // its place in the header
    std::vector<std::string> texts;           // by raw id, each distinct text once
    std::size_t level_column = std::string::npos;  // its column of StudyData::columns, npos for none (unit)
    std::vector<std::uint32_t> level;         // by raw id: the level id in that column
};

struct StudyRow {
    int case_id = 0;
    std::uint32_t metric = 0;         // index into StudyData::metrics
    double value = 0.0;               // NaN: empty (failed, or nothing to measure)
    std::uint32_t status = 0;         // index into StudyData::statuses ("ok", "failed: <reason>")
    std::uint32_t warning = 0;        // index into StudyData::warnings (0: none)
    std::vector<std::uint32_t> levels;  // one per StudyData::columns
    std::vector<std::uint32_t> raw;     // one per StudyData::raw_columns: the field's text as results.csv gives it
};

struct StudyData {
    io::Json manifest;
    std::string name, description, kind;
    std::vector<ColumnLevels> columns;  // engine, then the grid's parameter columns up to settings
    std::vector<std::string> header;    // results.csv's header line
    std::vector<RawColumn> raw_columns;  // in header order
    std::vector<std::size_t> assumption_columns;  // the column of each of kAssumptionKeys (npos when absent)
    std::vector<MetricMeta> metrics;
    std::vector<Series> series;
    std::vector<StudyRow> rows;
    std::vector<std::string> statuses;  // the status column's texts, interned (a row's reason, e.g. a censored IDA)
    std::vector<std::string> warnings = {""};  // the warnings column's texts, interned; [0] is a row without
    long failed_rows = 0, warned_rows = 0, warned_tasks = 0;
    std::map<std::string, long> failure_reasons;  // failure_reason() of each failed row, and how many rows

    // Index of a column; npos when the study has none of that name.
    std::size_t column(const std::string& key) const;
    const std::string& text(const StudyRow& row, std::size_t column) const {
        return columns[column].texts[row.levels[column]];
    }
    // The varied parameters (wall, excitation, assumptions) in column order.
    std::vector<std::size_t> varied() const;
    // Whether the row belongs to the series: its engine and settings, and each assumption equal or not applying.
    // Assumption columns listed in `ignored` are not compared (a plot that has them on its x axis).
    bool in_series(const StudyRow& row, const Series& s, const std::vector<std::size_t>& ignored = {}) const;
    // "analytic kinematics=exact impact=eq19", "ODE dt=0.0002": the varied assumptions not in `ignored`, the settings.
    std::string series_label(const Series& s, const std::vector<std::size_t>& ignored = {}) const;
};

// Whether a status is a failed row's ("failed: <reason>"), and its reason (the status without "failed: ").
bool is_failed(const std::string& status);
std::string failure_reason(const std::string& status);

// DIR/manifest.json and DIR/results.csv (InputError naming the file when either is missing or malformed).
StudyData read_study_data(const std::filesystem::path& dir);

// A study's data built row by row from results.csv's fields: those read from the file, or those its writer has
// just written (so that a run does not read back what it wrote).
class StudyDataBuilder {
public:
    // results.csv's header and the manifest's metric names, in its order (InputError for a header without one of
    // the columns the data needs).
    StudyDataBuilder(std::vector<std::string> header, std::vector<std::string> metrics);
    // Not copied: the interners point into this builder's data, which a copy would share and write into.
    StudyDataBuilder(const StudyDataBuilder&) = delete;
    StudyDataBuilder& operator=(const StudyDataBuilder&) = delete;
    StudyDataBuilder(StudyDataBuilder&&) = default;
    StudyDataBuilder& operator=(StudyDataBuilder&&) = default;
    // One row's fields, one per header column (InputError for a malformed one). same_columns: the row's case and run
    // are the last row's, so its parameter fields are too (the writer knows; a file's reader passes false).
    void add(const std::vector<std::string>& fields, bool same_columns = false);
    // The data, with the manifest whose metrics were given (InputError when it is not a study manifest).
    StudyData finish(io::Json manifest);

private:
    StudyData d_;
    std::vector<std::string> metric_names_;
    std::size_t case_id_ = 0, first_ = 0, metric_ = 0, value_ = 0, status_ = 0, warnings_ = 0;
    struct Interners;
    std::shared_ptr<Interners> interners_;  // the raw columns' and the texts' indexes
    std::vector<std::uint32_t> last_raw_;  // the last row's raw fields (its parameters repeat in the next row)
    std::set<std::tuple<int, std::vector<std::uint32_t>>> warned_tasks_;
};

// Parameter and its unit for axis labels ("height [m]", "amplitude [g]"; a word parameter as it is).
std::string parameter_label(const std::string& key);
// A metric for axis labels and sentences ("peak_rotation [alpha1]", "restitution").
std::string metric_label(const MetricMeta& metric);

}  // namespace vssw::study
