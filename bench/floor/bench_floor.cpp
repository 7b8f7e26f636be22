// The floor's cost (bench/floor/floor_step.hpp): CPU time per simulated second and per step of the minimal planar
// two-block contact step of the impulse engines' scheme, on the Fig. 6 VSSW (4 x 0.4 m, h1/h 0.7) at a 1 ms step,
// with 4, 8 (the default), 10 and 20 sequential-impulse sweeps:
//  - FloorFreeVibration: released at 0.5 alpha1, 2 simulated seconds (as vssw_bench_engines' FreeVibrationVssw);
//  - FloorAtRest: under the Lucerne record at 0.2 g (bench/floor/lucerne.hpp), under the wall's threshold: at rest
//    with every contact closed for the record's first 20 s;
//  - FloorRecord: under the same record at 1.0 g (as vssw_bench_engines' RecordVssw): it rocks, then stands.
// The run samples theta1 every step, as an engine's motion-only run does. Counters are rates of CPU time (Google
// Benchmark's default): `per_simulated_s` seconds of CPU per simulated second, `per_step` seconds of CPU per step.
// Run: build/bench/vssw_bench_floor --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <functional>
#include <string>

#include "analytic/wall.hpp"
#include "bench/floor/floor_step.hpp"
#include "bench/floor/lucerne.hpp"

namespace vssw {
namespace {

constexpr double kFreeVibration = 2.0;  // [s] per iteration, as vssw_bench_engines

void run(benchmark::State& state, double theta0_share, double pga_g) {
    const multibody::WallScene scene = multibody::WallScene::of(make_vssw(4.0, 0.4, 0.7));
    yardstick::FloorSettings settings;
    settings.iterations = static_cast<int>(state.range(0));
    GroundMotion motion = GroundMotion::none();
    if (pga_g > 0.0) motion = yardstick::lucerne(VSSW_DATA_DIR, pga_g);
    const double simulated = pga_g > 0.0 ? yardstick::kRecordWindow : kFreeVibration;
    const std::function<double(double)> a_h = [&motion](double t) { return motion(t); };
    long steps = 0;
    for (auto _ : state) {
        const multibody::Trajectory t =
            yardstick::run_floor(scene, theta0_share * scene.alpha(), simulated, settings, a_h);
        benchmark::DoNotOptimize(t.samples.data());
        steps += t.steps;
    }
    state.counters["per_simulated_s"] =
        benchmark::Counter(simulated * static_cast<double>(state.iterations()),
                           benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    state.counters["per_step"] =
        benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void FloorFreeVibration(benchmark::State& state) { run(state, 0.5, 0.0); }
void FloorAtRest(benchmark::State& state) { run(state, 0.0, 0.2); }
void FloorRecord(benchmark::State& state) { run(state, 0.0, 1.0); }

BENCHMARK(FloorFreeVibration)->ArgName("iterations")->Arg(8)->Arg(4)->Arg(10)->Arg(20)->Unit(benchmark::kMicrosecond);
BENCHMARK(FloorAtRest)->ArgName("iterations")->Arg(8)->Arg(4)->Arg(10)->Arg(20)->Unit(benchmark::kMicrosecond);
BENCHMARK(FloorRecord)->ArgName("iterations")->Arg(8)->Arg(4)->Arg(10)->Arg(20)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace vssw

BENCHMARK_MAIN();
