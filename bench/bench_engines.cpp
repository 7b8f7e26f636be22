// Speed of each engine at its default settings: wall time per simulated second of free vibration (the VSSW and the
// parapet of Fig. 6, released at 0.5 alpha), reported as the counter `per_simulated_s` (seconds of wall time per
// simulated second). Run: build/bench/vssw_bench_engines --benchmark_repetitions=5
//   --benchmark_report_aggregates_only=true and quote the medians.
#include <benchmark/benchmark.h>

#include <string>

#include "multibody/engine.hpp"

namespace vssw {
namespace {

constexpr double kSimulated = 2.0;  // [s] of free vibration per iteration

void run(benchmark::State& state, const std::string& engine_name, const multibody::WallScene& scene) {
    const auto engine = multibody::make_engine_in_process(engine_name);
    multibody::EngineSettings settings = engine->default_settings();
    settings.sample_dt = 1e-3;  // a trajectory a metric would use
    multibody::Excitation ex;
    ex.theta0 = 0.5 * scene.alpha();
    ex.t_end = kSimulated;
    ex.stop_at_rest = false;
    ex.motion_only = true;  // what compare/ and study/ read (the speed table of docs/measurements/speed.md measures the harness's runs)
    for (auto _ : state) {
        const multibody::Trajectory t = engine->simulate(scene, ex, settings);
        benchmark::DoNotOptimize(t.samples.data());
    }
    state.counters["per_simulated_s"] =
        benchmark::Counter(kSimulated * static_cast<double>(state.iterations()),
                           benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void register_all() {
    for (const std::string& name : multibody::available_engines()) {
        benchmark::RegisterBenchmark(("FreeVibrationVssw/" + name).c_str(), [name](benchmark::State& s) {
            run(s, name, multibody::WallScene::of(make_vssw(4.0, 0.4, 0.7)));
        })->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(("FreeVibrationParapet/" + name).c_str(), [name](benchmark::State& s) {
            run(s, name, multibody::WallScene::of(make_parapet(4.0, 0.4)));
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
