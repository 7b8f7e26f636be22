#pragma once
// The plots of `vssw report`, drawn by gnuplot (study/gnuplot.hpp) into DIR/plots/:
//   trace_<case>.svg   theta1 / alpha against t, the analytic model and each engine overlaid (history and free cases)
//   error_<metric>.svg relative error in % per case, one series per engine, the target as dashed lines
//   step_<metric>.svg  |relative error| against the engine step, log-log, one line per engine and case (step study)
#include <filesystem>
#include <string>
#include <vector>

#include "study/gnuplot.hpp"
#include "study/report.hpp"

namespace vssw::study {

struct PlotOptions {
    std::string gnuplot = "gnuplot";  // the program (looked up in PATH unless it holds a '/')
};

// The scripts and data of every plot the results call for, in the order the report shows them.
std::vector<PlotScript> report_plot_scripts(const ReportInput& in);

// Writes scripts and data into plots_dir (created) and runs gnuplot on each script.
PlotResult write_plots(const ReportInput& in, const std::filesystem::path& plots_dir, const PlotOptions& options);

}  // namespace vssw::study
