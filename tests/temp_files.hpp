#pragma once
// Files for the tests that write files: a temporary folder removed at the end of the test, a file read whole, a substring.
#include <stdlib.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace vssw::testing {

struct TempDir {
    static std::string test_name() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        return info ? std::string(info->test_suite_name()) + "_" + info->name() : std::string("test");
    }
    std::filesystem::path path;
    // A new folder "vssw_<name>_XXXXXX" in the system's temporary folder.
    explicit TempDir(const std::string& name) {
        std::string pattern = (std::filesystem::temp_directory_path() / ("vssw_" + name + "_XXXXXX")).string();
        char* made = mkdtemp(pattern.data());
        if (made == nullptr) throw std::runtime_error("mkdtemp failed");
        path = made;
    }
    ~TempDir() {
        std::error_code ec;
        if (!path.empty()) std::filesystem::remove_all(path, ec);
    }
    // A new folder named after the running test.
    TempDir() : TempDir(test_name()) {}
    std::filesystem::path operator/(const std::string& name) const { return path / name; }
    // Moved, not copied: one owner removes the folder.
    TempDir(TempDir&& other) noexcept : path(std::move(other.path)) { other.path.clear(); }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    TempDir& operator=(TempDir&&) = delete;
};

inline std::string read_file(const std::filesystem::path& p) {
    std::ifstream f(p, std::ios::binary);
    std::ostringstream s;
    s << f.rdbuf();
    return s.str();
}

inline bool contains(const std::string& text, const std::string& what) { return text.find(what) != std::string::npos; }

}  // namespace vssw::testing
