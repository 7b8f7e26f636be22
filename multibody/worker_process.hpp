#pragma once
// An engine whose library is not re-entrant (ODE: process-wide state, runs_concurrently() false) run beside itself on
// several cores: a caller's piece of work (a study's task: a threshold search's ten runs, a free vibration) in a forked
// child of its own, its answer sent back through a pipe. The results are those of the same work in the caller's
// process; what it costs more is a fork (docs/engines.md, "ODE": threads).
//
// Off with the environment variable VSSW_WORKER_PROCESSES=0 (then such an engine's tasks take turns, as before).
// Only a pool of more than one thread uses it: with one thread nothing forks.
#include <functional>
#include <string>
#include <string_view>

#include "multibody/engine.hpp"

namespace vssw::multibody {

// VSSW_WORKER_PROCESSES: unset, empty or "1" on; "0" off. Throws InputError naming any other value.
bool worker_processes_enabled();

// Whether a pool running `threads` threads at once should run `engine`'s work in worker processes: its runs cannot
// share a process (runs_concurrently() false) but can each run in a child (runs_in_worker_process()), more than one
// thread runs and worker processes are not off.
bool runs_in_worker_processes(const Engine& engine, int threads);

// Runs `work` in a forked child; what it appends to its string comes back, in a buffer of the calling thread's valid
// until its next call (child_process.hpp). Errors come back as they were thrown: EngineFailure and InputError with
// their messages, any other exception as std::runtime_error with its message; a child that dies by a signal, exits
// without an answer or sends a broken one is an EngineFailure saying so. `who` names the worker in
// the message of a child that died. A caller whose task makes several runs (a threshold search: about ten) forks
// once for the task rather than once per run (study/runner.cpp).
std::string_view run_in_worker_process(const std::function<void(std::string&)>& work, const std::string& who);

}  // namespace vssw::multibody
