#include "analytic/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <sstream>

#include <fmt/format.h>

#include "analytic/error.hpp"

namespace vssw {
namespace {

// What a non-regular file is, for the message.
const char* kind_of(mode_t mode) {
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a file";
}

// Closes the descriptor however the checks end.
struct Descriptor {
    int fd;
    ~Descriptor() {
        if (fd >= 0) ::close(fd);
    }
};

}  // namespace

std::ifstream open_input_file(const std::filesystem::path& path, const std::string& what, std::uintmax_t max_bytes) {
    // O_NONBLOCK: opening a FIFO no one writes to returns at once (a blocking open would wait for a writer forever).
    const Descriptor d{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
    if (d.fd < 0)
        throw InputError(fmt::format("cannot open {} '{}': {}", what, path.string(),
                                     errno == ENOENT ? "no such file" : std::strerror(errno)));
    struct stat st {};
    if (::fstat(d.fd, &st) != 0)
        throw InputError(fmt::format("cannot open {} '{}': {}", what, path.string(), std::strerror(errno)));
    if (S_ISDIR(st.st_mode)) throw InputError(fmt::format("{} '{}' is a directory", what, path.string()));
    if (!S_ISREG(st.st_mode))
        throw InputError(
            fmt::format("{} '{}' is not a regular file ({}): vssw reads only files", what, path.string(), kind_of(st.st_mode)));
    if (static_cast<std::uintmax_t>(st.st_size) > max_bytes)
        throw InputError(fmt::format("{} '{}' has {} bytes, more than the {} allowed", what, path.string(),
                                     static_cast<std::uintmax_t>(st.st_size), max_bytes));
    // The stream opens the file already checked (its descriptor's /proc entry), not whatever the name holds by now;
    // without /proc, the name again (a swap in these microseconds is the only way past the checks above).
    std::ifstream in(fmt::format("/proc/self/fd/{}", d.fd), std::ios::binary);
    if (!in) in.open(path, std::ios::binary);
    if (!in) throw InputError(fmt::format("cannot open {} '{}': {}", what, path.string(), std::strerror(errno)));
    return in;
}

std::string read_input_file(const std::filesystem::path& path, const std::string& what, std::uintmax_t max_bytes) {
    std::ifstream in = open_input_file(path, what, max_bytes);
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw InputError(fmt::format("error while reading {} '{}'", what, path.string()));
    // A file that grew past its bound after it was opened is refused all the same.
    if (text.str().size() > max_bytes)
        throw InputError(fmt::format("{} '{}' has more than the {} bytes allowed", what, path.string(), max_bytes));
    return text.str();
}

}  // namespace vssw
