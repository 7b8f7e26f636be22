#pragma once
// One piece of work in a forked child process, its answer (a string) written to a pipe: how `vssw stress` keeps a
// case that hangs, crashes or aborts inside an engine library from taking the run down (stress/run.hpp), and how
// a library that is not re-entrant runs beside itself on several cores (worker_process.hpp). The parent reads the
// answer, kills the child with SIGKILL once a time limit (if any) has passed, and tells how it ended.
//
// The child is a copy of a possibly multi-threaded parent holding only the thread that forked: the work may take no
// lock another thread could have held at the fork (malloc and stdio are safe: glibc resets their locks in the child),
// and it ends with _exit (no atexit handlers, static destructors or stdio flushes of the parent's copy run twice).
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace vssw::multibody {

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

// The command was interrupted while a child ran (Ctrl-C): the work's caller gets no answer and should stop, not record
// a failed run. Thrown by run_in_child while interruption is on (interrupt_children), and by worker_process.hpp for
// a worker ended by SIGINT, SIGTERM or SIGHUP (the terminal's Ctrl-C reaches the whole process group).
class RunInterrupted : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// On: every run_in_child waiting for its child kills it (within kInterruptionCheckS) and throws RunInterrupted, and a
// new call throws it before it forks. Off: runs go on as before. For a caller that handles the interruption itself
// (the Python module's Ctrl-C, python/core.cpp); the program's signal handling ends the whole process instead.
void interrupt_children(bool on);
inline constexpr double kInterruptionCheckS = 0.1;  // how soon a waiting caller sees interrupt_children(true)

// Runs `work` in a forked child; time_limit_s > 0 kills it at that limit, 0 waits as long as it runs. Safe to call
// from several threads at once (each call forks and waits for its own child only). Throws std::runtime_error only
// when the process cannot fork or make a pipe.
ChildResult run_in_child(const std::function<std::string()>& work, double time_limit_s);
// The same with the answer (of a child that completed or threw) left where it was received, in a buffer of the calling
// thread's that no child shares, valid until the thread's next call; r.output stays empty. For large answers.
ChildResult run_in_child(const std::function<std::string()>& work, double time_limit_s, std::string_view& answer);

// "failed: timed out after 3.0 s", "failed: crashed (signal 6, Aborted)", ... for every end but completed.
std::string describe_end(const ChildResult& r);
// describe_end without its "failed: ": "timed out after 3.0 s", ... (for an end that is not completed).
std::string describe_failure(const ChildResult& r);

}  // namespace vssw::multibody
