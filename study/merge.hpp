#pragma once
// `vssw study merge DIR1 DIR2 ... --out DIR`: the shards of one study (each run with --shard k/n) joined into the
// results.csv and manifest.json one run of the whole study would have written: the same rows in the same order.
// Refused (InputError naming the folder) unless every folder holds finished results of the same study (the same
// identity), the shards are those of one split (the same n), and each of 1..n is there exactly once.
#include <filesystem>
#include <vector>

namespace vssw::study {

struct MergeResult {
    int shards = 0;
    long rows = 0, failed_rows = 0;
};

// Each shard's results.csv must be the file its manifest records (its rows and a hash of its bytes: a file cut short,
// given a row twice or edited is refused, naming the shard and the counts); a row given twice is refused in any case.
// The files are written into `write_to` (empty: `out`), e.g. the staging folder that replaces `out` whole.
MergeResult merge_studies(const std::vector<std::filesystem::path>& dirs, const std::filesystem::path& out,
                          const std::filesystem::path& write_to = {});

}  // namespace vssw::study
