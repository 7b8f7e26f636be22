#pragma once
// One stress case in a child process with a time limit (`vssw stress`): a case that hangs, crashes or aborts inside
// an engine library cannot take the whole run down. The fork, the pipe and the verdict on how the child ended are
// multibody/child_process.hpp's, shared with the worker processes that run ODE beside itself.
#include <functional>
#include <string>

#include "multibody/child_process.hpp"

namespace vssw::stress {

using multibody::ChildEnd;
using multibody::ChildResult;
using multibody::describe_end;

// Runs `work` in a forked child; time_limit_s > 0 (multibody::run_in_child).
inline ChildResult run_isolated(const std::function<std::string()>& work, double time_limit_s) {
    return multibody::run_in_child(work, time_limit_s);
}

}  // namespace vssw::stress
