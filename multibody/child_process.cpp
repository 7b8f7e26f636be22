#include "multibody/child_process.hpp"

#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <stdexcept>

#include <fmt/format.h>

namespace vssw::multibody {
namespace {

// The child's message: one status byte ('r' returned, 't' threw) then the text. Written whole before _exit, so a
// child killed half-way leaves a short message that is never read as an answer (the parent goes by how it ended).
void write_all(int fd, const std::string& text) {
    size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return;
        done += static_cast<size_t>(n);
    }
}

[[noreturn]] void run_child(int fd, const std::function<std::string()>& work) {
    // Only this child's own write end stays open (and the standard streams): another thread of the parent forking at
    // the same time has its pipe's write end in this copy too, and its parent would wait for this child to end before
    // it saw the end of its own child's answer.
    if (fd > 3) ::close_range(3, static_cast<unsigned>(fd) - 1, 0);
    ::close_range(static_cast<unsigned>(fd) + 1, ~0U, 0);
    std::string message;
    try {
        message = "r" + work();
    } catch (const std::exception& e) {
        message = std::string("t") + e.what();
    } catch (...) {
        message = "tunknown exception";
    }
    write_all(fd, message);
    ::close(fd);
    // _exit: no atexit handlers or static destructors of the parent's copy (an engine library's globals, the test
    // framework's state) run twice.
    ::_exit(0);
}

thread_local double t_children_cpu = 0.0;  // reaped_children_cpu_seconds()

double seconds(const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec); }

}  // namespace

double reaped_children_cpu_seconds() { return t_children_cpu; }

ChildResult run_in_child(const std::function<std::string()>& work, double time_limit_s) {
    int fds[2];
    if (::pipe(fds) != 0) throw std::runtime_error(fmt::format("cannot make a pipe for a child process: {}", std::strerror(errno)));
    const auto start = std::chrono::steady_clock::now();
    const pid_t pid = ::fork();
    if (pid < 0) {
        ::close(fds[0]);
        ::close(fds[1]);
        throw std::runtime_error(fmt::format("cannot fork a child process: {}", std::strerror(errno)));
    }
    if (pid == 0) {
        ::close(fds[0]);
        run_child(fds[1], work);
    }
    ::close(fds[1]);
    const bool limited = time_limit_s > 0.0;
    const auto deadline = start + std::chrono::duration<double>(limited ? time_limit_s : 0.0);
    std::string message;
    bool killed = false;
    std::string buffer(1 << 16, '\0');  // a run's trajectory is megabytes: read it in large pieces
    for (;;) {
        const double left = std::chrono::duration<double>(deadline - std::chrono::steady_clock::now()).count();
        if (limited && left <= 0.0) {
            ::kill(pid, SIGKILL);
            killed = true;
            break;
        }
        pollfd p{fds[0], POLLIN, 0};
        const int ready = ::poll(&p, 1, limited ? static_cast<int>(left * 1000.0) + 1 : -1);
        if (ready < 0 && errno == EINTR) continue;
        if (ready <= 0) continue;  // the deadline is checked at the top
        const ssize_t n = ::read(fds[0], buffer.data(), buffer.size());
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;  // end of file: the child closed its end (returned, or died)
        message.append(buffer.data(), static_cast<size_t>(n));
    }
    ::close(fds[0]);
    int status = 0;
    rusage usage{};
    while (::wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {
    }
    t_children_cpu += seconds(usage.ru_utime) + seconds(usage.ru_stime);
    ChildResult r;
    r.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (killed) {
        r.end = ChildEnd::timed_out;
        r.time_s = time_limit_s;
    } else if (WIFSIGNALED(status)) {
        r.end = ChildEnd::crashed;
        r.signal = WTERMSIG(status);
    } else if (WIFEXITED(status) && WEXITSTATUS(status) != 0) {
        r.end = ChildEnd::exited;
        r.exit_code = WEXITSTATUS(status);
    } else if (!message.empty() && message[0] == 'r') {
        r.end = ChildEnd::completed;
        r.output = message.substr(1);
    } else if (!message.empty() && message[0] == 't') {
        r.end = ChildEnd::threw;
        r.output = message.substr(1);
    } else {
        r.end = ChildEnd::exited;  // exit(0) from inside the work, without an answer
        r.exit_code = 0;
    }
    return r;
}

std::string describe_end(const ChildResult& r) {
    switch (r.end) {
        case ChildEnd::completed:
            return "completed";
        case ChildEnd::threw:
            return "failed: " + r.output;
        case ChildEnd::timed_out:
            return fmt::format("failed: timed out after {:.1f} s", r.time_s);
        case ChildEnd::crashed:
            return fmt::format("failed: crashed (signal {}, {})", r.signal, ::strsignal(r.signal));
        case ChildEnd::exited:
            return fmt::format("failed: the process exited with code {} without an answer", r.exit_code);
    }
    return "failed";
}

}  // namespace vssw::multibody
