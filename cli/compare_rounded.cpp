#include "cli/compare_rounded.hpp"

#include <cmath>
#include <ostream>

#include <fmt/format.h>

#include "cli/table.hpp"
#include "io/json.hpp"

namespace vssw::cli {
namespace {

std::string text_or_none(double v, const char* format) {
    return std::isfinite(v) ? fmt::format(fmt::runtime(format), v) : std::string("none");
}

}  // namespace

io::Json to_json(const compare::RoundedCornerComparison& c, const WallOptions& wall, WallKind kind, double release) {
    io::Json engines = io::Json::array();
    for (const compare::RoundedEngineResult& e : c.engines)
        engines.push_back({{"engine", e.engine},
                           {"threshold_g", io::finite_or_null(e.threshold_g)},
                           {"threshold_rel_error", io::finite_or_null(e.threshold_rel_error)},
                           {"period", io::finite_or_null(e.period)},
                           {"overturned", e.overturned},
                           {"failure", e.failure}});
    return {{"wall", wall_inputs_json(wall, kind)},
            {"corner_radius", c.corner_radius_ratio},
            {"closed_forms", {{"threshold_g", c.closed_form_g}, {"threshold_sharp_g", c.sharp_closed_form_g}}},
            {"theta0", release},  // as plain compare writes it: the fraction of alpha typed
            {"engines", engines},
            {"threshold_spread", io::finite_or_null(c.threshold_spread)},
            {"period_spread", io::finite_or_null(c.period_spread)}};
}

void print_rounded_corners(std::ostream& out, const compare::RoundedCornerComparison& c, const WallOptions& wall,
                           WallKind kind) {
    const char* eq = kind == WallKind::vssw ? "Eq. (12r)" : "Eq. (17r)";
    Table t(describe_wall(wall, kind));
    t.add("threshold, rounded corners", io::num(c.closed_form_g), "g", eq)
        .add("threshold, sharp corners", io::num(c.sharp_closed_form_g), "g",
             kind == WallKind::vssw ? "Eq. (12)" : "Eq. (17)")
        .add("release theta0", io::num(c.theta0), "rad", "for the period");
    for (const compare::RoundedEngineResult& e : c.engines) {
        if (!e.failure.empty()) {
            t.text(e.engine, "failed: " + e.failure);
            continue;
        }
        t.add(e.engine + " threshold", io::num(e.threshold_g), "g",
              fmt::format("{} {:+.3f} %", eq, 100.0 * e.threshold_rel_error))
            .add(e.engine + " period", text_or_none(e.period, "{:.6g}"), std::isfinite(e.period) ? "s" : "",
                 !e.overturned                ? "4 x release to first impact"
                 : std::isfinite(e.period)    ? "4 x release to first impact; then the wall overturned"
                                              : "the free vibration overturned");
    }
    t.add("threshold spread", text_or_none(100.0 * c.threshold_spread, "{:.3f}"),
          std::isfinite(c.threshold_spread) ? "%" : "", "(largest - smallest) / smallest over the engines")
        .add("period spread", text_or_none(100.0 * c.period_spread, "{:.3f}"),
             std::isfinite(c.period_spread) ? "%" : "", "the model cannot follow the rolling: this is its uncertainty")
        .print(out);
}

}  // namespace vssw::cli
