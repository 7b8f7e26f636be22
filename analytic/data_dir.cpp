#include "analytic/data_dir.hpp"

#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace vssw {
namespace {

namespace fs = std::filesystem;

bool holds(const fs::path& folder, const char* marker) {
    std::error_code ec;
    return fs::is_regular_file(folder / marker, ec);
}

// `environment` if set; else the first of: beside the running program, the source tree's, the configured prefix's
// folder that holds `marker`; else the source tree's (whose absence the reader then reports by name).
std::string shipped_folder(const char* environment, const char* installed_name, const char* marker,
                           const char* source_folder, const char* configured_folder) {
    if (const char* from_environment = std::getenv(environment); from_environment && *from_environment)
        return from_environment;
    std::error_code ec;
    const fs::path program = fs::read_symlink("/proc/self/exe", ec);  // Linux: the running program's own path
    if (!ec) {
        const fs::path installed = program.parent_path().parent_path() / "share" / "vssw" / installed_name;
        if (holds(installed, marker)) return installed.string();
    }
    if (holds(source_folder, marker)) return source_folder;
    if (holds(configured_folder, marker)) return configured_folder;
    return source_folder;
}

}  // namespace

std::string shipped_data_dir() {
    return shipped_folder("VSSW_DATA_DIR", "data", "table1.csv", VSSW_DATA_DIR, VSSW_INSTALL_DATA_DIR);
}

std::string shipped_studies_dir() {
    return shipped_folder("VSSW_STUDIES_DIR", "studies", "validation-default.toml", VSSW_STUDIES_DIR,
                          VSSW_INSTALL_STUDIES_DIR);
}

}  // namespace vssw
