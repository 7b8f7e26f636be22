#pragma once
// Helpers shared by the study tests (the temporary folder is tests/temp_files.hpp's): a study file written from
// text, a study run into a folder, its results.csv read back.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "study/grid.hpp"
#include "study/results_files.hpp"
#include "study/runner.hpp"
#include "study/spec.hpp"
#include "tests/temp_files.hpp"

namespace vssw::testing {

inline std::filesystem::path write_file(const std::filesystem::path& path, const std::string& text) {
    std::ofstream(path) << text;
    return path;
}

// The study in `toml`, parsed as the file `dir/name` would be (records relative to `dir`).
inline study::StudySpec study_of(const TempDir& dir, const std::string& toml, const std::string& name = "s.toml") {
    return study::read_study_file(write_file(dir / name, toml).string());
}

// Runs the study into `out` (threads, shard) and returns what run_study says.
inline study::StudyRunResult run_study_into(const study::Grid& grid, const std::filesystem::path& out, int threads = 1,
                                           study::Shard shard = {}) {
    study::StudyRunOptions o;
    o.threads = threads;
    o.shard = shard;
    study::prepare_study_dir(grid, out, o);
    return study::run_study(grid, out, o);
}

// Runs the study into `out` (threads, shard) and returns results.csv read back.
inline study::ResultsTable run_into(const study::Grid& grid, const std::filesystem::path& out, int threads = 1,
                                    study::Shard shard = {}) {
    (void)run_study_into(grid, out, threads, shard);
    return study::read_results_csv(out / study::kResultsCsv);
}

// The value of `metric` in the row of `table` whose columns match every (column, value) given.
inline double value_of(const study::ResultsTable& t, const std::string& metric,
                       const std::vector<std::pair<std::string, std::string>>& where) {
    const std::size_t m = t.column("metric"), v = t.column("value");
    for (const auto& row : t.rows) {
        if (row[m] != metric) continue;
        bool match = true;
        for (const auto& [col, want] : where) match = match && row[t.column(col)] == want;
        if (match) return row[v].empty() ? std::numeric_limits<double>::quiet_NaN() : std::stod(row[v]);
    }
    ADD_FAILURE() << "no row for " << metric;
    return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace vssw::testing
