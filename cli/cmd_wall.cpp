// `vssw wall`: the closed forms of a VSSW and of the parapet of the same size.
#include <memory>
#include <ostream>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "cli/wall_output.hpp"
#include "io/json.hpp"

namespace vssw::cli {

Command add_wall_command(CLI::App& root) {
    struct Options {
        WallOptions wall;
        bool json = false;
    };
    auto o = std::make_shared<Options>();
    CLI::App* cmd = root.add_subcommand(
        "wall", "Closed forms of a VSSW (Sorrentino, Masiani & Griffith 2008) and of the parapet of the same size");
    add_wall_options(*cmd, o->wall, false);
    add_corner_radius_option(*cmd, o->wall);
    cmd->add_flag("--json", o->json, "print JSON instead of a table");
    cmd->footer(
        "Angles in rad, lengths in m, accelerations in g (the wall's --g), velocities in rad/s.\n"
        "JSON keys: height, thickness, hinge_ratio, xi, density, g, alpha1, alpha2, R1, R2, threshold_g (Eq. 12),\n"
        "restitution (Eq. 19), A, P (Eq. 21), theta_lim (Eq. 26; null with the hinge at or below mid-height),\n"
        "period_half_A (Eq. 22 at A/2), collapse_angle, reference_velocity (Eq. 24),\n"
        "threshold_ratio_vssw_over_parapet, optimal_hinge_ratio (Eq. 15),\n"
        "parapet {alpha, R, threshold_g (Eq. 17), restitution, p} (Housner 1963).\n"
        "With --corner-radius, corner_radius and the thresholds of Eq. (12r) and (17r); every other figure is the\n"
        "sharp blocks'. The parapet's threshold_g and the ratio are null when that parapet cannot stand (N off\n"
        "centre outside its rounded pivot's flat); a VSSW that cannot stand is refused.");
    return {cmd, [o](std::ostream& out) {
                const WallFigures figures = wall_figures(o->wall);
                if (o->json)
                    out << io::dump_json(to_json(figures), 2) << '\n';
                else
                    print_wall(out, figures);
            }};
}

}  // namespace vssw::cli
