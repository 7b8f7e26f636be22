#pragma once
// A progress line on a terminal (`vssw report`, `vssw study`), rewritten in place and cut to 80 columns; nothing when
// the error stream is not a terminal (a log, a test's stream). Redrawn at most every tenth of a second, so that
// thousands of short tasks do not spend their time writing to the terminal; the last line always shows.
#include <unistd.h>

#include <chrono>
#include <iostream>
#include <mutex>
#include <string>

#include <fmt/format.h>

namespace vssw::cli {

class Progress {
public:
    explicit Progress(std::ostream& err) : err_(err), on_(&err == &std::cerr && isatty(STDERR_FILENO) == 1) {}
    bool on() const { return on_; }
    void show(long done, long total, const std::string& what) {
        const std::lock_guard<std::mutex> lock(mutex_);
        const auto now = std::chrono::steady_clock::now();
        if (done < total && now - last_ < kRedraw) return;
        last_ = now;
        std::string line = fmt::format("[{}/{}] {}", done, total, what);
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
    bool on_;
    std::mutex mutex_;
    std::size_t shown_ = 0;
    std::chrono::steady_clock::time_point last_{};
};

}  // namespace vssw::cli
