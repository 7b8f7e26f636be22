// The floor's cost (bench/floor/floor_step.hpp): CPU time per simulated second and per step of the minimal planar
// two-block contact step of the impulse engines' scheme, on the Fig. 6 VSSW (4 x 0.4 m, h1/h 0.7) at a 1 ms step,
// with 4, 8 (the default), 10 and 20 sequential-impulse sweeps:
//  - FloorFreeVibration: released at 0.5 alpha1, 2 simulated seconds (as vssw_bench_engines' FreeVibrationVssw);
//  - FloorAtRest: the wall at rest under a small record-like shaking (two sines, half the rest threshold at their
//    peak), every contact closed: the state a record run mostly spends its steps in.
// The run samples theta1 every step, as an engine's motion-only run does. Counters are rates of CPU time (Google
// Benchmark's default): `per_simulated_s` seconds of CPU per simulated second, `per_step` seconds of CPU per step.
// Run: build/bench/vssw_bench_floor --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cmath>
#include <functional>

#include "analytic/wall.hpp"
#include "bench/floor/floor_step.hpp"
#include "multibody/kit/scene_geometry.hpp"

namespace vssw {
namespace {

constexpr double kSimulated = 2.0;  // [s] per iteration, as vssw_bench_engines
constexpr double kTwoPi = 6.283185307179586;

void run(benchmark::State& state, double theta0_share, bool shaken) {
    const multibody::WallScene scene = multibody::WallScene::of(make_vssw(4.0, 0.4, 0.7));
    yardstick::FloorSettings settings;
    settings.iterations = static_cast<int>(state.range(0));
    std::function<double(double)> a_h;
    if (shaken) {
        // Half the rest threshold at most: 0.3 + 0.2 of it, at 1.7 Hz and 4.3 Hz (a record's band; never in phase).
        const double amplitude = 0.5 * multibody::rest_threshold(scene);
        a_h = [amplitude](double t) {
            return amplitude * (0.6 * std::sin(kTwoPi * 1.7 * t) +
                                0.4 * std::sin(kTwoPi * 4.3 * t));
        };
    }
    long steps = 0;
    for (auto _ : state) {
        const multibody::Trajectory t =
            yardstick::run_floor(scene, theta0_share * scene.alpha(), kSimulated, settings, a_h);
        benchmark::DoNotOptimize(t.samples.data());
        steps += t.steps;
    }
    state.counters["per_simulated_s"] =
        benchmark::Counter(kSimulated * static_cast<double>(state.iterations()),
                           benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    state.counters["per_step"] =
        benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void FloorFreeVibration(benchmark::State& state) { run(state, 0.5, false); }
void FloorAtRest(benchmark::State& state) { run(state, 0.0, true); }

BENCHMARK(FloorFreeVibration)->ArgName("iterations")->Arg(8)->Arg(4)->Arg(10)->Arg(20)->Unit(benchmark::kMicrosecond);
BENCHMARK(FloorAtRest)->ArgName("iterations")->Arg(8)->Arg(4)->Arg(10)->Arg(20)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace vssw

BENCHMARK_MAIN();
