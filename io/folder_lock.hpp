#pragma once
// A results folder is written by one command at a time: every command that writes one (study and its --resume, study
// merge, report, bench, stress, motions generate) holds an exclusive flock on a lock file beside it,
// ".NAME.vssw-lock", from its check of --out before anything runs until its folder is swapped in. The lock file is
// beside the folder, not in it, because the folder is replaced whole at the end and may not exist yet at the start
// (folders above it that do not exist yet are made for it, and removed again if the command ends without results
// there). A second
// command meanwhile is refused, naming the first one's process id (the file holds it), instead of appending to the
// same journal or swapping in a folder of mixed results. The kernel releases the lock when the process ends however
// it ends (SIGKILL too); the holder removes the file when it lets go (a signal's cleanup too), and whoever locks a
// file checks it is still the one named beside the folder. Under MPI only rank 0 takes it; shards have folders of
// their own.
#include <filesystem>

namespace vssw::io {

constexpr const char* kLockSuffix = ".vssw-lock";
// The name of the lock file in a folder of older versions (DIR/.vssw-lock): vssw's own, never carried over.
constexpr const char* kLockFile = ".vssw-lock";

// --out resolved: absolute, symlinks followed (so that two spellings of one folder share a lock, the staging folder
// goes beside the real folder, and a symlink named by --out stays a symlink to it), no trailing "/" or ".".
std::filesystem::path resolve_out(const std::filesystem::path& dir);

class FolderLock {
public:
    FolderLock() = default;
    // Locks the lock file of the folder `dir` (made if missing); InputError naming the process that holds it. Where
    // the file system has no locks, holds none.
    explicit FolderLock(const std::filesystem::path& dir);
    // Removes the lock file and lets go.
    ~FolderLock();
    FolderLock(FolderLock&& other) noexcept;
    FolderLock& operator=(FolderLock&& other) noexcept;
    FolderLock(const FolderLock&) = delete;
    FolderLock& operator=(const FolderLock&) = delete;

private:
    void release() noexcept;
    void remove_made() noexcept;
    int fd_ = -1;
    std::filesystem::path path_;  // the lock file
    std::filesystem::path made_;  // the outermost folder made for it, or empty
};

}  // namespace vssw::io
