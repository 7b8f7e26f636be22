#pragma once
// The plots of `vssw report`, drawn by gnuplot (io/gnuplot.hpp) into DIR/plots/:
//   trace_<case>.svg   theta1 / alpha against t over the motion, the analytic model under each assumption the report
//                      measures against (Eq. 19 or Housner; on a VSSW also the whole-mechanism impact) and each engine
//                      overlaid (history and free cases), one colour per engine (io/palette.hpp)
//   trace_<case>_zoom  the same without the reference, framed on the others, where they all peak below a third of it
//   error_<metric>.svg relative error in % per case, one series per engine, the target as dashed lines
//   step_<metric>.svg  |relative error| against the engine step, log-log, one line per engine and case (step study)
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "io/gnuplot.hpp"
#include "validation/report.hpp"

namespace vssw::validation {

struct PlotOptions {
    std::string gnuplot = "gnuplot";  // the program (looked up in PATH unless it holds a '/')
};

// The window a trace plot shows: t where any trace moves (beyond motion_fraction of the largest |theta1| / alpha of
// the traces, with a margin), theta1 / alpha over every value inside it and zero, padded.
struct TraceWindow {
    double t0 = 0.0, t1 = 1.0, y0 = -1.0, y1 = 1.0;
};
TraceWindow trace_window(const std::vector<const Trace*>& traces, double motion_fraction);
// The indices of the points of a polyline that keep every point within `tol` of it (Douglas-Peucker; x and y in the
// same unit, e.g. pixels); the first and last always, non-finite y always.
std::vector<std::size_t> simplify_polyline(const std::vector<double>& x, const std::vector<double>& y, double tol);

// The scripts and data of every plot the results call for, in the order the report shows them.
std::vector<io::PlotScript> report_plot_scripts(const ReportInput& in);

// Writes scripts and data into plots_dir (created) and runs gnuplot on each script.
io::PlotResult write_plots(const ReportInput& in, const std::filesystem::path& plots_dir, const PlotOptions& options);

}  // namespace vssw::validation
