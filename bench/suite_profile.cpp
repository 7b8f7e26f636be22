// Where a report's time goes: runs what `vssw report --no-plots` runs for a suite — the suite (default: the shipped
// "default", the engines `vssw report` compares by default), then its earthquake part and its relaxations part (the
// suite's default studies) — and prints the CPU time of their tasks summed per part and engine, beside each part's
// wall time and the CPU the whole process and its children used. A task's CPU is its thread's and that of the engine
// runs' children the thread waited for (compare::task_cpu_seconds): an engine run is a forked child.
//   vssw_suite_profile [--suite-only] [SUITE [THREADS [ENGINE ...]]]
#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <map>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "multibody/engine.hpp"
#include "validation/assumptions_part.hpp"
#include "validation/earthquake.hpp"
#include "validation/suite.hpp"
#include "validation/suite_file.hpp"

namespace {

using namespace vssw;
namespace fs = std::filesystem;

// CPU of a part's tasks, per engine: (cpu, tasks). Filled from the worker threads.
struct PartCpu {
    std::string part;
    double wall_s = 0.0;
    std::map<std::string, std::pair<double, int>> by_engine;
};

struct Profile {
    std::mutex mutex;
    std::vector<PartCpu> parts;
    void add(std::size_t part, const std::string& engine, double cpu_s) {
        const std::lock_guard<std::mutex> lock(mutex);
        auto& cell = parts[part].by_engine[engine];
        cell.first += cpu_s;
        ++cell.second;
    }
};

// A folder removed when the object goes, errors ignored.
struct RemovedAtEnd {
    fs::path dir;
    ~RemovedAtEnd() {
        std::error_code ec;
        fs::remove_all(dir, ec);
    }
};

// User and system CPU of this process and of the children it has waited for [s] (getrusage), as `time` prints it.
double process_cpu_seconds() {
    double s = 0.0;
    for (const int who : {RUSAGE_SELF, RUSAGE_CHILDREN}) {
        rusage u{};
        getrusage(who, &u);
        s += static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
             1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
    }
    return s;
}

// The suite's tasks, one part per case kind ("suite threshold", ...).
// Returns the threads it ran on.
int profile_suite(const validation::Suite& suite, const std::vector<std::string>& engines, int threads,
                  Profile& profile) {
    validation::RunOptions run;
    run.threads = threads;
    run.keep_traces = true;  // as `vssw report`
    const validation::SuiteResults r = validation::run_suite(suite, engines, run);
    std::map<std::string, std::size_t> part_of_kind;
    for (const validation::TaskTime& t : r.task_times) {
        const std::string part = std::string("suite ") + validation::to_string(t.kind);
        if (!part_of_kind.count(part)) {
            part_of_kind[part] = profile.parts.size();
            profile.parts.push_back({part, r.wall_time_s, {}});
        }
        profile.add(part_of_kind[part], t.engine, t.cpu_s);
    }
    return r.threads;
}

// A part's study run by `run` (the report's earthquake or relaxations part) with its tasks' CPU counted.
template <class Options, class Run>
void profile_part(const std::string& part, Options options, int threads, Profile& profile, const Run& run) {
    const std::size_t index = profile.parts.size();
    profile.parts.push_back({part, 0.0, {}});
    options.threads = threads;
    options.plots = false;
    options.task_cpu = [&profile, index](const std::string& engine, double cpu_s) {
        profile.add(index, engine, cpu_s);
    };
    const auto start = std::chrono::steady_clock::now();
    run(options);
    profile.parts[index].wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void print(const Profile& profile, int threads, double process_cpu_s) {
    std::map<std::string, double> per_engine;
    double total = 0.0;
    for (const PartCpu& p : profile.parts)
        for (const auto& [engine, cell] : p.by_engine) {
            per_engine[engine] += cell.first;
            total += cell.first;
        }
    fmt::print("task CPU {:.2f} s; the process and its children {:.2f} s; {} threads\n\n", total, process_cpu_s,
               threads);
    fmt::print("{:<20} {:<14} {:>6} {:>10} {:>7}\n", "part", "engine", "tasks", "cpu_s", "share");
    for (const PartCpu& p : profile.parts)
        for (const auto& [engine, cell] : p.by_engine)
            fmt::print("{:<20} {:<14} {:>6} {:>10.2f} {:>6.1f}%\n", p.part, engine, cell.second, cell.first,
                       100.0 * cell.first / total);
    fmt::print("\n");
    for (const auto& [engine, cpu] : per_engine)
        fmt::print("engine {:<20} {:>10.2f} s {:>6.1f}%\n", engine, cpu, 100.0 * cpu / total);
    double shown_wall = -1.0;
    for (const PartCpu& p : profile.parts) {
        double cpu = 0.0;
        for (const auto& [engine, cell] : p.by_engine) cpu += cell.first;
        const bool suite_kind = p.part.rfind("suite ", 0) == 0;
        std::string wall;  // the suite's kinds share one wall time, shown on the first
        if (!suite_kind) wall = fmt::format("wall {:.2f} s", p.wall_s);
        else if (p.wall_s != shown_wall) wall = fmt::format("wall {:.2f} s (the whole suite)", p.wall_s);
        shown_wall = p.wall_s;
        fmt::print("part   {:<20} {:>10.2f} s {:>6.1f}%{}\n", p.part, cpu, 100.0 * cpu / total,
                   wall.empty() ? "" : "  " + wall);
    }
}

}  // namespace

int main(int argc, char** argv) {
    try {
        std::vector<std::string> args(argv + 1, argv + argc);
        const bool suite_only = !args.empty() && args.front() == "--suite-only";
        if (suite_only) args.erase(args.begin());
        const std::string suite_name = !args.empty() ? args[0] : "default";
        const int threads = args.size() > 1 ? std::atoi(args[1].c_str()) : 0;
        std::vector<std::string> engines(args.size() > 2 ? args.begin() + 2 : args.end(), args.end());
        if (engines.empty()) engines = multibody::default_compared_engines();
        const validation::Suite suite = validation::read_suite(suite_name, VSSW_DATA_DIR);

        Profile profile;
        const int threads_used = profile_suite(suite, engines, threads, profile);
        if (!suite_only) {
            const fs::path dir = fs::temp_directory_path() / fmt::format("vssw_suite_profile.{}", ::getpid());
            const RemovedAtEnd remove_dir{dir};  // the parts' outputs, whether they finish or throw
            const std::string earthquake = validation::earthquake_study_file(
                validation::default_earthquake_for_suite(suite_name), engines);
            validation::EarthquakeRunOptions eq;
            eq.paper_model = true;  // as `vssw report`
            profile_part("earthquake", eq, threads, profile, [&](const validation::EarthquakeRunOptions& o) {
                return validation::run_earthquake_part(earthquake, engines, dir / "earthquake", o);
            });
            const std::string relaxations = validation::assumptions_study_file(
                validation::default_assumptions_for_suite(suite_name), engines);
            profile_part("relaxations", validation::PartRunOptions(), threads, profile,
                         [&](const validation::PartRunOptions& o) {
                             return validation::run_assumptions_part(relaxations, engines, dir / "relaxations", o);
                         });
        }
        fmt::print("suite {}{}\n", suite.name, suite_only ? " (the suite only)" : ", its earthquake and relaxations parts");
        print(profile, threads_used, process_cpu_seconds());
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "vssw_suite_profile: %s\n", e.what());
        return 2;
    }
}
