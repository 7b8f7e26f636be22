#include "cli/friction_option.hpp"

#include <cmath>
#include <cstdlib>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "analytic/error.hpp"
#include "multibody/kit/slip_meter.hpp"

namespace vssw::cli {
namespace {

// One coefficient as typed: a finite number > 0, all of the item.
std::optional<double> coefficient(const std::string& item) {
    char* end = nullptr;
    const double mu = std::strtod(item.c_str(), &end);
    if (item.empty() || *end != '\0' || !std::isfinite(mu) || !(mu > 0.0)) return std::nullopt;
    return mu;
}

io::Json time_or_null(const std::optional<double>& t) { return t ? io::Json(*t) : io::Json(nullptr); }

}  // namespace

void add_friction_option(CLI::App& cmd, std::optional<std::string>& text) {
    cmd.add_option("--friction", text,
                   "Coulomb friction of the engines' contacts, MU (base and hinge) or MU_BASE,MU_HINGE, each > 0: "
                   "sliding becomes a measured response (slip in the JSON) and the analytic model says whether it "
                   "would slide (default: 2, where nothing slides and a slide fails the run)");
}

multibody::WallScene with_friction(multibody::WallScene scene, const std::optional<std::string>& text) {
    if (!text) return scene;
    const std::string& t = *text;
    const auto comma = t.find(',');
    const std::optional<double> base = coefficient(t.substr(0, comma));
    const std::optional<double> hinge =
        comma == std::string::npos ? base : coefficient(t.substr(comma + 1));
    if (!base || !hinge)
        throw InputError(fmt::format("--friction must be MU or MU_BASE,MU_HINGE, finite numbers > 0, got '{}'", t));
    scene.friction = *base;
    if (comma != std::string::npos) scene.hinge_friction = *hinge;
    scene.slip_measured = true;
    return scene;
}

io::Json friction_json(const multibody::WallScene& scene) {
    if (!scene.slip_measured) return nullptr;
    return {{"base", scene.base_mu()}, {"hinge", scene.vssw ? io::Json(scene.hinge_mu()) : io::Json(nullptr)}};
}

io::Json slip_json(const multibody::SlipMeasures& s, bool has_hinge) {
    auto contact = [&](double largest, double residual) {
        return io::Json{{"largest_m", largest}, {"largest_b", largest / s.b}, {"residual_m", residual},
                        {"residual_b", residual / s.b}};
    };
    return {{"base", contact(s.base_largest, s.base_residual)},
            {"hinge", has_hinge ? contact(s.hinge_largest, s.hinge_residual) : io::Json(nullptr)},
            {"tolerance_b", multibody::kSlipTolerance},
            {"t_first_slip", time_or_null(s.t_first_slip)},
            {"t_first_lift", time_or_null(s.t_first_lift)},
            {"slid_before_rocking", s.slid_before_rocking()},
            {"slid_off", s.slid_off ? io::Json(*s.slid_off) : io::Json(nullptr)}};
}

}  // namespace vssw::cli
