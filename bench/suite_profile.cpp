// Where a validation suite's time goes: runs a suite (default: the shipped "default", the engines `vssw report`
// compares by default) and prints the CPU time of its tasks summed per case kind and engine, with the wall time.
//   vssw_suite_profile [SUITE [THREADS [ENGINE ...]]]
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "validation/suite.hpp"
#include "multibody/engine.hpp"
#include "validation/suite_file.hpp"

int main(int argc, char** argv) {
    using namespace vssw;
    try {
        const std::string suite_name = argc > 1 ? argv[1] : "default";
        validation::RunOptions run;
        run.threads = argc > 2 ? std::atoi(argv[2]) : 0;
        run.keep_traces = true;  // as `vssw report`
        std::vector<std::string> engines;
        for (int i = 3; i < argc; ++i) engines.emplace_back(argv[i]);
        if (engines.empty()) engines = multibody::default_compared_engines();
        const validation::Suite suite = validation::read_suite(suite_name, VSSW_DATA_DIR);
        const validation::SuiteResults r = validation::run_suite(suite, engines, run);

        std::map<std::pair<std::string, std::string>, std::pair<double, int>> by;  // (kind, engine) -> (cpu, tasks)
        std::map<std::string, double> per_engine, per_kind;
        double total = 0.0;
        for (const validation::TaskTime& t : r.task_times) {
            auto& cell = by[{validation::to_string(t.kind), t.engine}];
            cell.first += t.cpu_s;
            ++cell.second;
            per_engine[t.engine] += t.cpu_s;
            per_kind[validation::to_string(t.kind)] += t.cpu_s;
            total += t.cpu_s;
        }
        fmt::print("suite {}: {} tasks, wall {:.2f} s on {} threads, task CPU {:.2f} s\n\n", suite.name,
                   r.task_times.size(), r.wall_time_s, r.threads, total);
        fmt::print("{:<10} {:<14} {:>6} {:>10} {:>7}\n", "kind", "engine", "tasks", "cpu_s", "share");
        for (const auto& [key, cell] : by)
            fmt::print("{:<10} {:<14} {:>6} {:>10.2f} {:>6.1f}%\n", key.first, key.second, cell.second, cell.first,
                       100.0 * cell.first / total);
        fmt::print("\n");
        for (const auto& [engine, cpu] : per_engine)
            fmt::print("engine {:<14} {:>10.2f} s {:>6.1f}%\n", engine, cpu, 100.0 * cpu / total);
        for (const auto& [kind, cpu] : per_kind)
            fmt::print("kind   {:<14} {:>10.2f} s {:>6.1f}%\n", kind, cpu, 100.0 * cpu / total);
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "vssw_suite_profile: %s\n", e.what());
        return 2;
    }
}
