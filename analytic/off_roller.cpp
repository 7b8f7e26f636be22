#include "off_roller.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "bracket.hpp"

namespace vssw {
namespace {

using State = Vec<5>;  // theta1, theta2, theta1', theta2', work of the ground
enum class Mode { free, far_guide };
// The flight's events as a table of guards g(t, y) (bracket.hpp), each falling through zero at its event, and the
// reset each one calls (Flight::reset):
//   event           guard g(t, y)                      reset
//   base impact     side theta1                        on the far guide: the one-DOF model's impact (the caller's);
//                                                      in free flight: not modelled, a failure
//   collapse        collapse angle - side theta1       the run ends
//   roller landing  the roller corner's gap            plastic landing onto the one-DOF mechanism: the flight ends
//   far landing     the far corner's gap               plastic landing onto the far guide
//   far release     the far guide's push               free flight
//   fold            free: side theta2 + alpha2 + pi/2  the run ends: the upper block has turned past the lock of
//                   far guide: pi/2 - |theta2|         the roller (Eq. 26) or of the far guide (theta2 = pi/2):
//                                                      the standing mechanism is gone (overturning)
// The turning points of theta1 (theta1' crossing zero either way) are recorded on the way.
enum class Event { none, roller_landing, far_landing, far_release, base_impact, collapse, fold };
// On the far guide the wall can only be released from it.
// Free flight can land on either guide (its base impact is looked for first: Flight::first_event).
constexpr Event kFreeEvents[] = {Event::collapse, Event::fold, Event::roller_landing, Event::far_landing};
constexpr Event kFarGuideEvents[] = {Event::base_impact, Event::collapse, Event::fold, Event::far_release};

// Eq. (2) with the top on the roller has two branches, side theta2 + alpha2 = asin(s sin(alpha1 - |theta1|)) (the
// standing one, through rest) and -pi - asin(...) (folded), which meet at Eq. (26)'s limit where the asin is -pi/2.
// Off the roller the upper block can turn on past that lock (measured: to 4 rad and back to theta1 = 0, where the
// guides' gaps no longer describe its corners): the flight ends there as overturning, which is also what keeps a
// flight from landing on the folded branch, where the one-DOF model's theta2(theta1) would be the other one.
constexpr double kHalfPi = 1.5707963267948966;

// A corner this close to its guide (relative to b) is on it: the round-off of its position (some 1e-16 m) is a
// thousand times smaller.
constexpr double kOnGuide = 1e-12;

// The first step of a flight: the motion has just changed mechanism; the controller takes over from there.
constexpr double kFirstFlightStep = 1e-4;  // [s]

Vec2 q_of(const State& y) { return {y[0], y[1]}; }
Vec2 qdot_of(const State& y) { return {y[2], y[3]}; }

class Flight {
public:
    Flight(const VsswGeometry& w, const OffRollerSetup& s, int side)
        : wall_(w, side), s_(s), side_(side),
          integrator_(Rhs{this}, s.step, State{w.alpha1, w.alpha2, 1.0, 1.0, w.W * w.h()}) {}

    OffRollerEnd run(const OffRollerStart& start, long& steps);

private:
    struct Rhs {
        const Flight* f;
        State operator()(double t, const State& y) const { return f->derivative(t, y); }
    };

    Vec2 acceleration(double t, const State& y) const {
        const double a_h = (*s_.horizontal)(t), a_v = (*s_.vertical)(t);
        if (mode_ == Mode::free) return wall_.free_acceleration(q_of(y), qdot_of(y), a_h, a_v);
        return wall_.constrained_motion(q_of(y), qdot_of(y), a_h, a_v, Guide::far).qddot;
    }
    State derivative(double t, const State& y) const {
        const Vec2 q = q_of(y), qd = qdot_of(y), qdd = acceleration(t, y);
        // The ground's pseudo-forces' power: the generalised forces with the ground minus those without it.
        const double a_h = (*s_.horizontal)(t), a_v = (*s_.vertical)(t);
        const Vec2 ground = wall_.generalized_forces(q, a_h, a_v) - wall_.generalized_forces(q, 0.0, 0.0);
        return {qd(0), qd(1), qdd(0), qdd(1), ground.dot(qd)};
    }
    double far_force(double t, const State& y) const {
        return wall_.constrained_motion(q_of(y), qdot_of(y), (*s_.horizontal)(t), (*s_.vertical)(t), Guide::far)
            .roller;
    }
    double on_guide_band() const { return kOnGuide * wall_.wall().b; }  // [m]
    // A landing guard's value at a step's start, `value` its guard there. A corner that starts the step on its guide
    // (the roller it has just left; right after a base impact at theta1 = 0 both guides, the slot being closed) has a
    // gap of round-off size, of either sign: read as zero or below, it could never fall through zero, and the corner
    // went through its guide unseen (measured: 0.6 mm and 3.2 mm before the base impact, energy balance errors 7e-4 and
    // 5e-3 of the largest energy in play, at micro-rocking). Such a start counts as just off the guide, so that a
    // corner that moves into it lands at once. Every other value is the guard's own.
    double step_start_guard(Event ev, double value) const {
        const bool landing = ev == Event::roller_landing || ev == Event::far_landing;
        return landing && value <= 0.0 && value >= -on_guide_band() ? on_guide_band() : value;
    }
    // The guards of the table above: positive before the event.
    double guard(Event ev, double t, const State& y) const {
        switch (ev) {
            case Event::roller_landing: return wall_.gap(q_of(y), Guide::roller);
            case Event::far_landing: return wall_.gap(q_of(y), Guide::far);
            case Event::far_release: return far_force(t, y);
            case Event::base_impact: return side_ * y[0];
            case Event::collapse: return s_.collapse_angle - side_ * y[0];
            case Event::fold:  // each mode's lock: the roller's (free flight) or the far guide's (|theta2| = pi/2)
                return mode_ == Mode::free ? side_ * y[1] + wall_.wall().alpha2 + kHalfPi : kHalfPi - std::abs(y[1]);
            case Event::none: break;
        }
        return 1.0;
    }
    // On the far guide the state is kept on it: theta2 and its rate from theta1 (the integration drifts slowly).
    void project(State& y) const {
        if (mode_ != Mode::far_guide) return;
        const Vec2 q = wall_.on_far_guide(y[0]);
        y[1] = q(1);
        y[3] = wall_.mechanism_tangent(q, Guide::far)(1) * y[2];
    }
    bool take_step(double t, const State& y, const State& dy, double& h_try, RkStep<5>& step) const;
    std::optional<std::pair<Event, Root>> first_event(double t, const State& y, RkStep<5>& step) const;
    void record_turning_points(double t, const State& y, RkStep<5>& step, double until, OffRollerEnd& out) const;
    std::optional<OffRollerEnd::How> reset(Event ev, double t, State& y, OffRollerEnd& out);

    TwoBlockWall wall_;
    const OffRollerSetup& s_;
    int side_;
    Mode mode_ = Mode::free;
    Dop853<5, Rhs> integrator_;
};

OffRollerEnd Flight::run(const OffRollerStart& start, long& steps) {
    OffRollerEnd out{};
    double t = start.t;
    const Vec2 q0 = wall_.on_roller(start.theta1);
    const Vec2 tangent = wall_.mechanism_tangent(q0, Guide::roller);
    State y{q0(0), q0(1), start.theta1_dot, tangent(1) * start.theta1_dot, start.work_ground};
    out.max_abs_theta = std::abs(y[0]);
    // Leaving at theta1 = 0 (a lift-off where the roller would pull at once): the far corner is on its guide too, and
    // as both guides share their Jacobian there the motion presses it in at second order, never crossing its gap
    // from outside: the flight starts leaning on the far guide (measured: a free start sank the corner 3e-4 m into
    // it unseen, and the energy balance failed at the next impact).
    if (wall_.gap(q0, Guide::far) <= on_guide_band()) {
        mode_ = Mode::far_guide;
        project(y);
        if (far_force(t, y) < 0.0) mode_ = Mode::free;
    }
    State dy = integrator_.rhs(t, y);
    double h_try = kFirstFlightStep;
    RkStep<5> step;
    auto finish = [&](OffRollerEnd::How how) {
        out.how = how;
        out.t = t;
        out.theta1 = y[0];
        out.theta1_dot = y[2];
        out.work_ground = y[4];
        return out;
    };
    while (t < s_.t_end) {
        if (++steps > s_.max_steps)
            throw std::runtime_error("integration exceeded the step limit (top off the roller)");
        if (!take_step(t, y, dy, h_try, step)) continue;
        const auto first = first_event(t, y, step);
        const double first_time = first ? first->second.t : t + step.h;
        if (s_.emit) {
            integrator_.make_dense(step);
            s_.emit(t, first_time, [&](double tau) { return step.at(tau); });
        }
        record_turning_points(t, y, step, first_time, out);
        if (first) {
            t = first_time;
            y = step.at(first_time);
        } else {
            t += step.h;
            y = step.y1;
            project(y);
        }
        out.max_abs_theta = std::max(out.max_abs_theta, std::abs(y[0]));
        if (s_.check_energy) s_.check_energy(t, y, out.dissipated);
        if (first)
            if (const std::optional<OffRollerEnd::How> how = reset(first->first, t, y, out))
                return finish(*how);
        dy = integrator_.rhs(std::nextafter(t, s_.t_end + 1.0), y);
        if (first) h_try = std::min(h_try, kFirstFlightStep);
    }
    return finish(OffRollerEnd::How::end_time);
}

// A trial step from (t, y) to the next breakpoint or the end (h_try at most) into `step`; false when rejected (h_try
// is cut). On acceptance h_try is the next step's size.
bool Flight::take_step(double t, const State& y, const State& dy, double& h_try, RkStep<5>& step) const {
    const double stop = std::min(s_.next_breakpoint(t), s_.t_end);
    const double h = std::min(h_try, stop - t);
    const double err = integrator_.step(t, y, dy, h, step);
    bool finite = std::isfinite(err);
    for (double v : step.y1) finite = finite && std::isfinite(v);
    if (!finite || err > 1.0) {
        h_try = finite ? integrator_.next_step(h, err) : 0.25 * h;
        if (h_try <= s_.step.min_step)
            throw std::runtime_error(fmt::format("step size underflow at t = {} s with the top off the roller", t));
        return false;
    }
    h_try = integrator_.next_step(h, err);
    return true;
}

// The first root over the mode's guards on the step, bracketed on its continuous extension from the step's start and
// end (one look: a guard the step crosses and crosses back is not seen; the steps are short next to the flight). In
// free flight the guards are looked at up to theta1 = 0 when the step reaches it: past it the flight's side is the
// wrong one, and a corner that has struck its guide just before the base can look clear again there (measured: a far
// landing missed by 4e-5 m of penetration, the base impact then taken with the top inside the guide).
std::optional<std::pair<Event, Root>> Flight::first_event(double t, const State& y, RkStep<5>& step) const {
    const auto at = [this, &step](double tau) {
        integrator_.make_dense(step);
        return step.at(tau);
    };
    const auto on_step_until = [&](double end) {
        return [&, end](Event ev) {
            const double before = step_start_guard(ev, guard(ev, t, y));
            return StepGuard{Direction::falling, before,
                             end == t + step.h ? guard(ev, end, step.y1) : guard(ev, end, at(end)),
                             [this, ev, &at, t, before](double tau) {
                                 return tau == t ? before : guard(ev, tau, at(tau));
                             }};
        };
    };
    if (mode_ == Mode::far_guide)
        return first_root_over(kFarGuideEvents, Looks{t, step.h}, s_.event_time_tol, on_step_until(t + step.h));
    const Event base[] = {Event::base_impact};
    const auto impact = first_root_over(base, Looks{t, step.h}, s_.event_time_tol, on_step_until(t + step.h));
    const double end = impact ? impact->second.t : t + step.h;
    const auto other = first_root_over(kFreeEvents, Looks{t, end - t}, s_.event_time_tol, on_step_until(end));
    return other ? other : impact;
}

// The turning points of theta1 inside the step up to `until` (the step's event), recorded as peaks.
void Flight::record_turning_points(double t, const State& y, RkStep<5>& step, double until, OffRollerEnd& out) const {
    const StepGuard velocity{Direction::either, y[2], step.y1[2], [&](double tau) {
                                 integrator_.make_dense(step);
                                 return step.at(tau)[2];
                             }};
    scan_and_bracket(velocity, Looks{t, step.h}, s_.event_time_tol, [&](Root r) {
        if (r.t <= until) out.peaks.push_back({r.t, step.at(r.t)[0]});
        return true;
    });
}

// The reset of an event at (t, y): the flight's end when it ends there, nothing when it goes on (in another mode).
std::optional<OffRollerEnd::How> Flight::reset(Event ev, double t, State& y, OffRollerEnd& out) {
    switch (ev) {
        case Event::none: break;
        case Event::collapse:
        case Event::fold: return OffRollerEnd::How::collapse;
        case Event::base_impact:
            if (mode_ == Mode::free) {
                // theta1 = 0 in free flight: both top corners are back at their guides (the slot has closed, theta2
                // ~ 0), so the base and the guides strike at once. Taken as the top's plastic landing on the roller
                // an instant before the base (the M-orthogonal projection onto the mechanism, as any landing),
                // whose one-DOF base impact the caller applies: both steps dissipative, the energy accounted for.
                const TwoBlockWall::Landing l = wall_.land(wall_.on_roller(0.0), qdot_of(y), Guide::roller);
                out.dissipated += l.dissipated;
                y[1] = 0.0;
                y[2] = l.theta1_dot;
            }
            y[0] = 0.0;
            return OffRollerEnd::How::base_impact;
        case Event::roller_landing: {
            const TwoBlockWall::Landing l = wall_.land(q_of(y), qdot_of(y), Guide::roller);
            out.dissipated += l.dissipated;
            y[2] = l.theta1_dot;
            return OffRollerEnd::How::on_roller;
        }
        case Event::far_landing: {
            // The far guide's Eq. (2) has its branches too (sin theta2 fixed, two_block.cpp): landing with
            // |theta2| > pi/2 is on the folded one, the upper block turned over: overturning, as at the fold above.
            if (std::abs(y[1]) > kHalfPi) return OffRollerEnd::How::collapse;
            const TwoBlockWall::Landing l = wall_.land(q_of(y), qdot_of(y), Guide::far);
            out.dissipated += l.dissipated;
            y[2] = l.qdot(0);
            y[3] = l.qdot(1);
            mode_ = Mode::far_guide;
            project(y);
            // Landed where the far guide would at once have to pull: the block rebounds into free flight.
            if (far_force(t, y) < 0.0) mode_ = Mode::free;
            break;
        }
        case Event::far_release: mode_ = Mode::free; break;
    }
    return std::nullopt;
}

}  // namespace

OffRollerEnd fly_off_roller(const VsswGeometry& w, const OffRollerStart& start, const OffRollerSetup& setup,
                            long& steps) {
    Flight flight(w, setup, start.side);
    return flight.run(start, steps);
}

}  // namespace vssw
