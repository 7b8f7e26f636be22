#include "multibody/host/plugin_file_check.hpp"

#include <fcntl.h>
#include <link.h>  // ElfW: the ELF types of this machine's class
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <vector>

#include <fmt/format.h>

namespace vssw::multibody {
namespace {

// The ELF class of this machine's libraries (dlopen refuses another).
constexpr unsigned char kNativeClass = __ELF_NATIVE_CLASS == 64 ? ELFCLASS64 : ELFCLASS32;

// Reads `size` bytes at `offset` whole; false when the file has fewer.
bool read_at(int fd, void* data, std::size_t size, std::uint64_t offset) {
    std::size_t done = 0;
    while (done < size) {
        const ssize_t n = ::pread(fd, static_cast<char*>(data) + done, size - done, static_cast<off_t>(offset + done));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        done += static_cast<std::size_t>(n);
    }
    return true;
}

// Why `path` is not a regular file ("" when it is).
std::string not_a_file(const std::string& path) {
    struct stat target {};
    if (::stat(path.c_str(), &target) == 0) {
        if (S_ISREG(target.st_mode)) return "";
        return S_ISDIR(target.st_mode) ? "it is a directory" : "it is not a regular file (a device, pipe or socket)";
    }
    if (errno == ELOOP) return "it is a loop of symbolic links";
    struct stat link {};
    if (errno == ENOENT && ::lstat(path.c_str(), &link) == 0 && S_ISLNK(link.st_mode)) {
        std::vector<char> to(4096);
        const ssize_t n = ::readlink(path.c_str(), to.data(), to.size() - 1);
        return fmt::format("it is a symbolic link to {}, which does not exist",
                           n > 0 ? std::string(to.data(), static_cast<std::size_t>(n)) : "a missing file");
    }
    return fmt::format("it cannot be read: {}", std::strerror(errno));
}

// Why the ELF library open as `fd`, `size` bytes long, would be mapped past its end ("" when it would not).
std::string cut_short(int fd, std::uint64_t size) {
    ElfW(Ehdr) header{};
    if (!read_at(fd, &header, sizeof header, 0) || std::memcmp(header.e_ident, ELFMAG, SELFMAG) != 0 ||
        header.e_ident[EI_CLASS] != kNativeClass || header.e_phentsize != sizeof(ElfW(Phdr)))
        return "";  // not a library dlopen would map: it says why
    std::uint64_t need = 0;  // where the last loadable segment's bytes in the file end
    for (std::size_t i = 0; i < header.e_phnum; ++i) {
        ElfW(Phdr) segment{};
        if (!read_at(fd, &segment, sizeof segment, header.e_phoff + i * sizeof segment))
            return fmt::format("the file is cut short (a copy or install that did not finish?): it has {} bytes, and "
                               "its program headers end past them",
                               size);
        std::uint64_t end = 0;  // a sum that wraps around ends past any file
        if (__builtin_add_overflow(segment.p_offset, segment.p_filesz, &end)) end = UINT64_MAX;
        if (segment.p_type == PT_LOAD) need = std::max(need, end);
    }
    if (need <= size) return "";
    return fmt::format("the file is cut short (a copy or install that did not finish?): it has {} bytes, and its "
                       "loadable segments need {}",
                       size, need);
}

// The descriptor of the GNU build-id note among the `size` bytes of notes read into `notes`, as hex ("" when none).
// Each note: its header, then its name and its descriptor, each padded to `align` bytes (4, or 8 for a segment
// aligned so).
std::string build_id_in(const std::vector<unsigned char>& notes, std::uint64_t align) {
    const auto padded = [align](std::uint64_t n) { return (n + align - 1) / align * align; };
    for (std::uint64_t at = 0; at + sizeof(ElfW(Nhdr)) <= notes.size();) {
        ElfW(Nhdr) note{};
        std::memcpy(&note, notes.data() + at, sizeof note);
        const std::uint64_t name = at + sizeof note, desc = name + padded(note.n_namesz);
        if (desc + note.n_descsz > notes.size()) return "";
        if (note.n_type == NT_GNU_BUILD_ID && note.n_namesz == 4 &&
            std::memcmp(notes.data() + name, "GNU", 4) == 0) {
            std::string hex;
            for (std::uint64_t i = 0; i < note.n_descsz; ++i) hex += fmt::format("{:02x}", notes[desc + i]);
            return hex;
        }
        at = desc + padded(note.n_descsz);
    }
    return "";
}

}  // namespace

std::string plugin_file_problem(const std::string& path) {
    if (std::string why = not_a_file(path); !why.empty()) return why;
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return fmt::format("it cannot be read: {}", std::strerror(errno));
    struct stat file {};
    const std::string why = ::fstat(fd, &file) == 0 ? cut_short(fd, static_cast<std::uint64_t>(file.st_size)) : "";
    ::close(fd);
    return why;
}

std::string plugin_build_note(const std::string& path) {
    constexpr std::uint64_t kLargestNotes = 1 << 16;  // a library's notes are a few hundred bytes
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return "";
    std::string id;
    ElfW(Ehdr) header{};
    if (read_at(fd, &header, sizeof header, 0) && std::memcmp(header.e_ident, ELFMAG, SELFMAG) == 0 &&
        header.e_ident[EI_CLASS] == kNativeClass && header.e_phentsize == sizeof(ElfW(Phdr))) {
        for (std::size_t i = 0; id.empty() && i < header.e_phnum; ++i) {
            ElfW(Phdr) segment{};
            if (!read_at(fd, &segment, sizeof segment, header.e_phoff + i * sizeof segment)) break;
            if (segment.p_type != PT_NOTE || segment.p_filesz > kLargestNotes) continue;
            std::vector<unsigned char> notes(segment.p_filesz);
            if (read_at(fd, notes.data(), notes.size(), segment.p_offset))
                id = build_id_in(notes, segment.p_align == 8 ? 8 : 4);
        }
    }
    ::close(fd);
    return id;
}

}  // namespace vssw::multibody
