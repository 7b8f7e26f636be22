#include "cli/trajectory_csv.hpp"

#include <filesystem>
#include <ostream>
#include <system_error>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "analytic/ground_motion.hpp"

namespace vssw::cli {

void write_trajectory_csv(std::ostream& out, const RockingModel& model, const SimulationResult& result) {
    const double alpha = model.reference_angle();
    const double v_ref = model.reference_velocity();
    const double e_ref = model.reference_energy();
    out << "t,theta1_over_alpha1,theta_dot_over_ref,E_over_Vr,ED_over_Vr,ag_g\n";
    for (const Sample& s : result.samples) {
        const double energy = s.kinetic + s.weight_potential - s.work_overburden;
        out << fmt::format("{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g}\n", s.t, s.theta / alpha,
                           s.theta_dot / v_ref, energy / e_ref, s.dissipated / e_ref, s.a_h / vssw::kStandardGravity);
    }
}

TrajectoryCsv::TrajectoryCsv(const std::optional<std::string>& path, bool json, const std::vector<std::string>& inputs)
    : to_stdout_(path == "-") {
    if (!path) return;
    if (path->empty()) throw InputError("--csv: the path is empty (give a file name, or - for standard output)");
    if (to_stdout_ && json)
        throw InputError("--csv - and --json both write to standard output: give the CSV a file name");
    if (to_stdout_) return;
    for (const std::string& input : inputs) {
        std::error_code ec;
        if (std::filesystem::equivalent(*path, input, ec))
            throw InputError(fmt::format("--csv '{}' is the file '{}' the run reads: writing the trajectory there "
                                         "would replace it; give the CSV another name",
                                         *path, input));
    }
    file_ = std::make_unique<io::AtomicFile>(*path);
}

void TrajectoryCsv::write(std::ostream& out, const RockingModel& model, const SimulationResult& result) {
    write_with(out, [&](std::ostream& to) { write_trajectory_csv(to, model, result); });
}

void TrajectoryCsv::write_with(std::ostream& out, const std::function<void(std::ostream&)>& rows) {
    if (to_stdout_) rows(out);
    if (file_) {
        rows(file_->stream());
        file_->commit();
    }
}

}  // namespace vssw::cli
