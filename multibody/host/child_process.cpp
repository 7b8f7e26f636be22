#include "multibody/host/child_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/mman.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdint>
#include <chrono>
#include <cstring>
#include <new>
#include <stdexcept>
#include <string_view>

#include <fmt/format.h>

#include "analytic/child_fork.hpp"

namespace vssw::multibody {
namespace {

// The child's message: a header (the text's length, then one status byte: 'r' returned, 't' threw), then the text.
// Written whole before _exit, so a child killed half-way leaves a short message that is never read as an answer (the
// parent goes by how it ended, and by the length).
constexpr std::size_t kHeaderBytes = sizeof(std::uint64_t) + 1;

void write_all(int fd, const char* data, std::size_t size) {
    std::size_t done = 0;
    while (done < size) {
        const ssize_t n = ::write(fd, data + done, size - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return;
        done += static_cast<std::size_t>(n);
    }
}

[[noreturn]] void run_child(int fd, const std::function<std::string()>& work) {
    // Only this child's own write end stays open (and the standard streams): another thread of the parent forking at
    // the same time has its pipe's write end in this copy too, and its parent would wait for this child to end before
    // it saw the end of its own child's answer.
    if (fd > 3) ::close_range(3, static_cast<unsigned>(fd) - 1, 0);
    ::close_range(static_cast<unsigned>(fd) + 1, ~0U, 0);
    std::string text;
    char status = 'r';
    try {
        text = work();
    } catch (const std::exception& e) {
        status = 't';
        text = e.what();
    } catch (...) {
        status = 't';
        text = "unknown exception";
    }
    char header[kHeaderBytes];
    const std::uint64_t length = text.size();
    std::memcpy(header, &length, sizeof length);
    header[sizeof length] = status;
    write_all(fd, header, sizeof header);
    write_all(fd, text.data(), text.size());
    ::close(fd);
    // _exit: no atexit handlers or static destructors of the parent's copy (an engine library's globals, the test
    // framework's state) run twice.
    ::_exit(0);
}

// Where a thread receives its children's answers: pages of its own, mapped with MADV_DONTFORK so that no child shares
// them. An answer can be large (a task's rows; the suite once sent whole trajectories); received into ordinary heap
// pages, which the other threads' children share copy-on-write, every page written would fault, and in a
// multi-threaded process each such fault flushes the other cores' TLBs (measured: most of the cost of a worker
// process when answers were trajectories; docs/contributing/engines.md, "ODE").
class ReceiveBuffer {
public:
    ReceiveBuffer() = default;
    ReceiveBuffer(const ReceiveBuffer&) = delete;
    ReceiveBuffer& operator=(const ReceiveBuffer&) = delete;
    ~ReceiveBuffer() {
        if (data_) ::munmap(data_, capacity_);
    }
    char* data() { return data_; }
    std::size_t capacity() const { return capacity_; }
    // At least `want` bytes, the first `keep` kept.
    void reserve(std::size_t want, std::size_t keep) {
        if (want <= capacity_) return;
        const std::size_t page = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
        std::size_t size = std::max<std::size_t>(capacity_ * 2, 1 << 16);
        while (size < want) size *= 2;
        size = (size + page - 1) / page * page;
        void* p = ::mmap(nullptr, size, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        if (p == MAP_FAILED) throw std::bad_alloc();
        ::madvise(p, size, MADV_DONTFORK);  // an optimisation: without it the answer is the same
        if (keep) std::memcpy(p, data_, keep);
        if (data_) ::munmap(data_, capacity_);
        data_ = static_cast<char*>(p);
        capacity_ = size;
    }

private:
    char* data_ = nullptr;
    std::size_t capacity_ = 0;
};

thread_local ReceiveBuffer t_received;

std::atomic<bool> g_interrupting{false};

}  // namespace

void interrupt_children(bool on) { g_interrupting = on; }

ChildResult run_in_child(const std::function<std::string()>& work, double time_limit_s, std::string_view& answer) {
    answer = {};
    if (g_interrupting) throw RunInterrupted("interrupted: no new run is started");
    int fds[2];
    if (::pipe(fds) != 0)
        throw std::runtime_error(fmt::format("cannot make a pipe for a child process: {}", std::strerror(errno)));
    // A larger pipe: a megabyte answer in 16 turns between child and parent rather than 256 (ignored if refused).
    (void)::fcntl(fds[0], F_SETPIPE_SZ, 1 << 20);
    ReceiveBuffer& buffer = t_received;
    buffer.reserve(1 << 16, 0);
    const auto start = std::chrono::steady_clock::now();
    const pid_t pid = fork_child();  // flushed, and the child dies with this process (child_fork.hpp)
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
    std::size_t received = 0;
    std::uint64_t length = 0;  // the text's, once the header is in
    bool killed = false, interrupted = false;
    for (;;) {
        const double left = std::chrono::duration<double>(deadline - std::chrono::steady_clock::now()).count();
        if (limited && left <= 0.0) {
            ::kill(pid, SIGKILL);
            killed = true;
            break;
        }
        if (g_interrupting) {
            ::kill(pid, SIGKILL);
            interrupted = true;
            break;
        }
        pollfd p{fds[0], POLLIN, 0};
        // At most kInterruptionCheckS at a time (the deadline and interruption are checked again at the top); a limit
        // of days in milliseconds would not fit an int either (UBSan stopped
        // EngineSteps.AStepTooSmallForTheRunIsRefusedAtOnceNamingIt there).
        const double wait_s = limited ? std::min(left, kInterruptionCheckS) : kInterruptionCheckS;
        const int ready = ::poll(&p, 1, static_cast<int>(wait_s * 1000.0) + 1);
        if (ready < 0 && errno == EINTR) continue;
        if (ready <= 0) continue;  // the deadline is checked at the top
        if (received == buffer.capacity()) buffer.reserve(received + 1, received);
        const ssize_t n = ::read(fds[0], buffer.data() + received, buffer.capacity() - received);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;  // end of file: the child closed its end (returned, or died)
        const bool had_header = received >= kHeaderBytes;
        received += static_cast<std::size_t>(n);
        if (!had_header && received >= kHeaderBytes) {
            std::memcpy(&length, buffer.data(), sizeof length);
            // Room for the whole answer at once; a longer one (never met) grows the buffer as it comes, so that a broken
            // header cannot ask for any amount of memory.
            constexpr std::uint64_t kMaxReserve = std::uint64_t{1} << 28;  // 256 MiB
            buffer.reserve(kHeaderBytes + static_cast<std::size_t>(std::min(length, kMaxReserve)), received);
        }
    }
    ::close(fds[0]);
    const int status = wait_child(pid);
    if (interrupted) throw RunInterrupted("interrupted: the run was stopped");
    ChildResult r;
    r.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const bool whole = received >= kHeaderBytes && received - kHeaderBytes == length;
    const char tag = whole ? buffer.data()[sizeof length] : '\0';
    if (killed) {
        r.end = ChildEnd::timed_out;
        r.time_s = time_limit_s;
    } else if (WIFSIGNALED(status)) {
        r.end = ChildEnd::crashed;
        r.signal = WTERMSIG(status);
    } else if (WIFEXITED(status) && WEXITSTATUS(status) != 0) {
        r.end = ChildEnd::exited;
        r.exit_code = WEXITSTATUS(status);
    } else if (tag == 'r' || tag == 't') {
        r.end = tag == 'r' ? ChildEnd::completed : ChildEnd::threw;
        answer = std::string_view(buffer.data() + kHeaderBytes, length);
    } else {
        r.end = ChildEnd::exited;  // exit(0) from inside the work, without an answer
        r.exit_code = 0;
    }
    return r;
}

ChildResult run_in_child(const std::function<std::string()>& work, double time_limit_s) {
    std::string_view answer;
    ChildResult r = run_in_child(work, time_limit_s, answer);
    r.output = std::string(answer);
    return r;
}

std::string describe_end(const ChildResult& r) {
    return r.end == ChildEnd::completed ? "completed" : "failed: " + describe_failure(r);
}

std::string describe_failure(const ChildResult& r) {
    switch (r.end) {
        case ChildEnd::completed:
            return "completed";  // not a failure; callers ask only of ends that are
        case ChildEnd::threw:
            return r.output;
        case ChildEnd::timed_out:
            return fmt::format("timed out after {:.1f} s", r.time_s);
        case ChildEnd::crashed:
            return fmt::format("crashed (signal {}, {})", r.signal, ::strsignal(r.signal));
        case ChildEnd::exited:
            return fmt::format("the process exited with code {} without an answer", r.exit_code);
    }
    return "ended in an unknown way";
}

}  // namespace vssw::multibody
