#pragma once
// A progress line on a terminal (`vssw report`, `vssw study`), rewritten in place and cut to 80 columns; nothing when
// the error stream is not a terminal (a log, a test's stream). Redrawn at most every tenth of a second, so that
// thousands of short tasks do not spend their time writing to the terminal; the last line always shows.
// A caller that shows progress its own way (the Python module's progress bar, python/core.cpp) sets a hook for its
// thread (ScopedProgressHook): a Progress made on that thread then hands every line to the hook instead, unthrottled.
#include <unistd.h>

#include <chrono>
#include <functional>
#include <iostream>
#include <mutex>
#include <string>

#include <fmt/format.h>

#include "io/text.hpp"

namespace vssw::cli {

// done, total, what: called from the command's worker threads, one call at a time.
using ProgressHook = std::function<void(long done, long total, const std::string& what)>;

// The hook of the calling thread, read when a Progress is made (nullptr: none).
inline thread_local const ProgressHook* progress_hook = nullptr;

// Sets the calling thread's hook for its lifetime (the previous one restored).
class ScopedProgressHook {
public:
    explicit ScopedProgressHook(const ProgressHook* hook) : previous_(progress_hook) { progress_hook = hook; }
    ~ScopedProgressHook() { progress_hook = previous_; }
    ScopedProgressHook(const ScopedProgressHook&) = delete;
    ScopedProgressHook& operator=(const ScopedProgressHook&) = delete;

private:
    const ProgressHook* previous_;
};

class Progress {
public:
    explicit Progress(std::ostream& err)
        : err_(err),
          hook_(progress_hook),
          on_(hook_ != nullptr || (&err == &std::cerr && isatty(STDERR_FILENO) == 1)) {}
    bool on() const { return on_; }
    // `what` names a case from an input: shown with its control characters escaped (a terminal, or Python's bar).
    void show(long done, long total, const std::string& what) {
        const std::lock_guard<std::mutex> lock(mutex_);
        if (hook_ != nullptr) {
            (*hook_)(done, total, io::printable(what));
            return;
        }
        const auto now = std::chrono::steady_clock::now();
        if (done < total && now - last_ < kRedraw) return;
        last_ = now;
        std::string line = fmt::format("[{}/{}] {}", done, total, io::printable(what));
        if (line.size() > kWidth) line.resize(kWidth);
        err_ << '\r' << line << std::string(shown_ > line.size() ? shown_ - line.size() : 0, ' ') << std::flush;
        shown_ = line.size();
    }
    void clear() {
        if (shown_ > 0) err_ << '\r' << std::string(shown_, ' ') << '\r' << std::flush;
        shown_ = 0;
    }

private:
    static constexpr std::size_t kWidth = 79;  // an 80-column terminal
    static constexpr std::chrono::milliseconds kRedraw{100};
    std::ostream& err_;
    const ProgressHook* hook_;
    bool on_;
    std::mutex mutex_;
    std::size_t shown_ = 0;
    std::chrono::steady_clock::time_point last_{};
};

}  // namespace vssw::cli
