#include "cli/signal_cleanup.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <thread>

#include "analytic/child_fork.hpp"
#include "io/temp_registry.hpp"

namespace vssw::cli {
namespace {

constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};

// Written once before the handlers are installed, read only after.
pid_t g_owner = 0;
int g_pipe[2] = {-1, -1};

void on_signal(int sig) {
    const int saved = errno;
    if (::getpid() != g_owner) {  // a forked child: no cleanup of the parent's files
        ::signal(sig, SIG_DFL);
        ::raise(sig);
        errno = saved;
        return;
    }
    const unsigned char byte = static_cast<unsigned char>(sig);
    [[maybe_unused]] const ssize_t n = ::write(g_pipe[1], &byte, 1);  // a full pipe: a signal already on its way
    errno = saved;
}

void watch() {
    unsigned char byte = 0;
    for (;;) {
        const ssize_t n = ::read(g_pipe[0], &byte, 1);
        if (n == 1) break;
        if (n < 0 && errno == EINTR) continue;
        return;  // the pipe is gone: nothing to watch
    }
    // The children first (engine workers, gnuplot): none outlives the program, and none that ends now is reported as a
    // failed run by a process already ending (child_fork.hpp).
    vssw::kill_children_before_exit();
    vssw::io::remove_registered_temps();
    const int sig = byte;
    ::signal(sig, SIG_DFL);
    // The default action of these signals ends the whole process, with the status of a death by the signal.
    ::kill(::getpid(), sig);
}

}  // namespace

void install_signal_cleanup() {
    if (g_owner != 0) return;
    if (::pipe2(g_pipe, O_CLOEXEC) != 0) return;  // no cleanup, but the program runs as before
    g_owner = ::getpid();
    std::thread(watch).detach();
    for (const int sig : kSignals) {
        struct sigaction old {};
        if (::sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;
        struct sigaction sa {};
        sa.sa_handler = on_signal;
        sigemptyset(&sa.sa_mask);
        sa.sa_flags = SA_RESTART;
        ::sigaction(sig, &sa, nullptr);
    }
}

}  // namespace vssw::cli
