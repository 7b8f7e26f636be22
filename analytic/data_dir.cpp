#include "analytic/data_dir.hpp"

#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace vssw {

std::string shipped_data_dir() {
    if (const char* from_environment = std::getenv("VSSW_DATA_DIR"); from_environment && *from_environment)
        return from_environment;
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path program = fs::read_symlink("/proc/self/exe", ec);  // Linux: the running program's own path
    if (!ec) {
        const fs::path installed = program.parent_path().parent_path() / "share" / "vssw" / "data";
        if (fs::is_regular_file(installed / "table1.csv", ec)) return installed.string();
    }
    // The install prefix configured at build time: where the Python module (whose program is python3) finds it.
    if (fs::is_regular_file(fs::path(VSSW_INSTALL_DATA_DIR) / "table1.csv", ec)) return VSSW_INSTALL_DATA_DIR;
    return VSSW_DATA_DIR;
}

}  // namespace vssw
