#pragma once
// A shipped study run by the report for the report's engines (the earthquake part, the assumptions part), and what
// each part says of that run.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "study/runner.hpp"
#include "study/spec.hpp"

namespace vssw::validation {

// The study file with its engines replaced by the analytic model (the reference) and the report's; the settings it
// gives engines that are not run are dropped (the report chooses the engines, at the file's settings for those it
// names).
study::StudySpec with_engines(const std::string& file, const std::vector<std::string>& engines);

// What a part of the report says of its study's run: the file, the study's name and description, its folder (inside
// the report's), its rows and failed rows, its wall time.
struct StudyPartRun {
    std::string study_file, study_name, description;
    std::filesystem::path folder;
    long rows = 0, failed_rows = 0;
    double wall_time_s = 0.0;
};
// How the report runs a part's study: what `vssw report` passes on of its own options.
struct PartRunOptions {
    int threads = 0;  // 0: the available cores
    bool plots = true;
    std::string gnuplot = "gnuplot";
    std::string commit;  // vssw's, for the study's manifest
    std::function<void(long, long, const std::string&)> progress;  // as StudyRunOptions::progress
    std::function<void(const std::string&, double)> task_cpu;       // as StudyRunOptions::task_cpu
};
// The study runner's options of a part's (threads, commit, progress, task_cpu).
study::StudyRunOptions study_run_options(const PartRunOptions& options);

StudyPartRun study_part_run(const std::string& file, const study::StudySpec& spec, const std::filesystem::path& dir,
                            const study::StudyRunResult& result);

}  // namespace vssw::validation
