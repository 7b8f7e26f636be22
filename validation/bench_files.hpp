#pragma once
// What `vssw bench` writes into its folder (validation/work_precision.hpp runs the sweep): bench.json, bench.csv and
// bench.md, each through AtomicFile, and plots/wp_<problem>_<metric>.{gp,dat,svg}, the work-precision diagrams
// (log-log error against CPU time, one line per engine, the Pareto front circled, the target dashed).
#include <filesystem>
#include <string>
#include <vector>

#include "validation/work_precision.hpp"
#include "io/document.hpp"
#include "io/gnuplot.hpp"
#include "io/json.hpp"

namespace vssw::validation {

struct BenchMeta {
    std::string date;    // ISO 8601 UTC
    std::string commit;  // vssw's git commit, empty when unknown
    std::string load;    // the machine's load average when the bench started (/proc/loadavg), empty when unknown
    int repeats = 1;
    bool quick = false;
    std::vector<std::string> engines, problems;
};

struct BenchData {
    BenchMeta meta;
    std::vector<BenchPoint> points;
    std::vector<bool> pareto;  // per point: on the Pareto front of its problem and metric (all engines)
    std::vector<Cheapest> cheapest;
};

// The Pareto flags and the cheapest settings of a finished sweep.
BenchData bench_data(BenchMeta meta, std::vector<BenchPoint> points);

// The CSV's header, in its column order (the tests check the file against it).
std::vector<std::string> bench_csv_columns();
io::Json bench_json(const BenchData& data);
// The per-engine table of the cheapest settings within the targets, in Markdown (bench.md and `vssw bench`'s output).
std::string cheapest_markdown(const BenchData& data);
// The plot scripts, one per problem and metric with at least one finite, positive error.
std::vector<io::PlotScript> bench_plot_scripts(const BenchData& data);

// Writes bench.json, bench.csv, bench.md and the plots (unless `gnuplot` is empty) into `dir` (created). The result
// says which plots were made and, when gnuplot failed or is missing, why (a warning: the data are written anyway).
io::PlotResult write_bench(const BenchData& data, const std::filesystem::path& dir, const std::string& gnuplot);

}  // namespace vssw::validation

namespace vssw::validation {

// The validation report's section on a finished bench folder (`vssw report --bench DIR`; the report never runs the
// sweep itself, it would take minutes): a heading, when and where the bench ran, the cheapest settings per engine
// from DIR/bench.json, and DIR/plots/wp_*.svg copied into `plots_dir` and shown. InputError naming the file when
// DIR/bench.json is missing or not a bench's.
std::vector<io::DocBlock> bench_report_blocks(const std::filesystem::path& bench_dir,
                                          const std::filesystem::path& plots_dir);
// The same checks without writing anything (before the suite runs).
void check_bench_dir(const std::filesystem::path& bench_dir);

}  // namespace vssw::validation
