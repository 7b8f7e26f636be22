// Speed of each engine at its default settings: CPU time per simulated second of free vibration (the VSSW and the
// parapet of Fig. 6, released at 0.5 alpha1, a parapet's alpha), reported as the counter `per_simulated_s` (seconds
// of this process's CPU time per simulated second: Google Benchmark's rate counters divide by CPU time unless a
// benchmark asks for real time, and the runs here are in-process, so the CPU time is the run's). Compare with the
// floor's cost per step (bench/floor/bench_floor.cpp): `per_step` is the CPU time per engine step. RecordVssw runs the
// Fig. 6 VSSW under the Lucerne record at 1.0 g (bench/floor/lucerne.hpp), its first 20 s, as the floor's FloorRecord.
// Run:
//   build/bench/vssw_bench_engines --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// and quote the medians.
#include <benchmark/benchmark.h>

#include <string>

#include "bench/floor/lucerne.hpp"
#include "multibody/engine.hpp"

namespace vssw {
namespace {

constexpr double kSimulated = 2.0;  // [s] of free vibration per iteration

void run(benchmark::State& state, const std::string& engine_name, const multibody::WallScene& scene,
         const GroundMotion* record) {
    const auto engine = multibody::make_engine_in_process(engine_name);
    multibody::EngineSettings settings = engine->default_settings();
    settings.sample_dt = 1e-3;  // a trajectory a metric would use
    multibody::Excitation ex;
    ex.theta0 = record ? 0.0 : 0.5 * scene.alpha();
    if (record) ex.horizontal = *record;
    ex.t_end = record ? yardstick::kRecordWindow : kSimulated;
    ex.stop_at_rest = false;
    ex.motion_only = true;  // what compare/ and study/ read (the speed table of docs/measurements/speed.md measures the harness's runs)
    long steps = 0;
    for (auto _ : state) {
        const multibody::Trajectory t = engine->simulate(scene, ex, settings);
        benchmark::DoNotOptimize(t.samples.data());
        steps += t.steps;
    }
    state.counters["per_simulated_s"] =
        benchmark::Counter(ex.t_end * static_cast<double>(state.iterations()),
                           benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    state.counters["per_step"] =
        benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void register_all() {
    for (const std::string& name : multibody::available_engines()) {
        benchmark::RegisterBenchmark(("FreeVibrationVssw/" + name).c_str(), [name](benchmark::State& s) {
            run(s, name, multibody::WallScene::of(make_vssw(4.0, 0.4, 0.7)), nullptr);
        })->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(("FreeVibrationParapet/" + name).c_str(), [name](benchmark::State& s) {
            run(s, name, multibody::WallScene::of(make_parapet(4.0, 0.4)), nullptr);
        })->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(("RecordVssw/" + name).c_str(), [name](benchmark::State& s) {
            const GroundMotion record = yardstick::lucerne(VSSW_DATA_DIR, 1.0);
            run(s, name, multibody::WallScene::of(make_vssw(4.0, 0.4, 0.7)), &record);
        })->Unit(benchmark::kMillisecond);
    }
}

}  // namespace
}  // namespace vssw

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    vssw::register_all();
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
