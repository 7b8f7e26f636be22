#pragma once
// An ensemble's records as files on disk. A record is identified by the file it resolves to, its (device, inode)
// pair, not by how its path is spelled: "a.at2", "./a.at2", "../recs/a.at2", a path through a symlinked folder, a
// symbolic link to it and a hard link to it are one record, and an ensemble naming it twice is refused (counted twice,
// the fragility fit and its intervals would take one record for two independent ones). The inode rather than the
// canonical path, because a hard link has no canonical spelling in common with the file. Two byte-identical copies
// are two files: they count twice (whether a copy is a second record is the user's to say).
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace vssw::study {

// Why `path` cannot be a record file ("" when it is a regular file, a symbolic link followed): "a symbolic link to a
// missing file", "a symbolic link loop", "a FIFO", "a device", "a socket", "a folder", or the system's reason.
std::string not_a_record_file(const std::filesystem::path& path);

// The indices (i < j) of the first two paths that name one file, or nothing. Paths that cannot be looked up are
// skipped (their reader names them).
std::optional<std::pair<std::size_t, std::size_t>> same_file_twice(const std::vector<std::filesystem::path>& paths);

}  // namespace vssw::study
