#include "study/ida_curves.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <numeric>
#include <ostream>
#include <tuple>

#include <fmt/format.h>

#include "analytic/assumption_sets.hpp"
#include "analytic/error.hpp"
#include "analytic/input_file.hpp"
#include "analytic/intensity_measures.hpp"
#include "io/csv.hpp"
#include "io/gnuplot.hpp"
#include "io/palette.hpp"
#include "study/overturned_runs.hpp"
#include "study/plot_panels.hpp"

namespace vssw::study {

const char* const kIdaSection = "Ensemble: incremental dynamic analysis curves";

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
const std::vector<std::string> kHeader = {"case_id", "engine",    "assumptions",    "settings",        "record",
                                          "scale",   "measure",   "intensity",      "intensity_unit", "peak_over_alpha1",
                                          "overturned"};
// The peaks at which the fractiles are read: steps of 2.5 % of alpha1 up to alpha1 (the rest threshold's angle),
// beyond which a wall is overturning rather than rocking.
constexpr double kPeakStep = 0.025;
constexpr int kPeakLevels = 40;
// The plot's peak axis ends this far above the height an overturned run is drawn at (study/overturned_runs.hpp), so
// that the rings there are not cut by the frame.
constexpr double kPeakAxisHeadroom = 1.1;
// The records' curves: this transparency (gnuplot's alpha byte, 00 opaque to FF invisible), so the fractiles read above.
constexpr const char* kRecordAlpha = "A0";
// The fractiles drawn: 16, 50 and 84 %, the median and one lognormal standard deviation either side.
constexpr double kFractiles[] = {0.16, 0.50, 0.84};

// The measure a case's intensity is reported in: its part's ensemble intensity, else the PGA.
Intensity case_intensity(const Grid& grid, const CaseSpec& c) {
    Intensity im = c.intensity;
    const PartSpec& part = grid.spec().parts[c.part];
    im.measure = part.ensemble ? parse_intensity_measure(part.ensemble->intensity) : IntensityMeasure::pga;
    return im;
}

std::string assumptions_of(const RunSpec& run) {
    // As assumptions_text (study/ensemble_measures.hpp) writes a series': the set first, then its three parts.
    std::string out = run.engine == "analytic"
                          ? "set=" + set_name(Assumptions{run.kinematics, run.impact, run.roller})
                          : std::string();
    for (std::size_t i = 0; i < run.assumptions.size() && i < kAssumptionKeys.size(); ++i)
        out += fmt::format("{}{}={}", out.empty() ? "" : " ", kAssumptionKeys[i], to_text(run.assumptions[i]));
    return out;
}

}  // namespace

void write_ida_csv(std::ostream& out, const Grid& grid, std::vector<IdaRow> rows) {
    std::stable_sort(rows.begin(), rows.end(), [](const IdaRow& a, const IdaRow& b) {
        return std::tie(a.case_id, a.run) < std::tie(b.case_id, b.run);
    });
    for (std::size_t i = 0; i < kHeader.size(); ++i) out << (i ? "," : "") << kHeader[i];
    out << '\n';
    int case_id = 0;
    CaseSpec c;
    double at_one = 0.0;  // the case's record's measure at scale 1
    Intensity im;
    for (const IdaRow& r : rows) {
        if (r.case_id != case_id) {
            case_id = r.case_id;
            c = grid.make_case(case_id);
            im = case_intensity(grid, c);
            at_one = record_intensity(grid.record(c), im);
        }
        const RunSpec& run = grid.runs().at(r.run);
        // The PGA as collapse_pga has it (the record's PGA times the scale), so the two read alike.
        const double intensity = im.measure == IntensityMeasure::pga
                                     ? r.point.scale * grid.record(c).pga() / kStandardGravity
                                     : intensity_at_scale(im.measure, at_one, r.point.scale);
        out << fmt::format("{},{},{},{},{},{},{},{},{},{},{}\n", r.case_id, io::csv_field(run.engine),
                           io::csv_field(assumptions_of(run)), io::csv_field(run.settings_text), io::csv_field(c.file),
                           io::csv_number(r.point.scale), to_string(im.measure), io::csv_number(intensity),
                           intensity_unit(im.measure), io::csv_number(r.point.peak), r.point.overturned ? 1 : 0);
    }
}

void merge_ida_csv(const std::vector<std::filesystem::path>& shard_dirs, const std::filesystem::path& dest) {
    std::vector<std::pair<int, std::string>> lines;  // (case id, the row as written)
    bool any = false;
    for (const std::filesystem::path& dir : shard_dirs) {
        std::error_code ec;
        if (!std::filesystem::exists(std::filesystem::symlink_status(dir / kIdaCsv, ec))) continue;
        std::ifstream in = open_input_file(dir / kIdaCsv, "the study's IDA curves", kMaxResultsBytes);
        any = true;
        std::string line;
        std::getline(in, line);  // the header
        while (std::getline(in, line))
            if (!line.empty()) lines.push_back({std::atoi(line.c_str()), line});
    }
    if (!any) return;
    // Each shard's rows are in case order and a case is one shard's: a stable sort by case keeps each task's order.
    std::stable_sort(lines.begin(), lines.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::ofstream out(dest / kIdaCsv, std::ios::binary | std::ios::trunc);
    for (std::size_t i = 0; i < kHeader.size(); ++i) out << (i ? "," : "") << kHeader[i];
    out << '\n';
    for (const auto& [id, line] : lines) out << line << '\n';
    if (!out) throw InputError(fmt::format("cannot write '{}'", (dest / kIdaCsv).string()));
}

std::vector<IdaCurve> read_ida_csv(const std::filesystem::path& path) {
    std::ifstream in = open_input_file(path, "the study's IDA curves", kMaxResultsBytes);
    std::vector<std::string> f;
    if (!io::read_csv_record(in, f) || f != kHeader)
        throw InputError(fmt::format("'{}' is not an ida.csv of this vssw: its header is not '{}'", path.string(),
                                     fmt::join(kHeader, ",")));
    std::vector<IdaCurve> curves;
    std::map<std::tuple<int, std::string, std::string, std::string>, std::size_t> index;
    while (io::read_csv_record(in, f)) {
        if (f.size() == 1 && f[0].empty()) continue;
        if (f.size() != kHeader.size())
            throw InputError(fmt::format("'{}': a row of {} fields, not {}", path.string(), f.size(), kHeader.size()));
        const int id = std::atoi(f[0].c_str());
        const auto [it, added] = index.emplace(std::make_tuple(id, f[1], f[2], f[3]), curves.size());
        if (added) curves.push_back({id, f[1], f[2], f[3], f[4], f[6], f[8], {}, {}, {}});
        IdaCurve& c = curves[it->second];
        c.intensity.push_back(std::strtod(f[7].c_str(), nullptr));
        c.peak.push_back(std::strtod(f[9].c_str(), nullptr));
        c.overturned.push_back(f[10] == "1");
    }
    for (IdaCurve& c : curves) {  // sorted by intensity: the curve
        std::vector<std::size_t> order(c.intensity.size());
        std::iota(order.begin(), order.end(), std::size_t{0});
        std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
            return c.intensity[a] < c.intensity[b];
        });
        IdaCurve sorted = c;
        for (std::size_t i = 0; i < order.size(); ++i) {
            sorted.intensity[i] = c.intensity[order[i]];
            sorted.peak[i] = c.peak[order[i]];
            sorted.overturned[i] = c.overturned[order[i]];
        }
        c = std::move(sorted);
    }
    return curves;
}

double intensity_reaching(const IdaCurve& curve, double y) {
    double x0 = 0.0, y0 = 0.0;
    for (std::size_t i = 0; i < curve.intensity.size(); ++i) {
        const double x1 = curve.intensity[i], y1 = curve.peak[i];
        if (y1 >= y) return y1 == y0 ? x1 : x0 + (x1 - x0) * (y - y0) / (y1 - y0);
        x0 = x1;
        y0 = y1;
    }
    return kInf;
}

double fractile(std::vector<double> values, double q) {
    if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
    std::sort(values.begin(), values.end());
    const double h = q * static_cast<double>(values.size() - 1);
    const auto lo = static_cast<std::size_t>(std::floor(h));
    const std::size_t hi = std::min(lo + 1, values.size() - 1);
    if (std::isinf(values[lo]) || std::isinf(values[hi])) return kInf;
    return values[lo] + (h - static_cast<double>(lo)) * (values[hi] - values[lo]);
}

void add_ida_plot(const StudyData& d, const EnsembleMeasures& e, const std::vector<IdaCurve>& curves, StudyPlots& out) {
    if (curves.empty() || !e.applies || e.walls.empty()) return;
    // Each curve's series (the first of its engine, assumptions and settings) and wall.
    std::vector<std::size_t> series(curves.size(), std::string::npos), wall(curves.size(), std::string::npos);
    for (std::size_t i = 0; i < curves.size(); ++i) {
        for (std::size_t s = 0; s < d.series.size() && series[i] == std::string::npos; ++s)
            if (d.series[s].engine == curves[i].engine && d.series[s].settings == curves[i].settings &&
                assumptions_text(d.series[s]) == curves[i].assumptions)
                series[i] = s;
        if (const auto it = e.case_wall.find(curves[i].case_id); it != e.case_wall.end()) wall[i] = it->second;
    }
    const PanelLayout layout = panel_layout(e.walls.size());
    io::PlotScript s;
    s.plot = {kIdaSection, "ida",
              "IDA curves: each record's runs (thin) and the 16, 50, 84 % fractiles of the intensity given the peak",
              false};
    s.dat = "# " + io::gp_comment(s.plot.title) + "\n";
    std::string gp = io::gp_preamble("vssw study", s.plot.name, layout.width, layout.height) +
                     io::gp_xlabel(e.label, !layout.multiplot()) +
                     fmt::format("set ylabel {}\n", io::gp_string("peak |theta1| / alpha1")) +
                     layout_begin(layout, s.plot.title);
    std::size_t block = 0;
    std::vector<std::pair<std::string, std::string>> entries;
    std::vector<bool> listed(d.series.size(), false);
    // The key names the rings "overturned" only when some run overturned (a panel's first ring carries the title).
    bool any_overturned = false;
    for (const IdaCurve& c : curves)
        any_overturned =
            any_overturned || std::find(c.overturned.begin(), c.overturned.end(), true) != c.overturned.end();
    for (std::size_t w = 0; w < e.walls.size(); ++w) {
        std::string cmd;
        bool ringed = !any_overturned;  // the title given (or none to give): the panel's later rings go untitled

        const auto add = [&](const std::string& style, const std::string& title) {
            cmd += fmt::format("{}'{}.dat' index {} using 1:2 with {} {}", cmd.empty() ? "plot " : ", \\\n     ",
                               s.plot.name, block++, style, title.empty() ? "notitle" : "title " + io::gp_string(title));
        };
        for (std::size_t sr = 0; sr < d.series.size(); ++sr) {
            std::vector<const IdaCurve*> mine;
            for (std::size_t i = 0; i < curves.size(); ++i)
                if (series[i] == sr && wall[i] == w) mine.push_back(&curves[i]);
            if (mine.empty()) continue;
            const std::string colour = fmt::format("lc rgb '{}'", io::engine_colour(d.series[sr].engine));
            // The records' curves in the series' colour, mostly transparent (gnuplot's #AARRGGBB), under its fractiles.
            const std::string faint = fmt::format("lc rgb '#{}{}'", kRecordAlpha, io::engine_colour(d.series[sr].engine).substr(1));
            for (const IdaCurve* c : mine) {
                s.dat += fmt::format("# {}: {}: intensity peak_drawn overturned\n", io::gp_comment(d.series[sr].label),
                                     io::gp_comment(c->record));
                for (std::size_t k = 0; k < c->intensity.size(); ++k)
                    s.dat += fmt::format("{} {} {}\n", io::gp_number(c->intensity[k]),
                                         io::gp_number(c->overturned[k] ? kOverturnedDrawnAt : c->peak[k]),
                                         c->overturned[k] ? 1 : 0);
                s.dat += "\n\n";
                add("linespoints " + faint + " lw 0.5 pt 7 ps 0.25", "");
                // Its overturned runs ringed at kOverturnedDrawnAt, as every plot of the peak draws them.
                cmd += fmt::format(", \\\n     '{}.dat' index {} using 1:($3 > 0.5 ? $2 : NaN) with points {} {}",
                                   s.plot.name, block - 1, kOverturnedRing,
                                   ringed ? "notitle" : "title " + io::gp_string("overturned"));
                ringed = true;
            }
            for (const double q : kFractiles) {
                s.dat += fmt::format("# {}: {:g} % fractile of the intensity given the peak\n",
                                     io::gp_comment(d.series[sr].label), 100.0 * q);
                for (int k = 1; k <= kPeakLevels; ++k) {
                    const double y = kPeakStep * k;
                    std::vector<double> x;
                    for (const IdaCurve* c : mine) x.push_back(intensity_reaching(*c, y));
                    s.dat += fmt::format("{} {}\n", io::gp_number(fractile(x, q)), io::gp_number(y));
                }
                s.dat += "\n\n";
                const bool first = !listed[sr] && q == 0.5;
                const std::string style = fmt::format("{} lw {} dt {}", colour, q == 0.5 ? 2.5 : 1.5, q == 0.5 ? 1 : 2);
                add("lines " + style, first ? d.series[sr].label + " (16, 50, 84 %)" : "");
                if (first) entries.push_back({d.series[sr].label + " (16, 50, 84 %)", style});
                if (first) listed[sr] = true;
            }
        }
        gp += panel_begin(layout, e.walls[w]) + fmt::format("set yrange [0:{}]\n", io::gp_number(kOverturnedDrawnAt * kPeakAxisHeadroom)) +
              (cmd.empty() ? "plot [0:1][0:1] NaN notitle\n" : cmd + "\n");
    }
    s.gp = gp + layout_end(layout, entries,
                           any_overturned ? fmt::format("NaN with points {} title 'overturned'", kOverturnedRing) : "");
    out.scripts.push_back(std::move(s));
}

}  // namespace vssw::study
