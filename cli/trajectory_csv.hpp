#pragma once
// The trajectory CSV of `vssw history --csv` and `vssw free --csv`: one row per sample, in the model's reference units,
// to a file or to standard output.
#include <functional>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "analytic/model.hpp"
#include "analytic/simulate.hpp"
#include "io/atomic_file.hpp"

namespace vssw::cli {

// Header "t,theta1_over_alpha1,theta_dot_over_ref,E_over_Vr,ED_over_Vr,ag_g", then the samples (10 significant digits).
void write_trajectory_csv(std::ostream& out, const RockingModel& model, const SimulationResult& result);

// Where --csv sends the trajectory: nowhere (not given), standard output ("-": the summary then goes to the error
// stream), or a file written under a temporary name and renamed onto it after the run (created at once, so that an
// unwritable path fails before the run; a failed run leaves an existing file as it was and prints no rows).
class TrajectoryCsv {
public:
    // InputError for an empty path, for "-" together with --json (both would go to standard output), and for a path
    // that is one of `inputs` (the files the run reads: the rename would replace a record with its own trajectory).
    TrajectoryCsv(const std::optional<std::string>& path, bool json, const std::vector<std::string>& inputs = {});
    bool wanted() const { return to_stdout_ || file_ != nullptr; }
    // After a successful run.
    void write(std::ostream& out, const RockingModel& model, const SimulationResult& result);
    // The same with any writer of the rows (an engine's trajectory: cli/engine_runs.hpp).
    void write_with(std::ostream& out, const std::function<void(std::ostream&)>& rows);
    // The stream the command's table or JSON goes to.
    std::ostream& summary(std::ostream& out, std::ostream& err) const { return to_stdout_ ? err : out; }

private:
    bool to_stdout_;
    std::unique_ptr<io::AtomicFile> file_;
};

}  // namespace vssw::cli
