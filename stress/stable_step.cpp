#include "stress/stable_step.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>

#include <fmt/format.h>

#include "analytic/wall.hpp"
#include "compare/experiments.hpp"
#include "compare/task_pool.hpp"
#include "multibody/host/child_process.hpp"
#include "multibody/engine.hpp"

namespace vssw::stress {
namespace {

using multibody::ChildEnd;
using multibody::ChildResult;
using multibody::WallScene;

WallScene wall_scene(const std::string& wall) {
    return wall == "fig6-vssw" ? WallScene::of(make_vssw(4.0, 0.4, 0.7)) : WallScene::of(make_parapet(4.0, 0.4));
}

struct Probe {
    bool ran = false;  // the run finished and measured both metrics
    double period = NAN, restitution = NAN;
    std::string failure;  // why not
};

// One free vibration (0.5 alpha, 3 impacts) at step dt, in a child.
Probe probe(const std::string& engine, const std::string& wall, double dt, double time_limit_s) {
    const ChildResult child = multibody::run_in_child(
        [&] {
            const auto e = multibody::make_engine_in_process(engine);  // already in a child
            multibody::EngineSettings s = e->default_settings();
            s.dt = dt;
            compare::FreeVibrationOptions o;
            o.impacts = 3;
            const auto r = compare::run_free_vibration(*e, s, wall_scene(wall), o);
            for (const auto& x : r.trajectory.samples)
                if (!std::isfinite(x.theta1) || !std::isfinite(x.theta1_dot)) return fmt::format("NaN at t = {:.4f} s", x.t);
            if (r.trajectory.overturned) return std::string("overturned");
            if (!r.period || !r.restitution)
                return "no measurable first impact" + (r.restitution_note.empty() ? "" : ": " + r.restitution_note);
            return fmt::format("= {:.17g} {:.17g}", *r.period, *r.restitution);
        },
        time_limit_s);
    Probe p;
    if (child.end != ChildEnd::completed) {
        p.failure = multibody::describe_failure(child);
    } else if (std::sscanf(child.output.c_str(), "= %lg %lg", &p.period, &p.restitution) == 2) {
        p.ran = true;
    } else {
        p.failure = child.output;
    }
    return p;
}

// Stable against the reference, or why not.
std::string instability(const Probe& p, const StableStep& s) {
    if (!p.ran) return p.failure;
    const double dp = p.period / s.reference_period - 1.0, de = p.restitution / s.reference_restitution - 1.0;
    if (!(std::abs(dp) <= kStablePeriodTol) || !(std::abs(de) <= kStableRestitutionTol))
        return fmt::format("period {:+.2f} %, restitution {:+.2f} % against the reference", 100.0 * dp, 100.0 * de);
    return "";
}

// default_dt is read by the caller before the pool starts: an engine made on a pool thread (ODE initialises its
// library then) could be half set up in the sibling thread's forked probe child.
StableStep search(const std::string& engine, const std::string& wall, double default_dt, double time_limit_s) {
    const auto start = std::chrono::steady_clock::now();
    StableStep s;
    s.engine = engine;
    s.wall = wall;
    s.default_dt = default_dt;
    s.reference_dt = s.default_dt / 4.0;
    const Probe ref = probe(engine, wall, s.reference_dt, time_limit_s);
    s.probes = 1;
    if (!ref.ran) {
        s.unstable_reason = "no reference: " + ref.failure;
        s.first_unstable_dt = s.reference_dt;
    } else {
        s.reference_period = ref.period;
        s.reference_restitution = ref.restitution;
        double lo = s.reference_dt, hi = 0.0;
        for (int k = 0; k <= kMaxDoublings; ++k) {
            const double dt = s.default_dt * std::ldexp(1.0, k);
            const std::string why = instability(probe(engine, wall, dt, time_limit_s), s);
            ++s.probes;
            if (!why.empty()) {
                hi = dt;
                s.unstable_reason = why;
                break;
            }
            lo = dt;
        }
        for (int i = 0; hi > 0.0 && i < kBisections; ++i) {
            const double mid = std::sqrt(lo * hi);
            const std::string why = instability(probe(engine, wall, mid, time_limit_s), s);
            ++s.probes;
            if (why.empty()) {
                lo = mid;
            } else {
                hi = mid;
                s.unstable_reason = why;
            }
        }
        if (lo >= s.default_dt) s.largest_stable_dt = lo;
        if (hi > 0.0) s.first_unstable_dt = hi;
    }
    s.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return s;
}

}  // namespace

std::vector<StableStep> find_stable_steps(const std::vector<std::string>& engines, double time_limit_s, int threads) {
    struct Search {
        std::string engine, wall;
        double default_dt;
    };
    std::vector<Search> searches;
    for (const std::string& e : engines)
        if (e != "analytic") {
            const double dt = multibody::make_engine(e)->default_settings().dt;
            for (const char* wall : {"fig6-vssw", "fig6-pw"}) searches.push_back({e, wall, dt});
        }
    std::vector<StableStep> out(searches.size());
    std::vector<compare::PoolTask> tasks(searches.size());
    compare::run_pool(tasks, {false}, threads, [&](std::size_t i) {
        out[i] = search(searches[i].engine, searches[i].wall, searches[i].default_dt, time_limit_s);
    });
    return out;
}

}  // namespace vssw::stress
