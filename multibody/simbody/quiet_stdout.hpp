#pragma once
// Silencing stdout while Simbody steps (both Simbody routes use it).
#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <iostream>
#include <mutex>

namespace vssw::multibody {

// Debian's libsimbody 3.7 is built without NDEBUG, and SemiExplicitEulerTimeStepper then prints its working to
// stdout (printf and std::cout, several lines with whole vectors every step): it would corrupt `vssw compare --json`
// and cost most of the run time (measured: 178 s for `vssw compare` on the Fig. 6 VSSW with the text going to a
// pipe). The text has no switch (plain #ifndef NDEBUG in the library), so it is stopped before it is formatted:
//  - std::cout is put in a failed state, so every << returns at its sentry;
//  - the C stream `stdout` (glibc documents it as an assignable variable) is pointed at /dev/null opened READ-only:
//    printf, puts and putchar on a stream not open for writing return EOF before formatting anything (glibc's
//    check of _IO_NO_WRITES). Redirecting only the file descriptor, as before, let printf format every line and
//    throw it away: 21 % of the rigid route's instructions on a Fig. 6 VSSW free vibration
//    (docs/contributing/engines.md "Simbody (3.7)", where the time goes);
//  - file descriptor 1 goes to /dev/null as well, for anything written to it directly.
// All three are restored, and what was buffered flushed, when the last run ends, normally or not.
// This is process-wide state, so it is counted: runs on several threads at once (vssw report) share one silence,
// begun by the first and ended by the last; nothing else may write to stdout meanwhile.
class QuietStdout {
public:
    QuietStdout() {
        const std::lock_guard<std::mutex> lock(mutex());
        State& st = state();
        if (st.users++ > 0) return;
        std::cout.flush();
        std::fflush(stdout);
        st.saved_fd = ::dup(1);
        const int null_fd = ::open("/dev/null", O_WRONLY);
        if (st.saved_fd >= 0 && null_fd >= 0) ::dup2(null_fd, 1);
        if (null_fd >= 0) ::close(null_fd);
        st.saved_iostate = std::cout.rdstate();
        std::cout.setstate(std::ios::badbit);
        st.null_stream = std::fopen("/dev/null", "r");
        if (st.null_stream != nullptr) {
            st.saved_stream = stdout;
            stdout = st.null_stream;
        }
    }
    ~QuietStdout() {
        const std::lock_guard<std::mutex> lock(mutex());
        State& st = state();
        if (--st.users > 0) return;
        if (st.null_stream != nullptr) {
            stdout = st.saved_stream;
            std::fclose(st.null_stream);
            st.null_stream = nullptr;
        }
        std::fflush(stdout);  // Simbody's leftover text goes to /dev/null, not to the restored stdout
        std::cout.clear(st.saved_iostate);
        if (st.saved_fd >= 0) {
            ::dup2(st.saved_fd, 1);
            ::close(st.saved_fd);
            st.saved_fd = -1;
        }
    }
    QuietStdout(const QuietStdout&) = delete;
    QuietStdout& operator=(const QuietStdout&) = delete;

private:
    struct State {
        int users = 0;
        int saved_fd = -1;
        std::ios::iostate saved_iostate{};
        std::FILE* saved_stream = nullptr;  // the process's stdout while null_stream stands in for it
        std::FILE* null_stream = nullptr;   // /dev/null opened for reading: printf to it formats nothing
    };
    static State& state() {
        static State s;
        return s;
    }
    static std::mutex& mutex() {
        static std::mutex m;
        return m;
    }
};

}  // namespace vssw::multibody
