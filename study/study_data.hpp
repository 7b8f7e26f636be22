#pragma once
// A study's results as its plots and prose read them: DIR/manifest.json and DIR/results.csv, never the Grid, so that
// one run, a resumed run and a merge of shards are written by the same code from the same two files.
//
// Rows keep their parameter columns as level ids (the columns repeat a few texts over many rows). An empty column is
// a parameter that does not apply to the row: a parapet has no hinge, kinematics or roller; an engine has none of the
// analytic model's assumptions. The writers let such a row stand at every level of that parameter where they draw or
// match lines (a parapet's value in every hinge panel, an engine's in every kinematics series), and leave it out where
// they pair runs that differ in that parameter alone (it has no such pair).
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
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

struct StudyRow {
    int case_id = 0;
    std::uint32_t metric = 0;         // index into StudyData::metrics
    double value = 0.0;               // NaN: empty (failed, or nothing to measure)
    std::uint32_t status = 0;         // index into StudyData::statuses ("ok", "failed: <reason>")
    std::uint32_t warning = 0;        // index into StudyData::warnings (0: none)
    std::vector<std::uint32_t> levels;  // one per StudyData::columns
};

struct StudyData {
    io::Json manifest;
    std::string name, description, kind;
    std::vector<ColumnLevels> columns;  // engine, then the grid's parameter columns up to settings
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

// Parameter and its unit for axis labels ("height [m]", "amplitude [g]"; a word parameter as it is).
std::string parameter_label(const std::string& key);
// A metric for axis labels and sentences ("peak_rotation [alpha]", "restitution").
std::string metric_label(const MetricMeta& metric);

}  // namespace vssw::study
