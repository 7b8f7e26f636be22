#pragma once
// Writes every output of `vssw report` into one folder:
//   DIR/report.md, DIR/report.html, DIR/results.json, DIR/metrics.csv, DIR/failures.csv, DIR/traces.csv,
//   DIR/plots/{trace,error,step}_*.{svg,gp,dat}
// (see report_data.hpp for the JSON keys and CSV columns, report_plots.hpp for the plots).
#include <filesystem>
#include <string>
#include <vector>

#include "validation/report.hpp"
#include "validation/report_plots.hpp"

namespace vssw::validation {

struct ReportOptions {
    bool plots = true;  // false: --no-plots
    PlotOptions plot;
    // --bench: a finished `vssw bench` folder whose section (validation/bench_files.hpp) ends the report; empty: none.
    std::string bench_dir;
    // The earthquake part (validation/earthquake.hpp), already run into the folder's earthquake/; nullptr: none.
    const EarthquakePart* earthquake = nullptr;
    // The relaxations of the paper's assumptions (validation/assumptions_part.hpp), run into relaxations/; nullptr: none.
    const AssumptionsPart* relaxations = nullptr;
};

struct ReportFiles {
    std::filesystem::path dir, markdown, html, json;
    bool plots_made = false;
    std::vector<std::string> warnings;       // for stderr, one line each (e.g. gnuplot missing)
    std::vector<std::string> summary_lines;  // one per engine
};

// Creates dir if missing and checks that a file can be written in it; InputError naming the path otherwise (a file
// that is not a folder, no permission). Called before the suite runs, so a bad --out fails at once.
void prepare_report_dir(const std::filesystem::path& dir);

// Writes everything; meta.date and meta.commit as given (the plot fields are filled in here). InputError naming the
// file when one cannot be written. A missing or failing gnuplot is not an error: see ReportFiles::warnings.
ReportFiles write_suite_report(const std::filesystem::path& dir, const Suite& suite,
                               const SuiteResults& results, ReportMeta meta, const ReportOptions& options);

}  // namespace vssw::validation
