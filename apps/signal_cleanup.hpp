#pragma once
// SIGINT, SIGTERM and SIGHUP end the program as before (the default action, so the exit status is still 128 + the
// signal), after the temporary files and staging folders it has open are removed (io/temp_registry.hpp): an
// interrupted run leaves no hidden ".NAME.vssw-tmp-..." behind, and the files and folders it would have replaced
// stay as they were.
//
// The handler only writes the signal's number to a pipe (async-signal-safe); a thread waiting on the pipe removes the
// files and re-raises the signal. A forked child that has not exec'd yet (an engine's worker process, gnuplot being
// started) inherits the handler but not the thread: the handler sees that it is not the process that installed it,
// and takes the default action at once, so a child never removes its parent's files.
//
// Only the program calls this (apps/main.cpp): the Python module runs commands in-process and keeps Python's own
// SIGINT handling. A signal ignored when the program starts (nohup, a background job of a script) stays ignored.
namespace vssw::cli {

void install_signal_cleanup();

}  // namespace vssw::cli
