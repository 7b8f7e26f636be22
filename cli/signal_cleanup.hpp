#pragma once
// SIGINT, SIGTERM and SIGHUP end the program as before (the default action, so the exit status is still 128 + the
// signal), after its child processes (engine workers, gnuplot) are killed and the temporary files and staging folders
// it has open are removed (analytic/child_fork.hpp, io/temp_registry.hpp): an interrupted run leaves no process and no
// hidden ".NAME.vssw-tmp-..." behind, and the files and folders it would have replaced stay as they were. (A SIGKILL
// cannot be handled: the children then end by their parent-death signal, child_fork.hpp.)
//
// The handler only writes the signal's number to a pipe (async-signal-safe); a thread waiting on the pipe removes the
// files and re-raises the signal. A forked child resets the handler to the default action at once (child_fork.hpp);
// a signal that comes before that finds the handler without its thread: the handler sees that it is not the process
// that installed it, and takes the default action at once, so a child never removes its parent's files.
//
// Only the program calls this (cli/main.cpp): the Python module runs commands in-process and keeps Python's own
// SIGINT handling. A signal ignored when the program starts (nohup, a background job of a script) stays ignored.
namespace vssw::cli {

void install_signal_cleanup();

}  // namespace vssw::cli
