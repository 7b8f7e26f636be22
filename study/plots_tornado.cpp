// Tornado charts: the effect of each varied assumption of the analytic model on a metric, and of each of the paper's
// physical assumptions relaxed (study/study_plots.hpp).
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "study/study_plots.hpp"
#include "io/text.hpp"

namespace vssw::study {
namespace {

// Bar height in SVG pixels, and the room title, axis and margins take.
constexpr int kBarPixels = 46, kFramePixels = 170, kTornadoWidth = 860;
// A bar's thickness in units of the spacing between bars.
constexpr double kBarHalfHeight = 0.3;
// The change axis spans at least +-1 % (of the metric, or of the pairs for a 0/1 metric): an assumption that changes
// a metric by less is one that does not matter, and its bar stays a sliver instead of filling the chart.
constexpr double kMinChangePercent = 1.0;
// The median's dot, and its hover layer's.
constexpr const char* kMedianStyle = "pt 7 ps 1.4 lc rgb 'black'";

std::string bar_label(const Effect& e) { return fmt::format("{}: {} -> {}", e.parameter, e.from, e.to); }

// The two kinds of chart: the analytic model's assumptions (engines ignore them) and the paper's physical ones.
struct TornadoKind {
    const char* prefix;  // of the plot's name
    const char* what;    // in the title: "each assumption", "each physical assumption relaxed"
};
constexpr TornadoKind kModelTornado{"tornado_", "each assumption"};
constexpr TornadoKind kPhysicalTornado{"tornado_physical_", "each physical assumption relaxed (model and engines)"};

io::PlotScript tornado(const StudyData& d, std::size_t metric, std::vector<const Effect*> bars, const TornadoKind& kind,
                       const char* section) {
    // Largest first, at the top: the bar's reach, then its median.
    std::stable_sort(bars.begin(), bars.end(), [](const Effect* a, const Effect* b) {
        if (a->extent() != b->extent()) return a->extent() > b->extent();
        return a->magnitude() > b->magnitude();
    });
    const MetricMeta& m = d.metrics[metric];
    io::PlotScript s;
    s.plot.section = section;
    s.plot.name = io::file_stem(kind.prefix + m.name);
    s.plot.title = m.binary
                       ? fmt::format("{}: share of paired runs that flip (right: to 1, left: to 0; dot: net)", m.name)
                       : fmt::format("{}: change with {} (bar: smallest to largest; dot: median)", m.name, kind.what);
    s.dat = fmt::format("# {}\n# y label lo median hi pairs hover_text   (changes as fractions; binary metric: "
                        "shares of pairs, lo = -(1 -> 0), hi = +(0 -> 1), median = net)\n",
                        io::gp_comment(m.name));
    const std::size_t n = bars.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Effect& e = *bars[i];
        const std::string range = fmt::format("{:.4g} to {:.4g} %, median", 100.0 * e.lo, 100.0 * e.hi);
        s.dat += fmt::format("{} {} {} {} {} {} {}\n", n - 1 - i, io::gp_data_string(bar_label(e)), io::gp_number(e.lo),
                             io::gp_number(e.median), io::gp_number(e.hi), e.pairs,
                             io::gp_hover_text(bar_label(e), range, 100.0 * e.median, "%"));
    }
    // The bars' labels from the script, quoted by gp_string: a data file's strings are read another way (gnuplot.hpp).
    std::string tics;
    for (std::size_t i = 0; i < n; ++i)
        tics += fmt::format("{}{} {}", i == 0 ? "set ytics (" : ", \\\n    ", io::gp_string(bar_label(*bars[i])), n - 1 - i);
    const int height = kFramePixels + kBarPixels * static_cast<int>(n);
    s.gp = io::gp_preamble("vssw study", s.plot.name, kTornadoWidth, height) +
           fmt::format("set title {}\n{}set yrange [-0.6:{}]\nset ytics nomirror\n{})\nunset key\n"
                       "set arrow from 0, graph 0 to 0, graph 1 nohead lc rgb '#555555'\n"
                       "set xrange [*<{}:{}<*]\nset offsets graph 0.05, graph 0.05, 0, 0\n",
                       io::gp_string(s.plot.title),
                       io::gp_xlabel(m.binary ? "share of paired runs [%]" : "relative change of " + m.name + " [%]",
                                 false),
                       static_cast<double>(n) - 0.4, tics, io::gp_number(-kMinChangePercent),
                       io::gp_number(kMinChangePercent)) +
           fmt::format("plot '{0}.dat' using (50*($3+$5)):1:(100*$3):(100*$5):($1-{1}):($1+{1}) with "
                       "boxxyerror fs solid 0.45 noborder lc rgb '#1f77b4', \\\n"
                       "     '{0}.dat' using (100*$4):1 with points {2}, \\\n     {3}\n",
                       s.plot.name, kBarHalfHeight, kMedianStyle,
                       io::gp_hover_layer(fmt::format("'{}.dat' using (100*$4):1:(stringcolumn(7))", s.plot.name),
                                      kMedianStyle));
    return s;
}

}  // namespace

void add_tornado_plots(const StudyData& d, const std::vector<Effect>& effects, StudyPlots& out) {
    bool any_assumption = false, any_physical = false;
    for (std::size_t c : d.varied()) {
        any_assumption = any_assumption || d.columns[c].assumption;
        any_physical = any_physical || d.columns[c].physical;
    }
    if (!any_assumption && !any_physical) {
        out.notes.push_back("No assumption of the analytic model or of the paper varies: there are no tornado charts.");
        return;
    }
    for (std::size_t m = 0; m < d.metrics.size(); ++m) {
        std::vector<const Effect*> model, physical;
        for (const Effect& e : effects)
            if (e.metric == m && e.pairs > 0) {
                if (e.assumption) model.push_back(&e);
                if (e.physical && !d.metrics[m].is_slip()) physical.push_back(&e);
            }
        if (!physical.empty()) out.scripts.push_back(tornado(d, m, physical, kPhysicalTornado, kPhysicalTornadoSection));
        if (!model.empty()) out.scripts.push_back(tornado(d, m, model, kModelTornado, kTornadoSection));
    }
}

}  // namespace vssw::study
