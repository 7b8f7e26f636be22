#include "apps/trajectory_csv.hpp"

#include <ostream>

#include <fmt/format.h>

#include "analytic/ground_motion.hpp"

namespace vssw::cli {

void write_trajectory_csv(std::ostream& out, const RockingModel& model, const SimulationResult& result) {
    const double alpha = model.reference_angle();
    const double v_ref = model.reference_velocity();
    const double e_ref = model.reference_energy();
    out << "t,theta_over_alpha,theta_dot_over_ref,E_over_Vr,ED_over_Vr,ag_g\n";
    for (const Sample& s : result.samples) {
        const double energy = s.kinetic + s.weight_potential - s.work_overburden;
        out << fmt::format("{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g}\n", s.t, s.theta / alpha,
                           s.theta_dot / v_ref, energy / e_ref, s.dissipated / e_ref, s.a_h / kStandardGravity);
    }
}

}  // namespace vssw::cli
