#pragma once
// Every file vssw writes is written through AtomicFile: into a temporary file in the same folder, renamed onto the
// target only once everything was written. A run that fails (bad input found late, a failed integration, a full
// disk) leaves the target as it was: an existing file is never truncated or half-written.
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

namespace vssw::io {

class AtomicFile {
public:
    // Creates the temporary file ".<name>.vssw-tmp-<pid>-<n>" beside `target` (InputError naming the target if it
    // cannot: no such folder, no permission, the target is a folder). Call it before a long run so that an unwritable target fails at once.
    explicit AtomicFile(std::filesystem::path target);
    // Removes the temporary file unless commit() succeeded.
    ~AtomicFile();
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    std::ostream& stream() { return out_; }
    // Flushes, closes and renames the temporary file onto the target (InputError naming the target on failure).
    void commit();

private:
    std::filesystem::path target_, temp_;
    std::ofstream out_;
    bool committed_ = false;
};

// The whole file in one call: `write` fills the stream, then it is committed (InputError naming the target when it
// cannot be written; the target is then as it was).
void write_file(const std::filesystem::path& target, const std::function<void(std::ostream&)>& write);

}  // namespace vssw::io
