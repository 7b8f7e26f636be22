#include "io/temp_registry.hpp"

#include <mutex>
#include <set>
#include <system_error>
#include <utility>

namespace vssw::io {
namespace {

// Never destroyed: a signal arriving while the program exits still finds them whole.
std::mutex& registry_mutex() {
    static auto* m = new std::mutex;
    return *m;
}

std::set<std::filesystem::path>& registry() {
    static auto* paths = new std::set<std::filesystem::path>;
    return *paths;
}

}  // namespace

void register_temp(const std::filesystem::path& path) {
    const std::lock_guard<std::mutex> lock(registry_mutex());
    registry().insert(path);
}

void unregister_temp(const std::filesystem::path& path) {
    const std::lock_guard<std::mutex> lock(registry_mutex());
    registry().erase(path);
}

void remove_registered_temps() {
    // Locked for good: a thread about to create a temporary file registers it first, so it now waits until the process
    // ends instead of leaving a new one behind.
    registry_mutex().lock();
    for (const std::filesystem::path& p : registry()) {
        std::error_code ec;
        std::filesystem::remove_all(p, ec);
    }
    registry().clear();
}

TempRegistration::TempRegistration(std::filesystem::path path) : path_(std::move(path)) { register_temp(path_); }

TempRegistration::~TempRegistration() { unregister_temp(path_); }

}  // namespace vssw::io
