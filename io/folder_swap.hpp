#pragma once
// A results folder (study, study merge, report, bench, stress --out) is replaced as a whole or not at all: the run's
// files are written into a staging folder beside it, ".NAME.vssw-tmp-PID", which is swapped in only once everything
// is written (an atomic exchange of the two names; the old folder then removed). A run that fails (bad input found
// late, a full disk, SIGINT or SIGTERM) leaves the old folder as it was and removes the staging folder.
//
// Files in the folder that the command does not write (a user's notes, study_slurm.sh's shards/ and logs) are carried
// over into the new folder (hard links, a copy where a link cannot be made), so nothing of the user's is lost. A
// folder holding another command's results is refused: a report there would replace a study's results.json.
// `vssw motions generate` owns motions.csv and every "motion-<digits>.at2": a smaller set leaves none of a larger
// one's motions behind.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "io/folder_lock.hpp"

namespace vssw::io {

// Which command writes the folder: it decides which names are its own (replaced) and which another's (refused).
enum class OutKind { study, report, bench, stress, motions };

// Locks --out (io/folder_lock.hpp: another command writing it is named) and checks it before anything runs
// (InputError naming the folder): an existing path must be a folder this process can write, neither a mount point nor
// '/' (it could not be renamed), holding no other command's results; the folder beside it must take the staging
// folder (made and removed at once: a read-only or full place fails here, not after the run). The caller holds the
// lock it returns until its folder is swapped in (commit), or the run ends.
[[nodiscard]] FolderLock check_out_folder(const std::filesystem::path& dir, OutKind kind);

// Refuses (InputError) an input the run would destroy: a file that is, however spelled (symlink, hard link, ../),
// one of the files `kind` writes in `dir`, or lies in its plots/ folder. Each input is (what it is, its path), e.g.
// ("the record", "data/r.csv").
void check_inputs_not_outputs(const std::filesystem::path& dir, OutKind kind,
                              const std::vector<std::pair<std::string, std::filesystem::path>>& inputs);

class StagedFolder {
public:
    // Names the staging folder beside `dir`; it is made by create() (or by the writer of the first file: a study's
    // runner), when the results are written, so that a long run killed outright leaves no empty folder behind.
    StagedFolder(const std::filesystem::path& dir, OutKind kind);
    // Makes the staging folder (InputError when it cannot be made).
    void create();
    // Removes the staging folder unless commit() succeeded.
    ~StagedFolder();
    StagedFolder(const StagedFolder&) = delete;
    StagedFolder& operator=(const StagedFolder&) = delete;

    // Where the run writes its files.
    const std::filesystem::path& path() const { return staging_; }
    // A path inside the staging folder as it will be named once committed (for what the program prints).
    std::filesystem::path final_path(const std::filesystem::path& inside) const;
    // Checks again that the old folder holds no other command's results (written meanwhile by a command that did not
    // take the lock), carries over its files that are not the command's own, then swaps the staging folder in and
    // removes the old one (InputError naming the folder when it cannot; the old folder is then as it was).
    void commit();

private:
    std::filesystem::path dir_;       // --out as given (for messages and final_path)
    std::filesystem::path target_;    // --out resolved: absolute, symlinks followed
    std::filesystem::path staging_;
    OutKind kind_;
    bool committed_ = false;
};

}  // namespace vssw::io
