#pragma once
// The plots of `vssw report`, drawn by gnuplot to SVG in DIR/plots/, each beside the .gp script and .dat data that
// made it (so `cd DIR/plots && gnuplot NAME.gp` re-draws it):
//   trace_<case>.svg   theta1 / alpha against t, the analytic model and each engine overlaid (history and free cases)
//   error_<metric>.svg relative error in % per case, one series per engine, the target as dashed lines
//   step_<metric>.svg  |relative error| against the engine step, log-log, one line per engine and case (step study)
// When gnuplot cannot be run or fails, the scripts and data are still written and the result says why.
#include <filesystem>
#include <string>
#include <vector>

#include "apps/report_suite.hpp"

namespace vssw::cli {

struct PlotOptions {
    std::string gnuplot = "gnuplot";  // the program (looked up in PATH unless it holds a '/')
};

enum class PlotSection { traces, errors, steps };

struct Plot {
    PlotSection section;
    std::string name;   // file stem in plots/: "trace_fig6-vssw_r0.5"
    std::string title;  // for people
    bool made = false;  // the .svg exists
};

struct PlotResult {
    std::vector<Plot> plots;
    bool all_made = false;
    std::string note;  // empty when every plot was made; else what went wrong (for the report and a warning)
};

// Writes scripts and data into plots_dir (created) and runs gnuplot on each script.
PlotResult write_plots(const ReportInput& in, const std::filesystem::path& plots_dir, const PlotOptions& options);

}  // namespace vssw::cli
