#include "io/folder_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "io/temp_registry.hpp"

namespace vssw::io {
namespace {

// Tries to take the lock: another process may lock the file, then remove it as it lets go, between our open and our
// flock. The file we locked must still be the one named beside the folder; a few tries settle it (each a race of
// microseconds).
constexpr int kLockTries = 5;

// The process id a lock file holds, as text ("" when it holds none yet).
std::string holder(int fd) {
    char buf[32] = {};
    const ssize_t n = ::pread(fd, buf, sizeof buf - 1, 0);
    std::string s = n > 0 ? std::string(buf, static_cast<std::size_t>(n)) : std::string();
    while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
    return s;
}

// Whether the descriptor is still the file named `path` (nobody removed or replaced it after we opened it).
bool still_named(int fd, const std::filesystem::path& path) {
    struct stat held {}, named {};
    return ::fstat(fd, &held) == 0 && ::stat(path.c_str(), &named) == 0 && held.st_dev == named.st_dev &&
           held.st_ino == named.st_ino;
}

}  // namespace

std::filesystem::path resolve_out(const std::filesystem::path& dir) {
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::path p = fs::weakly_canonical(fs::absolute(dir), ec);
    if (ec) p = fs::absolute(dir).lexically_normal();
    while (p.has_parent_path() && p.filename().empty() && p != p.root_path()) p = p.parent_path();
    return p;
}

FolderLock::FolderLock(const std::filesystem::path& dir) {
    namespace fs = std::filesystem;
    const fs::path target = resolve_out(dir);
    // The folders the lock file goes in, made when missing (and removed again when the command lets go of the lock
    // with nothing put in them): one place for the lock whatever exists yet.
    path_ = target.parent_path() / fmt::format(".{}{}", target.filename().string(), kLockSuffix);
    std::error_code ec;
    for (fs::path p = target.parent_path(); !fs::exists(p, ec) && p.has_relative_path(); p = p.parent_path()) made_ = p;
    fs::create_directories(target.parent_path(), ec);
    if (ec) {
        remove_made();
        throw InputError(fmt::format("--out '{}': cannot make the folder '{}': {}", dir.string(),
                                     target.parent_path().string(), ec.message()));
    }
    const fs::path path = path_;
    for (int attempt = 0; attempt < kLockTries; ++attempt) {
        register_temp(path);  // before it exists: SIGINT/SIGTERM remove it (cli/signal_cleanup.hpp)
        // O_CLOEXEC: gnuplot and other programs run by vssw do not inherit the lock.
        const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
        if (fd < 0) {
            const int err = errno;
            unregister_temp(path);
            remove_made();
            throw InputError(fmt::format("--out '{}': cannot make the lock file '{}': {}", dir.string(), path.string(),
                                         std::strerror(err)));
        }
        if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
            const int err = errno;
            const std::string pid = holder(fd);
            ::close(fd);
            unregister_temp(path);  // another process's file: not ours to remove
            remove_made();
            if (err == EWOULDBLOCK)
                throw InputError(fmt::format("--out '{}' is in use by another vssw command ({}): wait for it to end, "
                                             "or give another --out",
                                             dir.string(), pid.empty() ? "a process" : "process " + pid));
            // A file system without locks (ENOLCK, EOPNOTSUPP on some network mounts): the command runs as it did
            // before there were locks, rather than not at all.
            return;
        }
        if (still_named(fd, path)) {
            const std::string pid = fmt::format("{}\n", static_cast<long>(::getpid()));
            if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, pid.data(), pid.size(), 0) < 0) {
                // The lock holds without the id: a refused run then names "a process".
            }
            fd_ = fd;
            return;
        }
        ::close(fd);
        unregister_temp(path);
    }
    remove_made();
    throw InputError(fmt::format("--out '{}': cannot lock '{}': it keeps being replaced", dir.string(), path.string()));
}

void FolderLock::release() noexcept {
    if (fd_ < 0) return;
    // Removed while still held: a process that opened it meanwhile finds, once it has the lock, that it is no longer
    // the file named beside the folder, and opens the new one.
    if (still_named(fd_, path_)) ::unlink(path_.c_str());
    ::close(fd_);
    unregister_temp(path_);
    fd_ = -1;
    remove_made();
}

void FolderLock::remove_made() noexcept {
    if (made_.empty()) return;
    // Only empty folders, innermost first: once the results are in place, their parent is not empty and stays.
    std::error_code ec;
    for (std::filesystem::path p = path_.parent_path(); !p.empty(); p = p.parent_path()) {
        if (!std::filesystem::remove(p, ec) || ec || p == made_) break;
    }
    made_.clear();
}

FolderLock::~FolderLock() { release(); }

FolderLock::FolderLock(FolderLock&& other) noexcept
    : fd_(other.fd_), path_(std::move(other.path_)), made_(std::move(other.made_)) {
    other.fd_ = -1;
    other.made_.clear();
}

FolderLock& FolderLock::operator=(FolderLock&& other) noexcept {
    if (this != &other) {
        release();
        fd_ = other.fd_;
        path_ = std::move(other.path_);
        made_ = std::move(other.made_);
        other.fd_ = -1;
        other.made_.clear();
    }
    return *this;
}

}  // namespace vssw::io
