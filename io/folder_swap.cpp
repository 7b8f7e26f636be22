#include "io/folder_swap.hpp"

#include <stdio.h>  // renameat2, RENAME_EXCHANGE (glibc 2.28)
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <system_error>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "io/folder_lock.hpp"
#include "io/temp_registry.hpp"

namespace vssw::io {
namespace fs = std::filesystem;
namespace {

struct KindInfo {
    OutKind kind;
    const char* what;    // "a study", for messages
    const char* whose;   // "a study's results"
    std::vector<std::string> own;        // every name the command writes in the folder
    std::vector<std::string> signature;  // the names no other command writes: they tell whose folder it is
};

const std::vector<KindInfo>& kinds() {
    static const std::vector<KindInfo> table = {
        {OutKind::study, "a study", "a study's results",
         {"results.csv", "results.json", "manifest.json", "journal.csv", "plots", "study.md", "study.html",
          "fragility.csv", "agreement.csv", "ida.csv"},
         {"manifest.json", "journal.csv", "results.csv", "study.md", "study.html"}},
        {OutKind::report, "a report", "a report",
         {"report.md", "report.html", "results.json", "metrics.csv", "failures.csv", "traces.csv", "plots",
          "earthquake", "relaxations"},
         {"report.md", "report.html", "metrics.csv", "failures.csv", "traces.csv"}},
        {OutKind::bench, "a bench", "a bench's results",
         {"bench.json", "bench.csv", "bench.md", "plots"},
         {"bench.json", "bench.csv", "bench.md"}},
        {OutKind::stress, "a stress run", "a stress run's results",
         {"stress.json", "stress.csv", "stress.md"},
         {"stress.json", "stress.csv", "stress.md"}},
        {OutKind::motions, "a set of generated motions", "generated motions", {"motions.csv"}, {"motions.csv"}},
    };
    return table;
}

const KindInfo& info(OutKind kind) {
    for (const KindInfo& k : kinds())
        if (k.kind == kind) return k;
    return kinds().front();
}

bool contains(const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

// "motion-<digits>.at2", the files of `vssw motions generate`: their number depends on --count.
bool numbered_motion(const std::string& name) {
    const std::string prefix = "motion-", suffix = ".at2";
    if (name.size() <= prefix.size() + suffix.size() || name.rfind(prefix, 0) != 0 ||
        name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
        return false;
    const std::string digits = name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
    return digits.find_first_not_of("0123456789") == std::string::npos;
}

// Whether the command of `me` writes `name` (replaces it in the new folder).
bool owns(const KindInfo& me, const std::string& name) {
    return contains(me.own, name) || (me.kind == OutKind::motions && numbered_motion(name));
}

// vssw's own hidden files, whatever the command: locks (of a folder inside, or of older versions), an old write probe,
// temporary files and folders.
bool vssw_hidden(const std::string& name) {
    const std::string suffix = kLockSuffix;
    const bool lock = name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
    return name == kLockFile || lock || name == ".vssw-write-test" || name.find(".vssw-tmp-") != std::string::npos;
}

fs::path staging_path(const fs::path& target) {
    return target.parent_path() / fmt::format(".{}.vssw-tmp-{}", target.filename().string(), static_cast<long>(::getpid()));
}

// Recreates `from` at `to` without copying data where it can: a folder is made anew (its permissions kept) and its
// entries linked in turn; anything else is hard-linked (symlinks as themselves), or copied where a link is refused.
void carry(const fs::path& from, const fs::path& to) {
    const fs::file_status st = fs::symlink_status(from);
    if (fs::is_directory(st)) {
        fs::create_directory(to, from);
        for (const fs::directory_entry& e : fs::directory_iterator(from)) carry(e.path(), to / e.path().filename());
        return;
    }
    std::error_code ec;
    fs::create_hard_link(from, to, ec);
    if (!ec) return;
    if (fs::is_symlink(st)) fs::copy_symlink(from, to);
    else fs::copy_file(from, to);
}

// The first folder below `target` on another file system than target's own (a mount point inside --out), or empty.
// The swap carries the old folder's files over and removes the old folder: across a mount point that would copy a
// whole file system's files and then delete them from it.
fs::path mount_point_inside(const fs::path& target) {
    struct stat top {};
    if (::stat(target.c_str(), &top) != 0) return {};
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(target, fs::directory_options::skip_permission_denied, ec);
         !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        if (!it->is_directory(ec) || it->is_symlink(ec)) continue;
        struct stat st {};
        if (::lstat(it->path().c_str(), &st) == 0 && st.st_dev != top.st_dev) return it->path();
    }
    return {};
}

// Whether `inner` is `outer` or lies inside it (both resolved).
bool within(const fs::path& inner, const fs::path& outer) {
    const auto mismatch = std::mismatch(outer.begin(), outer.end(), inner.begin(), inner.end());
    return mismatch.first == outer.end();
}

// Staging folders beside `target` (".NAME.vssw-tmp-PID") left by a run killed outright (SIGKILL, a power cut): their
// process is gone, so nothing will finish or remove them. A folder whose process id belongs to a live process is kept
// (that process may be a vssw writing it, or the id was reused: either way not ours to remove).
void remove_stale_staging(const fs::path& target) {
    const std::string prefix = "." + target.filename().string() + ".vssw-tmp-";
    std::error_code ec;
    for (const fs::directory_entry& e : fs::directory_iterator(target.parent_path(), ec)) {
        const std::string name = e.path().filename().string();
        if (name.rfind(prefix, 0) != 0) continue;
        const std::string digits = name.substr(prefix.size());
        if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 9) continue;
        const long pid = std::stol(digits);
        if (pid == static_cast<long>(::getpid())) continue;
        if (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;
        std::error_code ignored;
        fs::remove_all(e.path(), ignored);
    }
}

// Refuses (InputError) a folder holding another command's results: run at the check of --out, and again just before
// the swap (a command of an older vssw, or one that ignored the lock, may have written there meanwhile: its files
// would be carried into ours).
void refuse_other_results(const fs::path& dir, const fs::path& target, const KindInfo& me) {
    std::error_code ec;
    for (const fs::directory_entry& e : fs::directory_iterator(target, ec)) {
        const std::string name = e.path().filename().string();
        if (owns(me, name) || vssw_hidden(name)) continue;
        for (const KindInfo& other : kinds())
            if (other.kind != me.kind && contains(other.signature, name))
                throw InputError(fmt::format("--out '{}' holds {} ({}): {} there would replace them; give --out "
                                             "another folder",
                                             dir.string(), other.whose, name, me.what));
    }
    if (ec) throw InputError(fmt::format("--out '{}' cannot be read: {}", dir.string(), ec.message()));
}

}  // namespace

FolderLock check_out_folder(const fs::path& dir, OutKind kind) {
    const KindInfo& me = info(kind);
    if (dir.empty()) throw InputError("--out: the path is empty");
    std::error_code ec;
    const fs::path target = resolve_out(dir);
    if (target == target.root_path())
        throw InputError(fmt::format("--out '{}' is the root folder: vssw replaces its results folder as a whole; give "
                                     "--out a folder inside it",
                                     dir.string()));
    // Locked before anything is looked at: a command already writing --out is named, not raced.
    FolderLock lock(dir);
    const bool exists = fs::exists(target, ec);
    if (exists) {
        if (!fs::is_directory(target, ec))
            throw InputError(fmt::format("--out '{}' exists and is not a folder", dir.string()));
        refuse_other_results(dir, target, me);
        struct stat self {}, parent {};
        if (::stat(target.c_str(), &self) == 0 && ::stat(target.parent_path().c_str(), &parent) == 0 &&
            self.st_dev != parent.st_dev)
            throw InputError(fmt::format("--out '{}' is a mount point: vssw replaces its results folder as a whole, "
                                         "by renaming, which a mount point cannot be; give --out a folder inside it",
                                         dir.string()));
        if (::access(target.c_str(), W_OK | X_OK) != 0)
            throw InputError(fmt::format("--out '{}' cannot be written: {}", dir.string(), std::strerror(errno)));
        if (const fs::path mount = mount_point_inside(target); !mount.empty())
            throw InputError(fmt::format("--out '{}' holds a mount point ('{}'): vssw replaces its results folder as a "
                                         "whole and would carry that file system's files over; give --out a folder "
                                         "without one",
                                         dir.string(), mount.string()));
        std::error_code cwd_ec;
        const fs::path cwd = resolve_out(fs::current_path(cwd_ec));
        if (!cwd_ec && within(cwd, target))
            throw InputError(fmt::format("--out '{}' holds the current folder ('{}'): vssw replaces its results folder "
                                         "as a whole, which would leave this shell in a removed folder; give --out a "
                                         "folder beside or below it",
                                         dir.string(), cwd.string()));
    }
    remove_stale_staging(target);
    // The staging folder: made and removed now, so that a read-only or full place fails before the run. Where the
    // folder's parent does not exist yet, in the nearest one that does (the rest is made at the end).
    fs::path parent = target.parent_path();
    while (!fs::exists(parent, ec) && parent != parent.root_path()) parent = parent.parent_path();
    const fs::path staging = parent / staging_path(target).filename();
    const TempRegistration registered(staging);
    fs::remove_all(staging, ec);  // a leftover of a killed run that had this process id: ours by its name
    if (!fs::create_directory(staging, ec))
        throw InputError(fmt::format("--out '{}': cannot write in '{}' ({}): vssw writes the results into a folder "
                                     "beside --out and swaps it in when they are complete",
                                     dir.string(), parent.string(), ec ? ec.message() : "it exists"));
    fs::remove_all(staging, ec);
    return lock;
}

void check_inputs_not_outputs(const fs::path& dir, OutKind kind,
                              const std::vector<std::pair<std::string, fs::path>>& inputs) {
    const KindInfo& me = info(kind);
    std::error_code ec;
    for (const auto& [what, input] : inputs) {
        if (input.empty()) continue;
        for (const std::string& name : me.own) {
            const fs::path out = dir / name;
            bool hit = fs::equivalent(input, out, ec) && !ec;
            // A file inside a folder of outputs (plots/) goes with the folder.
            for (fs::path p = resolve_out(input).parent_path(); !hit && p.has_relative_path(); p = p.parent_path())
                hit = fs::equivalent(p, out, ec) && !ec;
            if (hit)
                throw InputError(fmt::format("{} '{}' is {} '{}' that {} writes: it would be replaced by the results; "
                                             "move it, or give --out another folder",
                                             what, input.string(), fs::is_directory(out, ec) ? "inside" : "the file",
                                             out.string(), me.what));
        }
    }
}

StagedFolder::StagedFolder(const fs::path& dir, OutKind kind)
    : dir_(dir), target_(resolve_out(dir)), staging_(staging_path(target_)), kind_(kind) {
    register_temp(staging_);  // before it exists: SIGINT/SIGTERM remove it (cli/signal_cleanup.hpp)
    std::error_code ec;
    fs::remove_all(staging_, ec);  // a leftover of a killed run that had this process id
}

void StagedFolder::create() {
    std::error_code ec;
    fs::create_directories(staging_, ec);
    if (ec)
        throw InputError(fmt::format("--out '{}': cannot make the folder '{}': {}", dir_.string(), staging_.string(),
                                     ec.message()));
}

StagedFolder::~StagedFolder() {
    if (committed_) return;
    std::error_code ec;
    fs::remove_all(staging_, ec);  // nothing to report from a destructor: the old folder is untouched either way
    unregister_temp(staging_);
}

fs::path StagedFolder::final_path(const fs::path& inside) const {
    const fs::path rel = inside.lexically_relative(staging_);
    if (rel.empty() || *rel.begin() == "..") return inside;
    return rel == "." ? dir_ : dir_ / rel;
}

void StagedFolder::commit() {
    const KindInfo& me = info(kind_);
    std::error_code ec;
    if (!fs::exists(target_, ec)) {
        fs::create_directories(target_.parent_path(), ec);
        fs::rename(staging_, target_, ec);
        if (ec)
            throw InputError(fmt::format("--out '{}': cannot move the results into place: {}", dir_.string(),
                                         ec.message()));
        committed_ = true;
        unregister_temp(staging_);
        return;
    }
    refuse_other_results(dir_, target_, me);
    try {
        for (const fs::directory_entry& e : fs::directory_iterator(target_)) {
            const std::string name = e.path().filename().string();
            if (owns(me, name) || vssw_hidden(name)) continue;
            carry(e.path(), staging_ / name);
        }
    } catch (const fs::filesystem_error& e) {
        throw InputError(fmt::format("--out '{}': cannot carry its other files over into the new results ({}); the "
                                     "folder is as it was",
                                     dir_.string(), e.what()));
    }
    if (::renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, target_.c_str(), RENAME_EXCHANGE) == 0) {
        committed_ = true;
        fs::remove_all(staging_, ec);  // now the old folder (still registered: a signal here removes it too)
        unregister_temp(staging_);
        return;
    }
    if (errno != EINVAL && errno != ENOSYS)
        throw InputError(fmt::format("--out '{}': cannot swap the new results in: {}", dir_.string(),
                                     std::strerror(errno)));
    // A file system without the exchange: the old folder renamed aside, the new one in, the old one removed. Between
    // the two renames neither is registered, so a signal there leaves both (hidden) rather than removing the old.
    unregister_temp(staging_);
    const fs::path aside =
        target_.parent_path() / fmt::format(".{}.vssw-old-{}", target_.filename().string(), static_cast<long>(::getpid()));
    fs::rename(target_, aside, ec);
    if (ec) {
        register_temp(staging_);
        throw InputError(fmt::format("--out '{}': cannot move the old results aside: {}", dir_.string(), ec.message()));
    }
    fs::rename(staging_, target_, ec);
    if (ec) {
        std::error_code back;
        fs::rename(aside, target_, back);
        register_temp(staging_);
        // When the old folder cannot go back either, say where it is: it is the user's earlier results.
        throw InputError(fmt::format("--out '{}': cannot move the new results in: {}{}", dir_.string(), ec.message(),
                                     back ? fmt::format(" (the earlier results are in '{}')", aside.string()) : ""));
    }
    committed_ = true;
    const TempRegistration registered(aside);
    fs::remove_all(aside, ec);
}

}  // namespace vssw::io
