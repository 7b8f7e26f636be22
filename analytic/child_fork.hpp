#pragma once
// The one way this program forks (engine workers, multibody/host/child_process.hpp; gnuplot, io/gnuplot.cpp), so that
// every child is made, ended and waited for alike:
//  - the standard streams are flushed first: a child holds a copy of the parent's unwritten output, and a child that
//    writes (an engine library's message) would write that copy too (`vssw compare --engine all > file` once wrote
//    21 blocks for 7 engines);
//  - the child dies with its parent (PR_SET_PDEATHSIG, SIGKILL): a parent killed, even by SIGKILL, leaves no engine
//    run behind to spend its CPU budget;
//  - the child takes the default action of every signal the parent handles (SIGINT, SIGTERM, ...; ignored ones stay
//    ignored, and a fault's handler stays, a sanitizer's report): a handler of the parent's that only sets a flag
//    (Python's SIGINT) would keep the child running;
//  - the parent keeps the children it has not reaped, so that its signal handling ends them before it ends
//    (cli/signal_cleanup.hpp).
// What stays the caller's: what the child runs (a child of a multi-threaded parent holds only the forking thread;
// multibody/host/child_process.hpp) and how it ends (_exit or exec).
#include <sys/types.h>

namespace vssw {

// fork() with the above. In the child: 0, or it ends at once (exit status 1) when the parent is gone already. In the
// parent: the child's pid, or -1 (errno set) when the process cannot fork.
pid_t fork_child();

// Waits for a child made by fork_child to end and reaps it: its waitpid status, or -1 when it cannot be waited for.
int wait_child(pid_t pid);

// The CPU time [s], user and system, of the children the calling thread has reaped with wait_child, summed over the
// thread's life. A forked engine run spends its CPU in its child, which the thread's own CPU clock does not see; a
// task that waits for its children on one thread adds this to its thread's CPU to know what it cost.
double reaped_children_cpu_seconds();

// Sends SIGKILL to every child made by fork_child not reaped yet, and keeps any other from being reaped or forked:
// for a process about to end (the signal handling of cli/signal_cleanup.cpp). A thread waiting for its child then
// never returns, so that no killed run is reported as failed by a process already ending.
void kill_children_before_exit();

}  // namespace vssw
