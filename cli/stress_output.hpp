#pragma once
// What `vssw stress` writes: the verdicts (and the largest stable steps, full set) as JSON, CSV and a short Markdown
// summary. Pure formatting: cmd_stress.cpp runs the cases and writes the files atomically.
#include <iosfwd>
#include <string>
#include <vector>

#include "io/json.hpp"
#include "stress/stable_step.hpp"
#include "stress/verdict.hpp"

namespace vssw::cli {

struct StressReport {
    bool quick = false;
    double time_limit_s = 0.0;
    std::vector<std::string> engines;
    std::vector<stress::CaseResult> cases;
    std::vector<stress::StableStep> stable_steps;  // empty in the quick set
    double wall_time_s = 0.0;
};

// {"quick", "time_limit_s", "engines", "cases": [{name, engine, verdict, failure, reason, time_s}], "unsafe",
//  "stable_steps": [...], "case_list": [{name, quick, what}], "wall_time_s"}
io::Json stress_json(const StressReport& r);
void write_stress_csv(std::ostream& out, const StressReport& r);
void write_stress_md(std::ostream& out, const StressReport& r);
// The verdict table for the terminal: one row per case, one column per engine.
void write_stress_table(std::ostream& out, const StressReport& r);

}  // namespace vssw::cli
