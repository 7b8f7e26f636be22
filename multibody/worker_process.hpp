#pragma once
// An engine whose library is not re-entrant (ODE: process-wide state, runs_concurrently() false) run beside itself on
// several cores: each simulate() in a forked child process of its own, its Trajectory sent back through a pipe bit for
// bit (trajectory_bytes.hpp). The results are those of the same run in the caller's process; what each run costs
// more is a fork and the copy of its trajectory (README, "ODE").
//
// Off with the environment variable VSSW_WORKER_PROCESSES=0 (then such an engine's runs take turns, as before).
// Only a pool of more than one thread uses it: with one thread nothing forks.
#include <functional>
#include <memory>
#include <string>
#include <string_view>

#include "multibody/engine.hpp"

namespace vssw::multibody {

// `inner`'s runs, each in a child process. Errors come back as they were thrown: EngineFailure and InputError with
// their messages, any other exception as std::runtime_error with its message; a child that dies by a signal, exits
// without an answer or sends a broken one is an EngineFailure saying so. The caller keeps `inner` alive.
class WorkerProcessEngine final : public Engine {
public:
    explicit WorkerProcessEngine(const Engine& inner) : inner_(inner) {}
    std::string name() const override { return inner_.name(); }
    std::string version() const override { return inner_.version(); }
    EngineSettings default_settings() const override { return inner_.default_settings(); }
    Trajectory simulate(const WallScene& scene, const Excitation& excitation,
                        const EngineSettings& settings) const override;
    void check_settings(const EngineSettings& settings) const override { inner_.check_settings(settings); }
    // Each run is a process of its own: nothing of the library is shared between them.
    bool runs_concurrently() const override { return true; }

private:
    const Engine& inner_;
};

// VSSW_WORKER_PROCESSES: unset, empty or "1" on; "0" off. Throws InputError naming any other value.
bool worker_processes_enabled();

// Whether a pool running `threads` threads at once should run `engine`'s work in worker processes: its runs cannot
// share a process (runs_concurrently() false) but can each run in a child (runs_in_worker_process()), more than one
// thread runs and worker processes are not off.
bool runs_in_worker_processes(const Engine& engine, int threads);

// Runs `work` in a forked child; what it appends to its string comes back, in a buffer of the calling thread's valid
// until its next call (child_process.hpp). Errors come back as for WorkerProcessEngine; `who` names the worker in
// the message of a child that died. A caller whose task makes several runs (a threshold search: about ten) forks
// once for the task rather than once per run (study/runner.cpp).
std::string_view run_in_worker_process(const std::function<void(std::string&)>& work, const std::string& who);

// A WorkerProcessEngine around `engine` when runs_in_worker_processes(engine, threads); otherwise nullptr (call
// `engine` itself).
std::unique_ptr<Engine> worker_process_engine_for(const Engine& engine, int threads);

}  // namespace vssw::multibody
