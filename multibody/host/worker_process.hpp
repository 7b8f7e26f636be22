#pragma once
// Work in a forked child of its own, its answer sent back through a pipe, its errors rethrown as their own types: how
// each engine library's run is isolated (isolated_engine.hpp). The results are those of the same work in the
// caller's process; what it costs more is a fork (docs/contributing/engines.md, "Isolation").
#include <functional>
#include <string>
#include <string_view>

#include "multibody/engine.hpp"

namespace vssw::multibody {

// What a worker may spend (isolated_engine.hpp gives each engine run its budget). cpu_seconds > 0: the kernel stops
// the child past that much CPU time (RLIMIT_CPU), and the EngineFailure says it passed `budget` (words naming the
// budget and how to change it). wall_seconds > 0: a child still running then (waiting on a lock, say: no CPU used)
// is killed and the EngineFailure says so. Zero: no limit.
struct WorkerLimits {
    double cpu_seconds = 0.0;
    double wall_seconds = 0.0;
    std::string budget;
};

// Runs `work` in a forked child; what it appends to its string comes back, in a buffer of the calling thread's valid
// until its next call (child_process.hpp). Errors come back as they were thrown: EngineFailure and InputError with
// their messages, any other exception as std::runtime_error with its message; a child that dies by a signal, exits
// without an answer or sends a broken one is an EngineFailure saying so, but one ended by SIGINT, SIGTERM or SIGHUP
// (interrupted, not failed) is a RunInterrupted (child_process.hpp), as is every run while interruption is on. `who` names the worker in
// the message of a child that died.
std::string_view run_in_worker_process(const std::function<void(std::string&)>& work, const std::string& who,
                                       const WorkerLimits& limits = {});

}  // namespace vssw::multibody
