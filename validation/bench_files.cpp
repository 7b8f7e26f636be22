#include "validation/bench_files.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <ostream>
#include <sstream>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "analytic/input_file.hpp"
#include "compare/targets.hpp"
#include "io/atomic_file.hpp"
#include "io/csv.hpp"
#include "io/palette.hpp"  // series_style, series_variants
#include "validation/report_data.hpp"  // settings_json
#include "io/json.hpp"
#include "io/text.hpp"

namespace vssw::validation {
namespace {

namespace fs = std::filesystem;
using validation::BenchPoint;

// Plot size: the report page's width (validation/report_plots.cpp), shown there at about its own size.
constexpr int kPlotWidth = 1100, kPlotHeight = 480;

std::string knobs_text(const multibody::EngineSettings& s) {
    std::string text;
    for (const auto& [name, value] : s.knobs) text += fmt::format("{}{}={:g}", text.empty() ? "" : ";", name, value);
    return text;
}

// An error or a target in percent without a sign ("0.5 %"), "-" when not measured (io::percent is signed).
std::string error_percent(double v) { return std::isfinite(v) ? fmt::format("{:.3g} %", 100.0 * v) : "-"; }

// The (problem, metric) pairs in the order the points first give them.
std::vector<std::pair<std::string, std::string>> problem_metrics(const std::vector<BenchPoint>& points) {
    std::vector<std::pair<std::string, std::string>> pm;
    for (const BenchPoint& p : points)
        if (std::find(pm.begin(), pm.end(), std::pair(p.problem, p.metric)) == pm.end()) pm.emplace_back(p.problem, p.metric);
    return pm;
}

bool plottable(const BenchPoint& p) { return std::isfinite(p.error) && p.error > 0.0 && p.cpu.median > 0.0; }

}  // namespace

BenchData bench_data(BenchMeta meta, std::vector<BenchPoint> points) {
    BenchData d{std::move(meta), std::move(points), {}, {}};
    d.pareto.assign(d.points.size(), false);
    for (const auto& [problem, metric] : problem_metrics(d.points)) {
        std::vector<std::size_t> idx;
        std::vector<double> cost, error;
        for (std::size_t i = 0; i < d.points.size(); ++i)
            if (d.points[i].problem == problem && d.points[i].metric == metric) {
                idx.push_back(i);
                cost.push_back(d.points[i].cpu.median);
                error.push_back(d.points[i].error);
            }
        const std::vector<bool> front = pareto_front(cost, error);
        for (std::size_t k = 0; k < idx.size(); ++k) d.pareto[idx[k]] = front[k];
    }
    d.cheapest = cheapest_within_targets(d.points, d.meta.engines);
    return d;
}

std::vector<std::string> bench_csv_columns() {
    return {"engine", "problem", "metric",    "setting", "dt",     "iterations", "knobs", "cpu_s",
            "noise",  "repeats", "cpu_repeats", "value", "reference", "error",    "pareto", "failure"};
}

io::Json bench_json(const BenchData& d) {
    io::Json points = io::Json::array();
    for (std::size_t i = 0; i < d.points.size(); ++i) {
        const BenchPoint& p = d.points[i];
        const std::optional<double> target = bench_target(p.metric);  // none for the peak
        points.push_back({{"engine", p.engine},
                          {"problem", p.problem},
                          {"metric", p.metric},
                          {"setting", p.setting},
                          {"settings", settings_json(p.settings)},
                          {"cpu_s", p.cpu.median},
                          {"cpu_repeats", p.cpu.repeats},
                          {"noise", p.cpu.noise},
                          {"value", io::finite_or_null(p.value)},
                          {"reference", io::finite_or_null(p.reference)},
                          {"error", io::finite_or_null(p.error)},
                          {"target", io::or_null(target)},
                          {"pareto", static_cast<bool>(d.pareto[i])},
                          {"failure", p.failure.empty() ? io::Json(nullptr) : io::Json(p.failure)}});
    }
    io::Json cheapest = io::Json::array();
    for (const Cheapest& c : d.cheapest) {
        io::Json per = io::Json::object();
        for (const auto& [key, index] : c.per_metric) {
            if (!index) {
                per[key] = nullptr;
                continue;
            }
            const BenchPoint& p = d.points[*index];
            per[key] = {{"setting", p.setting}, {"cpu_s", p.cpu.median}, {"error", p.error}};
        }
        cheapest.push_back({{"engine", c.engine},
                            {"setting", c.setting ? io::Json(*c.setting) : io::Json(nullptr)},
                            {"cpu_s", c.setting ? io::Json(c.cpu_s) : io::Json(nullptr)},
                            {"per_metric", per}});
    }
    return {{"date", d.meta.date},
            {"commit", d.meta.commit},
            {"load_average", d.meta.load},
            {"cpu_clock", "process CPU time (std::clock), median of the repeats; noise = (max - min) / median"},
            {"repeats", d.meta.repeats},
            {"quick", d.meta.quick},
            {"engines", d.meta.engines},
            {"problems", d.meta.problems},
            {"targets",
             {{"threshold", compare::kThresholdTarget},
              {"period", compare::kPeriodTarget},
              {"restitution", compare::kRestitutionTarget}}},
            {"points", points},
            {"cheapest", cheapest}};
}

std::string cheapest_markdown(const BenchData& d) {
    std::ostringstream md;
    md << "| engine | cheapest setting within every target | CPU [s] (sum over problems) |";
    const std::vector<std::pair<std::string, std::string>> pm = problem_metrics(d.points);
    std::vector<std::string> targeted;
    for (const auto& [problem, metric] : pm)
        if (bench_target(metric)) targeted.push_back(problem + "/" + metric);
    for (const std::string& key : targeted) md << ' ' << key << " |";
    md << "\n|---|---|---|";
    for (std::size_t i = 0; i < targeted.size(); ++i) md << "---|";
    md << '\n';
    for (const Cheapest& c : d.cheapest) {
        md << "| " << c.engine << " | " << (c.setting ? *c.setting : "none meets them all") << " | "
           << (c.setting ? fmt::format("{:.4g}", c.cpu_s) : "-") << " |";
        for (const std::string& key : targeted) {
            std::string cell = "-";
            for (const auto& [k, index] : c.per_metric)
                if (k == key) {
                    if (index) {
                        const BenchPoint& p = d.points[*index];
                        cell = fmt::format("{} ({:.3g} s, {})", p.setting, p.cpu.median, error_percent(p.error));
                    } else {
                        cell = "none within";
                    }
                }
            md << ' ' << cell << " |";
        }
        md << '\n';
    }
    return md.str();
}

std::vector<io::PlotScript> bench_plot_scripts(const BenchData& d) {
    std::vector<io::PlotScript> scripts;
    for (const auto& [problem, metric] : problem_metrics(d.points)) {
        const std::string name = io::file_stem("wp_" + problem + "_" + metric);
        std::ostringstream dat, gp;
        std::vector<std::string> series;
        std::size_t block = 0;
        for (std::size_t e = 0; e < d.meta.engines.size(); ++e) {
            const std::string& engine = d.meta.engines[e];
            std::vector<const BenchPoint*> line;
            for (const BenchPoint& p : d.points)
                if (p.problem == problem && p.metric == metric && p.engine == engine && plottable(p)) line.push_back(&p);
            if (line.empty()) continue;  // gnuplot refuses a block of nothing
            std::sort(line.begin(), line.end(), [](auto* a, auto* b) { return a->cpu.median < b->cpu.median; });
            dat << "# " << io::gp_comment(engine) << ": cpu_s error setting\n";
            for (const BenchPoint* p : line)
                dat << io::gp_number(p->cpu.median, true) << ' ' << io::gp_number(p->error, true) << ' '
                    << io::gp_data_string(p->setting) << '\n';
            dat << "\n\n";
            series.push_back(fmt::format("'{}.dat' index {} using 1:2 with linespoints {} title {}", name, block++,
                                         io::series_style(engine, 0), io::gp_string(engine)));
        }
        if (series.empty()) continue;
        dat << "# Pareto front (all engines): cpu_s error\n";
        std::vector<std::pair<double, double>> front;
        for (std::size_t i = 0; i < d.points.size(); ++i) {
            const BenchPoint& p = d.points[i];
            if (p.problem == problem && p.metric == metric && d.pareto[i] && plottable(p))
                front.emplace_back(p.cpu.median, p.error);
        }
        std::sort(front.begin(), front.end());
        for (const auto& [cpu, error] : front) dat << io::gp_number(cpu, true) << ' ' << io::gp_number(error, true) << '\n';
        if (!front.empty())
            series.push_back(fmt::format("'{}.dat' index {} using 1:2 with points pt 6 ps 2 lc rgb 'black' title "
                                         "'Pareto front'",
                                         name, block));
        if (const std::optional<double> target = bench_target(metric))
            series.push_back(fmt::format("{:g} with lines dt 3 lc rgb '#888888' title 'target {:g} %'", *target,
                                         100.0 * *target));
        const std::string title = fmt::format("Work-precision: {} on {}", metric, problem);
        gp << io::gp_preamble("vssw bench", name, kPlotWidth, kPlotHeight) << "set title " << io::gp_string(title) << '\n'
             << "set logscale xy\nset format x '%g'\nset format y '%g'\n"
             << io::gp_xlabel("CPU time per run [s] (median of repeats)")
             << "set ylabel 'relative error against the converged reference'\n"
             << "plot " << fmt::format("{}", fmt::join(series, ", \\\n     ")) << '\n';
        io::PlotScript script;
        script.plot.section = "Work-precision";
        script.plot.name = name;
        script.plot.title = title;
        script.gp = gp.str();
        script.dat = dat.str();
        scripts.push_back(std::move(script));
    }
    return scripts;
}

io::PlotResult write_bench(const BenchData& d, const fs::path& dir, const std::string& gnuplot) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    io::write_file(dir / "bench.json", [&](std::ostream& out) { out << io::dump_json(bench_json(d), 2) << '\n'; });
    io::write_file(dir / "bench.csv", [&](std::ostream& out) {
        const std::vector<std::string> columns = bench_csv_columns();
        out << fmt::format("{}", fmt::join(columns, ",")) << '\n';
        for (std::size_t i = 0; i < d.points.size(); ++i) {
            const BenchPoint& p = d.points[i];
            std::vector<std::string> repeats;
            for (double r : p.cpu.repeats) repeats.push_back(io::csv_number(r));
            const std::vector<std::string> row = {
                io::csv_field(p.engine), io::csv_field(p.problem), io::csv_field(p.metric), io::csv_field(p.setting),
                io::csv_number(p.settings.dt), std::to_string(p.settings.iterations), io::csv_field(knobs_text(p.settings)),
                io::csv_number(p.cpu.median), io::csv_number(p.cpu.noise), std::to_string(p.cpu.repeats.size()),
                io::csv_field(fmt::format("{}", fmt::join(repeats, ";"))), io::csv_number(p.value), io::csv_number(p.reference),
                io::csv_number(p.error), d.pareto[i] ? "1" : "0", io::csv_field(p.failure)};
            out << fmt::format("{}", fmt::join(row, ",")) << '\n';
        }
    });
    io::PlotResult plots;
    if (gnuplot.empty()) {
        plots.note = "plots not drawn (--no-plots)";
    } else {
        plots = io::draw_plots(bench_plot_scripts(d), dir / "plots", gnuplot);
    }
    io::write_file(dir / "bench.md", [&](std::ostream& md) {
        md << "# Work-precision (`vssw bench`)\n\n"
           << fmt::format("Made {} by vssw {}; {} repeat(s) per point{}; load average at the start: {}.\n\n",
                          d.meta.date, d.meta.commit.empty() ? "(commit unknown)" : d.meta.commit, d.meta.repeats,
                          d.meta.quick ? " (--quick sweep)" : "", d.meta.load.empty() ? "unknown" : d.meta.load)
           << "CPU time is the process's (std::clock), the median of the repeats; errors are relative, against the "
              "converged reference of the same physics (validation/work_precision.hpp). Targets: threshold "
           << error_percent(compare::kThresholdTarget) << ", period " << error_percent(compare::kPeriodTarget)
           << ", restitution " << error_percent(compare::kRestitutionTarget)
           << ".\n\n## Cheapest settings within the targets\n\n"
           << cheapest_markdown(d) << "\n## Plots\n\n";
        if (!plots.note.empty()) md << "No plots or not all: " << plots.note << "\n\n";
        for (const io::Plot& p : plots.plots)
            if (p.made) md << "![" << p.title << "](plots/" << p.name << ".svg)\n\n";
    });
    return plots;
}

}  // namespace vssw::validation

namespace vssw::validation {
namespace {

io::Json read_bench_json(const std::filesystem::path& bench_dir) {
    const std::filesystem::path path = bench_dir / "bench.json";
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        throw InputError(fmt::format("--bench: cannot read {} (run `vssw bench --out {}` first)", path.string(),
                                     bench_dir.string()));
    io::Json j = io::Json::parse(read_input_file(path, "--bench: the file", kMaxTextFileBytes), nullptr, false);
    if (j.is_discarded() || !j.is_object() || !j.contains("cheapest") || !j.contains("points"))
        throw InputError(fmt::format("--bench: {} is not a bench.json written by vssw bench", path.string()));
    return j;
}

std::string text_of(const io::Json& j, const char* key) {
    return j.contains(key) && j[key].is_string() ? j[key].get<std::string>() : std::string("?");
}

}  // namespace

void check_bench_dir(const std::filesystem::path& bench_dir) { (void)read_bench_json(bench_dir); }

std::vector<io::DocBlock> bench_report_blocks(const std::filesystem::path& bench_dir,
                                          const std::filesystem::path& plots_dir) {
    const io::Json j = read_bench_json(bench_dir);
    std::vector<io::DocBlock> blocks;
    blocks.push_back(io::heading(2, "Work-precision (vssw bench)"));
    blocks.push_back(io::paragraph(fmt::format(
        "From the bench folder {}: made {} by vssw {}, {} repeat(s) per point, load average at its start {}. CPU time "
        "of the process per run against the relative error on the converged reference of the same physics; the "
        "Pareto front circled. The report does not run the sweep (minutes): `vssw bench --out DIR` does.",
        bench_dir.string(), text_of(j, "date"), text_of(j, "commit"), j.value("repeats", 0),
        text_of(j, "load_average"))));
    io::DocBlock t = io::table({"engine", "cheapest setting within every target", "CPU [s] (sum over problems)"}, 2);
    for (const io::Json& c : j["cheapest"]) {
        const bool met = c.contains("setting") && c["setting"].is_string();
        t.rows.push_back({{text_of(c, "engine"), false},
                          {met ? c["setting"].get<std::string>() : "none meets them all", !met},
                          {met && c.contains("cpu_s") && c.at("cpu_s").is_number()
                               ? fmt::format("{:.4g}", c.at("cpu_s").get<double>())
                               : "-",
                           false}});
    }
    blocks.push_back(t);
    std::error_code ec;
    std::filesystem::create_directories(plots_dir, ec);
    // The plots of this bench's own problems and metrics, in the order of its points: a folder benched before may
    // hold plots of problems this bench did not run.
    std::vector<std::string> names;
    for (const io::Json& p : j.value("points", io::Json::array())) {
        const std::string name = "wp_" + text_of(p, "problem") + "_" + text_of(p, "metric");
        if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    }
    for (const std::string& name : names) {
        const std::filesystem::path svg = bench_dir / "plots" / (name + ".svg");
        if (!std::filesystem::exists(svg, ec)) continue;  // no gnuplot, or a metric with nothing to plot
        std::error_code copy_ec;
        std::filesystem::copy_file(svg, plots_dir / svg.filename(), std::filesystem::copy_options::overwrite_existing,
                                   copy_ec);
        if (!copy_ec) blocks.push_back(io::plot("Work-precision " + name.substr(3), name));
    }
    return blocks;
}

}  // namespace vssw::validation
