// Speed of the analytic core at relative tolerance 1e-10 (docs/contributing/analytic-speed.md's goals on a 2-core
// machine: the Fig. 6 free vibration to rest under 0.3 ms, met at about 0.22 ms; the Rinaldi record, through its whole
// length, under 1 ms, met at about 0.91 ms since the fifth pass; docs/measurements/speed.md,
// docs/contributing/analytic-speed.md). Run: build/bench/vssw_bench_analytic
//   --benchmark_repetitions=10 --benchmark_report_aggregates_only=true   and quote the medians (the CPU column when
//   the machine is loaded).
#include <benchmark/benchmark.h>

#include "analytic/simulate.hpp"
#include "analytic/specimens.hpp"

namespace vssw {
namespace {

SimulationOptions fast_options() {
    SimulationOptions o;
    o.step.rtol = 1e-10;
    o.keep_samples = false;  // events and summaries only: what a sweep or a threshold bisection needs
    return o;
}

// monitor: with the supports' forces along the run (the default), or the motion alone (what it costs).
void run_free_vibration(benchmark::State& state, Kinematics k, bool monitor = true) {
    const VsswGeometry w = make_vssw(4.0, 0.4, 0.7);  // Fig. 6: b = 0.2 m, h = 2 m, h1/h = 0.7, xi = 0
    const auto m = make_vssw_model(w, k);
    SimulationOptions o = fast_options();
    o.monitor_supports = monitor;
    for (auto _ : state) {
        const SimulationResult r = free_vibration(*m, 0.9 * w.alpha1, o);
        benchmark::DoNotOptimize(r.rest_times);
    }
}

void run_rinaldi(benchmark::State& state, Kinematics k, bool monitor = true) {
    // Table 1 specimen 18 (17's twin), Fig. 9's h1/h and xi.
    const VsswGeometry w = make_vssw(table1_specimen(read_table1(default_table1_path()), 18), 0.1);
    const auto m = make_vssw_model(w, k);
    // Scaled to 0.25 so that the wall rocks through all 19.9 s (unscaled, it overturns at 2.9 s).
    const GroundMotion record = read_record(std::string(VSSW_DATA_DIR) + "/NGA_no_1063_RRS228.AT2").scaled(0.25);
    SimulationOptions o = fast_options();
    o.t_end = record.duration();
    o.monitor_supports = monitor;
    for (auto _ : state) {
        const SimulationResult r = simulate(*m, record, GroundMotion::none(), {}, o);
        benchmark::DoNotOptimize(r.max_abs_theta);
    }
}

void BM_Fig6FreeVibrationPaper(benchmark::State& s) { run_free_vibration(s, Kinematics::paper); }
void BM_Fig6FreeVibrationExact(benchmark::State& s) { run_free_vibration(s, Kinematics::exact); }
void BM_RinaldiPaper(benchmark::State& s) { run_rinaldi(s, Kinematics::paper); }
void BM_RinaldiExact(benchmark::State& s) { run_rinaldi(s, Kinematics::exact); }
void BM_Fig6FreeVibrationExactMotionOnly(benchmark::State& s) { run_free_vibration(s, Kinematics::exact, false); }
void BM_RinaldiExactMotionOnly(benchmark::State& s) { run_rinaldi(s, Kinematics::exact, false); }

BENCHMARK(BM_Fig6FreeVibrationPaper)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Fig6FreeVibrationExact)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_RinaldiPaper)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_RinaldiExact)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Fig6FreeVibrationExactMotionOnly)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_RinaldiExactMotionOnly)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace vssw

BENCHMARK_MAIN();
