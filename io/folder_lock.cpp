#include "io/folder_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include <fmt/format.h>

#include "analytic/error.hpp"

namespace vssw::study {
namespace {

// Tries to take the lock: another process may lock the file, then remove the folder it is in (a finished study's
// folder is swapped away whole), between our open and our flock. The file we locked must still be the one named in
// the folder; a few tries settle it (each a race of microseconds).
constexpr int kLockTries = 5;

// The process id a lock file holds, as text ("" when it holds none yet).
std::string holder(int fd) {
    char buf[32] = {};
    const ssize_t n = ::pread(fd, buf, sizeof buf - 1, 0);
    std::string s = n > 0 ? std::string(buf, static_cast<std::size_t>(n)) : std::string();
    while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
    return s;
}

}  // namespace

FolderLock::FolderLock(const std::filesystem::path& dir) {
    const std::filesystem::path path = dir / kLockFile;
    for (int attempt = 0; attempt < kLockTries; ++attempt) {
        // O_CLOEXEC: gnuplot and other programs run by vssw do not inherit the lock.
        const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
        if (fd < 0)
            throw InputError(fmt::format("--out '{}': cannot make the lock file '{}': {}", dir.string(), path.string(),
                                         std::strerror(errno)));
        if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
            const int err = errno;
            const std::string pid = holder(fd);
            ::close(fd);
            if (err == EWOULDBLOCK)
                throw InputError(fmt::format("--out '{}' is in use by another vssw study ({}): wait for it to end, or "
                                             "give another --out",
                                             dir.string(), pid.empty() ? "a process" : "process " + pid));
            // A file system without locks (ENOLCK, EOPNOTSUPP on some network mounts): the study runs as it did
            // before there were locks, rather than not at all.
            return;
        }
        struct stat held {}, named {};
        if (::fstat(fd, &held) == 0 && ::stat(path.c_str(), &named) == 0 && held.st_dev == named.st_dev &&
            held.st_ino == named.st_ino) {
            const std::string pid = fmt::format("{}\n", static_cast<long>(::getpid()));
            if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, pid.data(), pid.size(), 0) < 0) {
                // The lock holds without the id: a refused run then names "a process".
            }
            fd_ = fd;
            return;
        }
        ::close(fd);
    }
    throw InputError(fmt::format("--out '{}': cannot lock '{}': it keeps being replaced", dir.string(), path.string()));
}

FolderLock::~FolderLock() {
    if (fd_ >= 0) ::close(fd_);
}

FolderLock& FolderLock::operator=(FolderLock&& other) noexcept {
    if (this != &other) {
        if (fd_ >= 0) ::close(fd_);
        fd_ = other.fd_;
        other.fd_ = -1;
    }
    return *this;
}

}  // namespace vssw::study
