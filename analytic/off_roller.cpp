#include "off_roller.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

#include "bracket.hpp"

namespace vssw {
namespace {

using State = Vec<5>;  // theta1, theta2, theta1', theta2', work of the ground
enum class Mode { free, far_guide };
enum class Event { none, roller_landing, far_landing, far_release, base_impact, collapse };

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
    // The event functions: positive before the event.
    double event_value(Event ev, double t, const State& y) const {
        switch (ev) {
            case Event::roller_landing: return wall_.gap(q_of(y), Guide::roller);
            case Event::far_landing: return wall_.gap(q_of(y), Guide::far);
            case Event::far_release: return far_force(t, y);
            case Event::base_impact: return side_ * y[0];
            case Event::collapse: return s_.collapse_angle - side_ * y[0];
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
        const double stop = std::min(s_.next_breakpoint(t), s_.t_end);
        const double h = std::min(h_try, stop - t);
        const double err = integrator_.step(t, y, dy, h, step);
        bool finite = std::isfinite(err);
        for (double v : step.y1) finite = finite && std::isfinite(v);
        if (!finite || err > 1.0) {
            h_try = finite ? integrator_.next_step(h, err) : 0.25 * h;
            if (h_try <= s_.step.min_step)
                throw std::runtime_error(fmt::format("step size underflow at t = {} s with the top off the roller", t));
            continue;
        }
        h_try = integrator_.next_step(h, err);
        // The events this step crosses, each placed on the continuous extension; the earliest wins.
        // Free flight can land on either guide; on the far guide it can only be released from it.
        const std::array<Event, 4> candidates =
            mode_ == Mode::free
                ? std::array<Event, 4>{Event::base_impact, Event::collapse, Event::roller_landing, Event::far_landing}
                : std::array<Event, 4>{Event::base_impact, Event::collapse, Event::far_release, Event::none};
        Event first = Event::none;
        double first_time = t + h;
        for (Event ev : candidates) {
            if (ev == Event::none || event_value(ev, t + h, step.y1) > 0.0) continue;
            if (event_value(ev, t, y) <= 0.0) continue;  // already there at the start: not crossed in this step
            integrator_.make_dense(step);
            double lo = t, hi = t + h;
            shrink_bracket([&](double tau) { return event_value(ev, tau, step.at(tau)); }, lo, hi,
                           s_.event_time_tol);
            if (hi <= first_time) {
                first = ev;
                first_time = hi;
            }
        }
        if (s_.emit) {
            integrator_.make_dense(step);
            s_.emit(t, first_time, [&](double tau) { return step.at(tau); });
        }
        // Turning points of theta1 inside the step (before the event).
        if ((y[2] > 0.0) != (step.y1[2] > 0.0) && y[2] != 0.0) {
            integrator_.make_dense(step);
            double lo = t, hi = t + h;
            shrink_bracket([&](double tau) { return step.component_at(tau, 2); }, lo, hi, s_.event_time_tol);
            if (hi <= first_time) out.peaks.push_back({hi, step.component_at(hi, 0)});
        }
        if (first == Event::none) {
            t += h;
            y = step.y1;
            project(y);
        } else {
            t = first_time;
            y = step.at(first_time);
        }
        out.max_abs_theta = std::max(out.max_abs_theta, std::abs(y[0]));
        if (s_.check_energy) s_.check_energy(t, y, out.dissipated);
        switch (first) {
            case Event::none: break;
            case Event::collapse: return finish(OffRollerEnd::How::collapse);
            case Event::base_impact:
                if (mode_ == Mode::free)
                    throw std::runtime_error(fmt::format(
                        "at t = {} s theta1 reached 0 with the top off both guides (off the roller since t = {} s): "
                        "a base impact of the two-DOF wall, which the model does not describe",
                        t, start.t));
                y[0] = 0.0;
                return finish(OffRollerEnd::How::base_impact);
            case Event::roller_landing: {
                const TwoBlockWall::Landing l = wall_.land(q_of(y), qdot_of(y), Guide::roller);
                out.dissipated += l.dissipated;
                y[2] = l.theta1_dot;
                return finish(OffRollerEnd::How::on_roller);
            }
            case Event::far_landing: {
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
        dy = integrator_.rhs(std::nextafter(t, s_.t_end + 1.0), y);
        if (first != Event::none) h_try = std::min(h_try, kFirstFlightStep);
    }
    return finish(OffRollerEnd::How::end_time);
}

}  // namespace

OffRollerEnd fly_off_roller(const VsswGeometry& w, const OffRollerStart& start, const OffRollerSetup& setup,
                            long& steps) {
    Flight flight(w, setup, start.side);
    return flight.run(start, steps);
}

}  // namespace vssw
