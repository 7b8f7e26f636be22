#pragma once
// Event location shared by the event-driven phases (simulate.cpp, off_roller.cpp). Each phase writes its events as a
// table of guards g(t, y), each crossing zero in a direction at its event (CVODE's root functions with their rootdir,
// Drake's witness functions); one routine looks at a guard along an accepted step and brackets its crossings
// (scan_and_bracket), and one takes the earliest over a table (first_root_over). The phases' own tables and resets
// are in their files.
#include <cstddef>
#include <limits>
#include <optional>
#include <utility>

namespace vssw {

constexpr int kMaxBisections = 400;  // bound on root-search iterations; reached only by a broken bracket

// Shrinks a bracket [lo, hi] of a sign change of f (f(lo) on one side, f(hi) on the other or zero) to width tol by
// Illinois false position, bisecting whenever two steps have not halved it: superlinear on the smooth functions met
// here, never slower than bisection. hi keeps the side of f(hi).
template <class F>
void shrink_bracket(F f, double& lo, double& hi, double tol) {
    double flo = f(lo), fhi = f(hi);
    int retained = 0;      // which end the last two steps kept: -1 lo, +1 hi (Illinois halves its value)
    int slow_steps = 0;    // steps since the bracket last halved
    double mark = hi - lo;
    for (int i = 0; i < kMaxBisections && hi - lo > tol; ++i) {
        double x = 0.5 * (lo + hi);
        if (slow_steps < 2 && fhi != flo) {
            const double secant = (lo * fhi - hi * flo) / (fhi - flo);
            if (secant > lo && secant < hi) x = secant;
        }
        const double fx = f(x);
        if (fx != 0.0 && (fx > 0.0) == (flo > 0.0)) {
            lo = x;
            flo = fx;
            if (retained == 1) fhi *= 0.5;
            retained = 1;
        } else {
            hi = x;
            fhi = fx;
            if (retained == -1) flo *= 0.5;
            retained = -1;
        }
        if (hi - lo <= 0.5 * mark) {
            mark = hi - lo;
            slow_steps = 0;
        } else {
            ++slow_steps;
        }
        if (fx == 0.0) break;
    }
}

// Which way a guard crosses zero at its event. Falling: from above zero to zero or below (reaching the surface
// counts: a wall that touches the ground has landed). Rising: from zero or below to above zero (a force that was
// zero and now pulls). Either: from a non-zero value to zero or to the other sign (a velocity that turns).
enum class Direction { falling, rising, either };

constexpr bool crosses(Direction d, double before, double after) {
    switch (d) {
        case Direction::falling: return before > 0.0 && after <= 0.0;
        case Direction::rising: return before <= 0.0 && after > 0.0;
        case Direction::either: return before != 0.0 && (after == 0.0 || (after > 0.0) != (before > 0.0));
    }
    return false;
}

// Whether a guard's value lies on its event's side of zero: at or below zero for a falling guard, above it for a
// rising one. An either-way guard has no such side.
constexpr bool past(Direction d, double value) {
    return d == Direction::falling ? value <= 0.0 : d == Direction::rising && value > 0.0;
}

// A guard along one step: its direction, its values at the step's start and end (the end read off the step's own end
// state, not its continuous extension), and value(t) at any time of the step (the continuous extension).
template <class Value>
struct StepGuard {
    Direction direction;
    double before, at_end;
    Value value;
};
template <class Value>
StepGuard(Direction, double, double, Value) -> StepGuard<Value>;

// Where a guard is looked at along a step [t0, t0 + h]: n evenly spaced times t0 + h k / n, k = 1..n, the last at the
// step's end, `end` (t0 + h unless the motion ends before it). One look (the end) finds what crosses once in a step;
// more find a guard that crosses and comes back within the step (a velocity that turns twice, a wall that lands
// within the first step of a flight).
struct Looks {
    double t0, h;
    int n = 1;
    // A crossing at look k is bracketed from look k - 1; with `from_width`, from one spacing h / n before look k. The
    // two are the same instant up to rounding; the impact and overturning searches of simulate.cpp bracket that way
    // and are kept so, to keep their results to the bit.
    bool from_width = false;
    double end = t0 + h;
    double time(int k) const { return k == n ? end : t0 + h * k / n; }
};

// A crossing located: the look that saw it (1..n) and its time, the bracket's end on the event's side, within the
// tolerance of the guard's zero.
struct Root {
    int look;
    double t;
};

constexpr double kNoLimit = std::numeric_limits<double>::infinity();

// Scan-and-bracket: looks at guard g along the step (Looks) and, for each crossing in its direction between two
// successive looks, shrinks the bracket to tol (shrink_bracket on g.value) and calls on_root(root), in time order,
// while it returns true. A look whose interval starts at or after `until` is not taken: the motion past an event
// that ends the step is not part of it.
template <class Value, class OnRoot>
void scan_and_bracket(const StepGuard<Value>& g, const Looks& looks, double tol, OnRoot on_root,
                      double until = kNoLimit) {
    double t_previous = looks.t0, previous = g.before;
    for (int k = 1; k <= looks.n; ++k) {
        const double t_look = looks.time(k);
        if (t_previous >= until) return;
        const double value = k == looks.n ? g.at_end : g.value(t_look);
        if (crosses(g.direction, previous, value)) {
            double lo = looks.from_width ? t_look - looks.h / looks.n : t_previous, hi = t_look;
            shrink_bracket(g.value, lo, hi, tol);
            if (!on_root(Root{k, hi})) return;
        }
        t_previous = t_look;
        previous = value;
    }
}

// The first root over a table of guards on a step: each guard the step's end shows across (its values at the start
// and the end cross in its direction; one that crosses and comes back within the step is not an event of it) is
// scanned and bracketed, guard_of(key) giving its StepGuard; the earliest root is returned with its key, a tie
// going to the later key. Nothing when no guard is across.
template <class Key, std::size_t N, class GuardOf>
std::optional<std::pair<Key, Root>> first_root_over(const Key (&table)[N], const Looks& looks, double tol,
                                                    GuardOf guard_of) {
    std::optional<std::pair<Key, Root>> first;
    for (const Key key : table) {
        const auto g = guard_of(key);
        if (!crosses(g.direction, g.before, g.at_end)) continue;
        scan_and_bracket(g, looks, tol, [&](Root r) {
            if (!first || r.t <= first->second.t) first = std::make_pair(key, r);
            return false;
        });
    }
    return first;
}

}  // namespace vssw
