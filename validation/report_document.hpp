#pragma once
// The content of report.md and report.html (io/document.hpp): the engines, a summary line per engine, the findings,
// the failures, the analytic model's warnings, a table per metric, the error-against-step study, the plots, the cases
// and the files.
#include "io/document.hpp"
#include "io/gnuplot.hpp"
#include "validation/report.hpp"

namespace vssw::validation {

// plots: what write_plots made (empty with --no-plots); plots_skipped: --no-plots was given.
io::Document build_document(const ReportInput& in, const io::PlotResult& plots, bool plots_skipped);

}  // namespace vssw::validation
