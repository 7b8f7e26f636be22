#pragma once
// A study folder is worked in by one process at a time: a run (or --resume) holds an exclusive flock on DIR/.vssw-lock
// for as long as it runs, and the kernel releases it when the process ends however it ends (SIGKILL too). A second run
// or --resume meanwhile is refused, naming the first one's process id (the file holds it), instead of appending to
// the same journal. Under MPI only rank 0 takes it; shards have folders of their own.
#include <filesystem>

namespace vssw::study {

constexpr const char* kLockFile = ".vssw-lock";

class FolderLock {
public:
    FolderLock() = default;
    // Locks DIR/.vssw-lock (made if missing); InputError naming the process that holds it. Where the file system has
    // no locks, holds none.
    explicit FolderLock(const std::filesystem::path& dir);
    ~FolderLock();
    FolderLock(FolderLock&& other) noexcept : fd_(other.fd_) { other.fd_ = -1; }
    FolderLock& operator=(FolderLock&& other) noexcept;
    FolderLock(const FolderLock&) = delete;
    FolderLock& operator=(const FolderLock&) = delete;

private:
    int fd_ = -1;
};

}  // namespace vssw::study
