#include "study/record_files.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <map>

namespace vssw::study {

std::string not_a_record_file(const std::filesystem::path& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        const int err = errno;
        struct stat link {};
        const bool is_link = ::lstat(path.c_str(), &link) == 0 && S_ISLNK(link.st_mode);
        if (is_link && err == ENOENT) return "a symbolic link to a missing file";
        if (err == ELOOP) return "a symbolic link loop";
        return std::strerror(err);
    }
    if (S_ISREG(st.st_mode)) return "";
    if (S_ISDIR(st.st_mode)) return "a folder";
    if (S_ISFIFO(st.st_mode)) return "a FIFO";
    if (S_ISSOCK(st.st_mode)) return "a socket";
    if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode)) return "a device";
    return "not a regular file";
}

std::optional<std::pair<std::size_t, std::size_t>> same_file_twice(const std::vector<std::filesystem::path>& paths) {
    std::map<std::pair<dev_t, ino_t>, std::size_t> seen;
    for (std::size_t j = 0; j < paths.size(); ++j) {
        struct stat st {};
        if (::stat(paths[j].c_str(), &st) != 0) continue;
        const auto [at, fresh] = seen.emplace(std::make_pair(st.st_dev, st.st_ino), j);
        if (!fresh) return std::make_pair(at->second, j);
    }
    return std::nullopt;
}

}  // namespace vssw::study
