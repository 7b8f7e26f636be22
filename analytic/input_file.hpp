#pragma once
// Every file vssw reads whole (records, study and suite files, a study folder's results.csv, journal.csv and
// manifest.json, a bench folder's bench.json, a folder's records.csv) is opened here: what is not a regular file is
// refused before a byte is read (a FIFO would block forever, /dev/zero or another device would be read until memory
// runs out, a folder reads as nothing), and so is a file larger than the bound its reader gives. The type is read from
// the opened descriptor (opened without blocking), so a file swapped for a FIFO after a look at its name cannot slip by.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace vssw {

// A file people write or edit (a study, suite, bounds or Table 1 file, a manifest.json, bench.json, records.csv): the
// largest vssw writes are a few MB (an ensemble's manifest naming 10,000 records is ~1 MB); 256 MiB is far past any.
constexpr std::uintmax_t kMaxTextFileBytes = 256ull * 1024 * 1024;
// A study's rows (results.csv, journal.csv): ~80 bytes a row, so 64 GiB is ~10^9 rows, a thousand times the rows of
// the largest study anyone has run here (10^4 tasks without --force, ~10 rows each); the bound only stops a sparse or
// endless file.
constexpr std::uintmax_t kMaxResultsBytes = 64ull * 1024 * 1024 * 1024;

// Opens `path` for reading; InputError naming it ("<what> '<path>' ...") when it does not exist or cannot be opened,
// is a folder, is not a regular file (a device, FIFO or socket; a symbolic link is followed to what it names), or has
// more than max_bytes bytes.
std::ifstream open_input_file(const std::filesystem::path& path, const std::string& what, std::uintmax_t max_bytes);

// The whole file as text, through open_input_file (the same refusals; InputError when reading fails).
std::string read_input_file(const std::filesystem::path& path, const std::string& what, std::uintmax_t max_bytes);

}  // namespace vssw
