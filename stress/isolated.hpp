#pragma once
// One piece of work in a child process with a time limit (`vssw stress`): a case that hangs, crashes or aborts
// inside an engine library cannot take the whole run down. The child runs the work and writes its answer (a string)
// to a pipe; the parent reads it, kills the child with SIGKILL once the limit has passed, and tells how it ended.
#include <functional>
#include <string>

namespace vssw::stress {

enum class ChildEnd {
    completed,  // the work returned; `output` is what it returned
    threw,      // the work threw; `output` is the exception's message
    timed_out,  // still running at the limit: killed
    crashed,    // ended by a signal (SIGSEGV, SIGABRT from abort(), ...): `signal` names it
    exited,     // ended with an exit code of its own (a library calling exit()): `exit_code`
};

struct ChildResult {
    ChildEnd end = ChildEnd::completed;
    std::string output;
    int signal = 0;
    int exit_code = 0;
    double time_s = 0.0;  // wall time from fork to the child's end (or the kill)
};

// Runs `work` in a forked child; time_limit_s > 0. Safe to call from several threads at once (each call forks and
// waits for its own child only). Throws std::runtime_error only when the process cannot fork or make a pipe.
ChildResult run_isolated(const std::function<std::string()>& work, double time_limit_s);

// "failed: timed out after 3.0 s", "failed: crashed (signal 6, Aborted)", ... for every end but completed.
std::string describe_end(const ChildResult& r);

}  // namespace vssw::stress
