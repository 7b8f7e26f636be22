#include "validation/report_write.hpp"

#include <fstream>
#include <system_error>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "io/atomic_file.hpp"
#include "io/json.hpp"
#include "validation/bench_files.hpp"
#include "io/document_html.hpp"
#include "io/document_markdown.hpp"
#include "validation/report_data.hpp"
#include "validation/report_document.hpp"

namespace vssw::validation {
namespace fs = std::filesystem;

void prepare_report_dir(const fs::path& dir) {
    std::error_code ec;
    if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
        throw InputError(fmt::format("--out: '{}' exists and is not a folder", dir.string()));
    fs::create_directories(dir, ec);
    if (ec) throw InputError(fmt::format("--out: cannot create '{}': {}", dir.string(), ec.message()));
    const fs::path probe = dir / ".vssw-write-test";
    {
        std::ofstream f(probe);
        if (!f) throw InputError(fmt::format("--out: cannot write in '{}'", dir.string()));
    }
    fs::remove(probe, ec);
}

ReportFiles write_suite_report(const fs::path& dir, const Suite& suite, const SuiteResults& results,
                               ReportMeta meta, const ReportOptions& options) {
    prepare_report_dir(dir);
    ReportFiles files;
    files.dir = dir;
    files.markdown = dir / "report.md";
    files.html = dir / "report.html";
    files.json = dir / "results.json";
    const fs::path plots_dir = dir / "plots";

    io::PlotResult plots;
    if (options.plots) {
        plots = write_plots(ReportInput{suite, results, meta}, plots_dir, options.plot);
        files.plots_made = plots.all_made;
        if (!plots.note.empty()) files.warnings.push_back("plots: " + plots.note);
    }
    meta.plots_made = options.plots && plots.all_made;
    meta.plots_note = options.plots ? plots.note : "not made (--no-plots)";
    const ReportInput in{suite, results, meta, options.earthquake, options.relaxations};

    io::write_file(files.json, [&](std::ostream& out) { out << io::dump_json(results_json(in), 2) << '\n'; });
    io::write_file(dir / "metrics.csv", [&](std::ostream& out) { write_metrics_csv(out, results); });
    io::write_file(dir / "failures.csv", [&](std::ostream& out) { write_failures_csv(out, results); });
    io::write_file(dir / "traces.csv", [&](std::ostream& out) { write_traces_csv(out, results); });
    io::Document doc = build_document(in, plots, !options.plots);
    if (!options.bench_dir.empty()) {
        const std::vector<io::DocBlock> bench = bench_report_blocks(options.bench_dir, plots_dir);
        doc.blocks.insert(doc.blocks.end(), bench.begin(), bench.end());
    }
    io::write_file(files.markdown, [&](std::ostream& out) { io::write_markdown(out, doc); });
    io::write_file(files.html, [&](std::ostream& out) { io::write_html(out, doc, plots_dir); });
    for (const EngineSummary& s : summarize(in)) files.summary_lines.push_back(s.line);
    return files;
}

}  // namespace vssw::validation
