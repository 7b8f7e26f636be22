#pragma once
// A study task run in a worker process (multibody/worker_process.hpp): its journal text, or, when the worker dies
// (a crash inside the engine's library: a signal, an exit without an answer), the text `on_death` makes of the reason
// (study/runner.cpp: the task's rows, each failed with it). A crash then fails one task's rows, not the study.
#include <functional>
#include <string>

#include "multibody/worker_process.hpp"

namespace vssw::study {

inline std::string run_task_in_worker(const std::function<std::string()>& task, const std::string& who,
                                      const std::function<std::string(const std::string&)>& on_death) {
    try {
        return std::string(multibody::run_in_worker_process([&](std::string& out) { out += task(); }, who));
    } catch (const multibody::EngineFailure& f) {  // measure() keeps a run's own failures as rows: this is the worker
        return on_death(f.what());
    }
}

}  // namespace vssw::study
