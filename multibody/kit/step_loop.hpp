#pragma once
// The fixed-step loop every stepping adapter runs, once: the ground motion at each step's midpoint (a tilted field or
// pseudo-forces, or the moving supports' velocity V_k = V_{k-1} + dt a_h), the overburden N on the top, the step, the
// run monitor's check of the blocks relative to the ground, the samples (every `every` steps, the last and the one
// that ends the run; the motion alone with Excitation::motion_only) and the end of the run. An adapter keeps its world
// building and supplies the hooks of SteppedWorld. Engine-free: no engine header is included here.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <utility>

#include "analytic/diaphragm.hpp"
#include "multibody/engine.hpp"
#include "multibody/kit/run_monitor.hpp"
#include "multibody/kit/wall_parts.hpp"

namespace vssw::multibody {

// The ground's motion over one step, as the loop hands it to an adapter.
struct GroundStep {
    // The horizontal ground acceleration at the step's midpoint [m/s^2]: its impulse over the step to second order.
    double a_h = 0.0;
    // Moving supports only (0 otherwise): the supports' velocity for the step, V_k = V_{k-1} + dt a_h (the velocity
    // change the pseudo-forces would give the blocks), and their displacement at its end by the midpoint rule.
    double v = 0.0, x = 0.0;
    // A flexible top support only (0 otherwise: the paper's rigid diaphragm): the roller's offset from the ground at
    // the step's end, u_d(t) of Eq. (9d), and the velocity relative to the ground that carries it there over the step,
    // (u_d(t) - u_d(t0)) / dt, so that a guide moved at it sits exactly on u_d at every step's end.
    double top_u = 0.0, top_v = 0.0;
};

// The times of step i (from 1): it runs from t0 to t.
struct StepTimes {
    long i;
    double t0, t, dt;
};

// The lower block's rotation and its rate, clockwise [rad, rad/s]: every sample's, the motion-only one's alone.
struct Rocking {
    double theta1, theta1_dot;
};

// The hooks an adapter gives the loop (W), called in this order each step:
//   void drive(const GroundStep&)           the ground motion for the step (a field, pseudo-forces or the supports);
//   void push_overburden()                  N on the top for the step (only when StepLoop::overburden);
//   void step(const StepTimes&, const GroundStep&);
//   void check_step(double t)               optional: the engine's own failures, thrown as EngineFailure;
//   WallState state(const GroundStep&)      the blocks relative to the (moving) ground, for the run monitor;
// and, when a sample is taken, Rocking rocking() (every sample) and void fill(TrajectorySample&) (a full sample's
// theta2, top_dy, kinetic, potential and contacts). Written without a C++20 concept: the project is C++17 (Simbody's
// headers do not compile as C++20).
template <class W, class = void>
struct HasCheckStep : std::false_type {};
template <class W>
struct HasCheckStep<W, std::void_t<decltype(std::declval<W&>().check_step(0.0))>> : std::true_type {};

// How the loop runs: the step, the sampling (sample_every), whether the supports move, whether N acts.
struct StepLoop {
    double dt;
    long every;
    bool moving_supports;
    bool overburden;
    // The VSSW's top support (the scene's): a flexible one moves the roller by u_d(t) relative to the ground
    // (GroundStep::top_u, top_v); only an adapter whose roller follows it passes it (the others refuse a flexible one:
    // require_rigid_top).
    Diaphragm diaphragm{};
};


// The supports' velocity and displacement after one more step of acceleration a_h.
inline void advance_supports(GroundStep& g, double dt) {
    const double v_next = g.v + dt * g.a_h;
    g.x += 0.5 * dt * (g.v + v_next);
    g.v = v_next;
}

// At most this many samples are reserved before a run (4 MiB: a run sampled every 1 ms for 65 s); a longer one grows.
inline constexpr long kReservedSamples = 1L << 16;

// Runs the wall from t = 0 to ex.t_end in steps of loop.dt (rounded to a whole number of steps); the monitor built by
// the adapter for this run. Returns the samples, the steps taken and how the run ended.
template <class W>
Trajectory run_fixed_steps(W& world, const Excitation& ex, const StepLoop& loop, RunMonitor& monitor) {
    Trajectory out;
    auto record = [&](double t) {
        const Rocking r = world.rocking();
        TrajectorySample p = motion_sample(t, r.theta1, r.theta1_dot);
        if (!ex.motion_only) world.fill(p);
        out.samples.push_back(p);
    };
    const double dt = loop.dt;
    const long n_steps = std::lround(ex.t_end / dt);
    // The samples of a whole run (the first, every `every` steps, the last) reserved at once: growing the vector copied
    // it and faulted in fresh pages, 3 % of a free vibration's CPU (perf, ODE). Pages not written are never touched.
    out.samples.reserve(static_cast<std::size_t>(std::min(n_steps / loop.every + 2, kReservedSamples)));
    GroundStep ground;
    const TopSupportMotion top(ex.horizontal, loop.diaphragm);  // once per run: u_d(t) of Eq. (9d)
    double top_u_before = 0.0;
    record(0.0);
    for (long i = 1; i <= n_steps; ++i) {
        const StepTimes st{i, static_cast<double>(i - 1) * dt, static_cast<double>(i) * dt, dt};
        ground.a_h = ex.horizontal(st.t0 + 0.5 * dt);
        if (loop.moving_supports) advance_supports(ground, dt);
        if (!top.is_rigid()) {
            ground.top_u = top(st.t).u;
            ground.top_v = (ground.top_u - top_u_before) / dt;
            top_u_before = ground.top_u;
        }
        world.drive(ground);
        if (loop.overburden) world.push_overburden();
        world.step(st, ground);
        ++out.steps;
        if constexpr (HasCheckStep<W>::value) world.check_step(st.t);
        WallState state = world.state(ground);
        state.top_offset = ground.top_u;
        const auto verdict = monitor.check(st.t, state);
        if (RunMonitor::records(i, n_steps, loop.every, verdict)) record(st.t);
        if (RunMonitor::ends_run(verdict, out)) break;
    }
    out.slip = monitor.slip();
    return out;
}

}  // namespace vssw::multibody
