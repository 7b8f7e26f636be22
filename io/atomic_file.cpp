#include "io/atomic_file.hpp"

#include <unistd.h>

#include <atomic>
#include <system_error>
#include <utility>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "io/temp_registry.hpp"

namespace vssw::io {
namespace fs = std::filesystem;
namespace {

// The process id and a counter make the temporary name unique among the writers that may share a folder (other
// vssw runs, other threads of this one).
std::atomic<unsigned> temp_counter{0};

}  // namespace

AtomicFile::AtomicFile(fs::path target) : target_(std::move(target)) {
    const fs::path folder = target_.has_parent_path() ? target_.parent_path() : fs::path(".");
    temp_ = folder / fmt::format(".{}.vssw-tmp-{}-{}", target_.filename().string(), static_cast<long>(::getpid()),
                                 temp_counter++);
    std::error_code ec;
    if (fs::is_directory(target_, ec))
        throw InputError(fmt::format("cannot write the output file '{}': it is a folder", target_.string()));
    register_temp(temp_);  // before it exists: SIGINT/SIGTERM remove it (cli/signal_cleanup.hpp)
    out_.open(temp_, std::ios::binary | std::ios::trunc);
    if (!out_) {
        unregister_temp(temp_);
        throw InputError(fmt::format("cannot write the output file '{}'", target_.string()));
    }
}

AtomicFile::~AtomicFile() {
    if (committed_) return;
    out_.close();
    std::error_code ec;
    fs::remove(temp_, ec);  // nothing to report from a destructor: the target is untouched either way
    unregister_temp(temp_);
}

void AtomicFile::commit() {
    out_.flush();
    out_.close();
    if (!out_) throw InputError(fmt::format("error while writing the output file '{}'", target_.string()));
    std::error_code ec;
    fs::rename(temp_, target_, ec);
    if (ec)
        throw InputError(fmt::format("cannot write the output file '{}': {}", target_.string(), ec.message()));
    committed_ = true;
    unregister_temp(temp_);
}

void write_file(const fs::path& target, const std::function<void(std::ostream&)>& write) {
    AtomicFile f(target);
    write(f.stream());
    f.commit();
}

}  // namespace vssw::io
