#include "analytic/child_fork.hpp"

#include <pthread.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <iostream>
#include <iterator>
#include <mutex>
#include <vector>

namespace vssw {
namespace {

// The signals a fault of the child's own raises: a handler of the parent's for them (a sanitizer's report) is kept.
constexpr int kFaultSignals[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGTRAP, SIGSYS};

// The children not reaped yet, and the lock under which one is reaped or all are killed. Held across every fork (in
// parent and child, pthread_atfork), so that no child starts with a copy held by a thread it does not have.
std::mutex g_reaping;
// reaped_children_cpu_seconds(): per thread, as each thread waits for its own children.
thread_local double t_reaped_cpu_s = 0.0;
std::vector<pid_t> g_children;

void hold_across_fork() {
    static std::once_flag once;
    std::call_once(once, [] {
        (void)::pthread_atfork([] { g_reaping.lock(); }, [] { g_reaping.unlock(); }, [] { g_reaping.unlock(); });
    });
}

bool is_fault_signal(int sig) {
    return std::find(std::begin(kFaultSignals), std::end(kFaultSignals), sig) != std::end(kFaultSignals);
}

// In the child, before it runs anything (async-signal-safe calls only: gnuplot's child execs next).
void become_child(pid_t parent) {
    (void)::prctl(PR_SET_PDEATHSIG, SIGKILL);
    // The parent may have ended between the fork and the line above, the child then adopted by another process.
    if (::getppid() != parent) ::_exit(1);
    for (int sig = 1; sig < NSIG; ++sig) {
        struct sigaction old {};
        if (is_fault_signal(sig) || ::sigaction(sig, nullptr, &old) != 0) continue;
        const bool handled = (old.sa_flags & SA_SIGINFO) ? old.sa_sigaction != nullptr
                                                          : old.sa_handler != SIG_DFL && old.sa_handler != SIG_IGN;
        if (!handled) continue;
        struct sigaction plain {};
        plain.sa_handler = SIG_DFL;
        sigemptyset(&plain.sa_mask);
        (void)::sigaction(sig, &plain, nullptr);
    }
    sigset_t none;
    sigemptyset(&none);
    (void)::sigprocmask(SIG_SETMASK, &none, nullptr);
}

}  // namespace

pid_t fork_child() {
    std::cout.flush();
    std::cerr.flush();
    std::clog.flush();
    (void)std::fflush(nullptr);
    hold_across_fork();
    const pid_t parent = ::getpid();
    const pid_t pid = ::fork();
    if (pid == 0) {
        become_child(parent);
        return 0;
    }
    if (pid > 0) {
        const std::lock_guard<std::mutex> lock(g_reaping);
        g_children.push_back(pid);
    }
    return pid;
}

int wait_child(pid_t pid) {
    // Until it has ended, without reaping it (its pid stays its own, so kill_children_before_exit cannot reach another
    // process of that pid); then reaped under the lock.
    siginfo_t info{};
    while (::waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOWAIT) != 0 && errno == EINTR) {
    }
    const std::lock_guard<std::mutex> lock(g_reaping);
    g_children.erase(std::remove(g_children.begin(), g_children.end(), pid), g_children.end());
    int status = 0;
    rusage usage{};
    while (::wait4(pid, &status, 0, &usage) < 0)
        if (errno != EINTR) return -1;
    auto seconds = [](const timeval& t) {
        return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec);
    };
    t_reaped_cpu_s += seconds(usage.ru_utime) + seconds(usage.ru_stime);
    return status;
}

double reaped_children_cpu_seconds() { return t_reaped_cpu_s; }

void kill_children_before_exit() {
    g_reaping.lock();  // never released: the process ends
    for (const pid_t pid : g_children) (void)::kill(pid, SIGKILL);
}

}  // namespace vssw
