#include "simulate.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>

#include "bracket.hpp"
#include "error.hpp"
#include "off_roller.hpp"
#include "support_monitor.hpp"

namespace vssw {
namespace {

using State = Vec<3>;  // theta1, theta1', work done by the ground motion

// Sub-intervals in which a step's continuous extension is searched for the first sign change of an event function
// (the first step after an impact is capped to the predicted flight, so its first point is still in flight).
constexpr int kScanPoints = 4;
// Largest scan interval at rest for analytic ground motions (records are scanned sample by sample): 1 ms, and at most
// a thousandth of the signal's duration so that a short pulse's time above the threshold is not stepped over.
constexpr double kRestScanStep = 1e-3;  // [s]
constexpr double kRestScanFraction = 1e-3;
// [s] how closely the instant a vertical analytic signal cancels gravity is placed (it is only reported).
constexpr double kWeightlessTimeTol = 1e-12;
// Runs longer than this, or with more output samples, are refused as bad input rather than left to run for hours.
constexpr double kMaxEndTime = 1e7;      // [s]
// Samples reserved at the start of a run (2^21, 144 MiB of address space): a longer run's vector grows as it fills.
constexpr double kReservedSamples = 2097152.0;
constexpr int kMaxNewtonIterations = 8;
// After the top lands back on the roller the step restarts small: the motion has just changed mechanism.
constexpr double kFirstStepAfterLanding = 1e-4;  // [s]
// An event placed within this of a step's end is carried there by y + dh f(y), whose error (dh^2/2 |y''|, < 1e-16
// here) is far below the integration error, instead of by another step.
constexpr double kTaylorSpan = 1e-8;  // [s]
// A free flight's duration is predicted from the last two (FlightHistory) and aimed at only when the first- and
// second-order predictions agree within this: on Fig. 6 the second-order error was a tenth of their difference, so
// the aimed step lands within kTaylorSpan. A prediction that misses costs a step, never accuracy.
constexpr double kFlightPredictionAgreement = 10.0 * kTaylorSpan;  // [s]
// In a flight the symmetry cannot predict (the ground moves, or the flight did not start from theta1 = 0 with the
// ground still: a release, a flight after the top left the roller) the landing is predicted at each step's start
// from theta1, theta1' and theta1'' (the parabola through them, parabola_landing) and the step cut to end there when
// the landing falls inside it. A cut step that
// ends within kShortLandingSpan of the landing is carried there by classical Runge-Kutta steps, each aimed by the
// parabola again, until the gap is within kTaylorSpan (land_short): no search on the continuous extension and no
// re-step of the whole step (a record run's landings cost 27 right-hand sides each that way, 4 to 8 this way). Their
// error needs no estimate: over 1e-4 s the 4th-order local error, of order dt^5 |y^(5)| / 120, is about 1e-19 rad
// for the |y^(5)| of a rocking wall (some 1e3 rad/s^5 under a record), as long as no breakpoint of the ground motion
// lies in the span (a kink of the record's slope would leave an error of order dt^2): such landings are searched.
constexpr double kShortLandingSpan = 1e-4;  // [s]
// The parabola's error after a step of d is of order |theta1''' / theta1'| d^3: from 1e-4 s the second gap is below
// 1e-9 s, the third within kTaylorSpan; a landing not reached in this many steps is searched instead.
constexpr int kMaxShortLandingSteps = 4;

// Time to the landing, u = side theta1 = 0 coming down, along u + u' d + u'' d^2 / 2 from u >= 0 (or u < 0 just past
// it, moving down: then negative, the landing behind), in forms without cancellation; infinity when the parabola
// does not come down to zero (it turns first, or rises for ever).
double parabola_landing(double u, double u_dot, double u_ddot) {
    const double disc = u_dot * u_dot - 2.0 * u_ddot * u;
    if (!(disc >= 0.0)) return std::numeric_limits<double>::infinity();
    if (u_dot < 0.0) return 2.0 * u / (-u_dot + std::sqrt(disc));  // moving down: the first root
    if (u_ddot < 0.0) return (u_dot + std::sqrt(disc)) / -u_ddot;    // rising: down again after the turn
    return std::numeric_limits<double>::infinity();
}

// Durations and launch speeds of the last two free flights (from theta1 = 0, the ground at rest). In the limit of
// small flights the duration is proportional to the launch speed (2|v|/a); the ratio duration/speed drifts slowly
// with the amplitude, and its drift from one flight to the next predicts the next one.
struct FlightHistory {
    double duration[2] = {0.0, 0.0}, speed[2] = {0.0, 0.0};  // [1]: the latest
    int known = 0;

    void add(double t, double v) {
        duration[0] = duration[1];
        speed[0] = speed[1];
        duration[1] = t;
        speed[1] = v;
        known = std::min(known + 1, 2);
    }
    // The next flight's duration from its launch speed, or infinity when the two predictions disagree.
    double predict(double v) const {
        if (known < 2) return std::numeric_limits<double>::infinity();
        const double first = duration[1] * v / speed[1];
        const double second = first * (duration[1] / speed[1]) / (duration[0] / speed[0]);
        return std::abs(second - first) < kFlightPredictionAgreement ? second
                                                                     : std::numeric_limits<double>::infinity();
    }
};

enum class Event { none, impact, collapse };

// A ground motion read at the integrator's stages: the twelve stages of a step under a record fall in one sample
// interval, so the interval's line is kept and the record looked up only when a time leaves it (the lookup was 10 %
// of a record run's instructions, callgrind). Values equal GroundMotion::operator() to rounding.
class MotionAtStages {
public:
    explicit MotionAtStages(const GroundMotion& m) : m_(m) {}
    double operator()(double t) const {
        if (!(t >= piece_.start && t <= piece_.end)) {
            const std::optional<GroundMotion::LinearPiece> p = m_.linear_piece(t);
            if (!p) return m_(t);  // an analytic signal, or outside the record's samples
            piece_ = *p;
        }
        return piece_.value + piece_.slope * (t - piece_.start);
    }

private:
    const GroundMotion& m_;
    mutable GroundMotion::LinearPiece piece_{1.0, 0.0, 0.0, 0.0};  // empty until the first lookup
};

class Simulator {
public:
    Simulator(const RockingModel& model, const GroundMotion& ah, const GroundMotion& av, const SimulationOptions& o)
        : model_(model),
          ah_(ah),
          av_(av),
          ah_stages_(ah),
          av_stages_(av),
          opt_(o),
          rest_terms_(model.terms(0.0)),
          e_(model.restitution()),
          g_(model.gravity()),
          N_(model.overburden()),
          alpha_(model.reference_angle()),
          collapse_(model.collapse_angle()),
          // |V_r|: V_r is negative for a wall whose overburden puts alpha1 past its unstable equilibrium.
          v_ref_(std::abs(model.reference_energy())),
          motion_end_(std::max(ah.duration(), av.duration())),
          rest_scan_step_(std::min(scan_step(ah), scan_step(av))),
          integrator_(Rhs{this}, o.step, State{alpha_, model.reference_velocity(), v_ref_}),
          supports_(model) {}

    SimulationResult run(InitialState init);

private:
    // An analytic, non-zero signal can cross the threshold between its breakpoints: scan it finely. Records are
    // linear between samples (their breakpoints), so the sample grid is scan enough.
    static double scan_step(const GroundMotion& m) {
        if (m.is_zero() || !m.sample_times().empty()) return std::numeric_limits<double>::infinity();
        return std::min(kRestScanStep, kRestScanFraction * m.duration());
    }

    struct Rhs {
        const Simulator* sim;
        State operator()(double t, const State& y) const { return sim->derivative(t, y); }
    };

    // Most runs have no vertical motion: not evaluated then (two calls per stage otherwise).
    double vertical_at_stage(double t) const { return av_.is_zero() ? 0.0 : av_stages_(t); }

    State derivative(double t, const State& y) const {
        // q = side theta1 by a branch, not a product: the branch is the same through a flight, the product would sit on
        // every stage's chain of dependent operations.
        const double q = side_ > 0 ? y[0] : -y[0];
        const RockingRates r = model_.rates(side_, q, y[1], ah_stages_(t), vertical_at_stage(t));
        return {y[1], r.acceleration, r.ground_force * y[1]};
    }

    // Net tipping acceleration margin at rest on the side the ground pushes towards (> 0: the wall lifts off).
    double tipping_margin(double t) const {
        const double a_h = ah_(t), a_v = av_(t);
        const ModelTerms& r = rest_terms_;
        return std::abs(a_h) * r.X - ((g_ + a_v) * r.Y + N_ * r.L);
    }

    double next_breakpoint(double t) const {
        double next = opt_.t_end;
        const double after = t + 1e-12 * std::max(1.0, std::abs(t));
        for (int c = 0; c < 2; ++c) {
            const auto& bp = (c == 0 ? ah_ : av_).breakpoints();
            // The first breakpoint past `after`. Runs move forward, so the last answer's neighbourhood is checked
            // before a binary search over a record's thousands of samples.
            // The hint i is an index in [0, bp.size()] (bp.size(): none left), as set here.
            std::size_t& i = breakpoint_hint_[c];
            const bool hint_is_first = (i == bp.size() || bp[i] > after) && (i == 0 || bp[i - 1] <= after);
            if (!hint_is_first) {
                const bool next_is_first = i < bp.size() && bp[i] <= after && (i + 1 == bp.size() || bp[i + 1] > after);
                if (next_is_first)
                    ++i;
                else
                    i = static_cast<std::size_t>(std::upper_bound(bp.begin(), bp.end(), after) - bp.begin());
            }
            if (i != bp.size()) next = std::min(next, bp[i]);
        }
        return next;
    }

    void emit(double t, const State& y) {
        if (!opt_.keep_samples) return;
        if (!opt_.sample_energies) {
            out_.samples.push_back(sample_without_energies(t, y[0], y[1], y[2]));
            return;
        }
        out_.samples.push_back({t, y[0], y[1], model_.kinetic(y[0], y[1]), model_.weight_potential(y[0]),
                                model_.overburden_work(y[0]), y[2], dissipated_, ah_(t)});
    }
    // A sample when no energies are asked for (sample_energies off): they are NaN, not zeros or stale values.
    Sample sample_without_energies(double t, double theta, double theta_dot, double work_ground) const {
        constexpr double kNotComputed = std::numeric_limits<double>::quiet_NaN();
        return {t, theta, theta_dot, kNotComputed, kNotComputed, kNotComputed, work_ground, dissipated_, ah_(t)};
    }

    // Energy balance at time t; throws EnergyBalanceFailure as soon as the error passes the ceiling.
    void check_balance(double t, const State& y) {
        if (off_mechanism_) return;  // the run ended off the roller: the flight checked its own (two-DOF) balance
        if (y[0] == 0.0) {
            // At theta1 = 0 (every impact) both potentials are zero and the mass is M(0): the same numbers as the
            // model's functions give there, without their trigonometry (3 % of a record run, perf).
            check_energies(t, 0.0, 0.5 * rest_terms_.M * (y[1] * y[1]), 0.0, 0.0, y[2], 0.0);
            return;
        }
        check_energies(t, std::abs(y[0]), model_.kinetic(y[0], y[1]), model_.weight_potential(y[0]),
                       model_.overburden_work(y[0]), y[2], 0.0);
    }
    // The balance from its terms [J/m]; `extra_dissipated`: dissipated beyond dissipated_ (a flight's landings so
    // far). Throws EnergyBalanceFailure as soon as the error passes the ceiling.
    void check_energies(double t, double abs_theta, double kinetic, double potential, double work_n,
                        double work_ground, double extra_dissipated) {
        const double dissipated = dissipated_ + extra_dissipated;
        const double residual = kinetic + potential - work_n - work_ground + dissipated - initial_energy_;
        energy_scale_ = std::max(energy_scale_, std::abs(kinetic) + std::abs(potential) + std::abs(work_n) +
                                                    std::abs(work_ground) + dissipated);
        max_residual_ = std::max(max_residual_, std::abs(residual));
        out_.energy_balance_error = max_residual_ / energy_scale_;
        if (!(out_.energy_balance_error <= opt_.energy_ceiling))  // NaN fails too
            throw EnergyBalanceFailure(fmt::format(
                "the energy balance error reached {:.3g} of the largest energy in play at t = {:.6g} s (|theta1| = "
                "{:.6g} rad), above the ceiling {:.3g}: the run is not a result (a tighter --rtol may help)",
                out_.energy_balance_error, t, abs_theta, opt_.energy_ceiling));
    }

    // Samples on the output grid in (t0, t1], from a function giving the state at any time in the interval.
    template <class StateAt>
    void emit_grid(double t0, double t1, StateAt state_at) {
        for_output_times(t0, t1, [&](double t) { emit(t, state_at(t)); });
    }
    // Calls f at each time of the output grid in (t0, t1] (nothing when no trajectory is kept).
    template <class F>
    void for_output_times(double t0, double t1, F f) {
        if (!opt_.keep_samples || opt_.output_dt <= 0.0) return;
        while (next_output_ <= t1 + 1e-12) {
            if (next_output_ > t0 - 1e-12) f(next_output_);
            ++output_index_;
            next_output_ = static_cast<double>(output_index_) * opt_.output_dt;
        }
    }

    // Records the supports' forces at (t, y) on the current side (a VSSW only).
    void record_supports(double t, const State& y, double theta_ddot) {
        if (!monitoring()) return;
        // The ground motion read as the stages read it (the record's current line, no search: 3 % of a record run).
        last_roller_ = supports_.record(t, side_, y[0], y[1], theta_ddot, ah_stages_(t), vertical_at_stage(t),
                                        out_.supports);
    }
    // The roller's reaction at time tau inside an accepted step (its continuous extension built).
    double roller_at(const RkStep<3>& step, double tau) const {
        const State s = step.at(tau);
        const double a_h = ah_(tau), a_v = av_(tau);
        const double acc = rocking_rates(model_.terms(side_ * s[0]), side_, s[1], a_h, a_v, g_, N_).acceleration;
        return supports_.reactions(side_, s[0], s[1], acc, a_h, a_v).roller;
    }
    bool unilateral() const { return opt_.roller == Roller::unilateral && supports_.active(); }
    // The supports are followed when asked for, and always under a unilateral roller (its departures need them).
    bool monitoring() const { return supports_.active() && (opt_.monitor_supports || unilateral()); }
    // The top leaves the roller at (t, y): flies off it (off_roller.hpp) until it lands back (nothing returned: the
    // one-DOF motion goes on from the updated t, y), or a base impact, overturning or the end ends the flight.
    std::optional<Event> leave_roller(double& t, State& y);
    bool rest_phase(double& t, State& y);
    Event rocking_phase(double& t, State& y);
    void polish_event(Event ev, double t, const State& y, const State& dy, double h, RkStep<3>& step) const;
    bool may_turn(const RkStep<3>& step) const;
    std::optional<double> land_short(double t, State y, State dy, double limit, State& landing,
                                     State& landing_dy) const;

    const RockingModel& model_;
    const GroundMotion& ah_;
    const GroundMotion& av_;
    MotionAtStages ah_stages_, av_stages_;  // the same motions, as the right-hand side reads them
    SimulationOptions opt_;
    ModelTerms rest_terms_;
    double e_, g_, N_, alpha_, collapse_, v_ref_, motion_end_, rest_scan_step_;  // the model's constants, read once
    Dop853<3, Rhs> integrator_;
    SupportMonitor supports_;
    double last_roller_ = 0.0;  // the roller's reaction at the last recorded state
    bool off_mechanism_ = false;  // the run ended with the top off the roller (its state is not the one-DOF model's)

    int side_ = 1;
    double dissipated_ = 0.0;
    double initial_energy_ = 0.0;
    double energy_scale_ = 0.0;  // set to V_r on construction; grows with the energies met
    double max_residual_ = 0.0;
    double next_output_ = 0.0;
    long output_index_ = 0;
    double h_ = 1e-3;
    FlightHistory flights_;  // the last free flights, to predict the next one's end
    mutable std::size_t breakpoint_hint_[2] = {0, 0};  // next_breakpoint's last answers (horizontal, vertical)
    SimulationResult out_;
};

std::optional<Event> Simulator::leave_roller(double& t, State& y) {
    const TwoBlockWall& blocks = supports_.wall(side_);
    OffRollerSetup setup;
    setup.horizontal = &ah_;
    setup.vertical = &av_;
    setup.step = opt_.step;
    setup.t_end = opt_.t_end;
    setup.collapse_angle = collapse_;
    setup.event_time_tol = opt_.event_time_tol;
    setup.max_steps = kMaxIntegrationSteps;
    setup.next_breakpoint = [this](double x) { return next_breakpoint(x); };
    // Samples of the flight carry its own (two-DOF) energies; none asked for, the flight builds no dense output.
    if (opt_.keep_samples && opt_.output_dt > 0.0)
        setup.emit = [&](double t0, double t1, const std::function<Vec<5>(double)>& at) {
        for_output_times(t0, t1, [&](double tau) {
            const Vec<5> z = at(tau);
            if (!opt_.sample_energies) {
                out_.samples.push_back(sample_without_energies(tau, z[0], z[2], z[4]));
                return;
            }
            const Vec2 q(z[0], z[1]), qd(z[2], z[3]);
            out_.samples.push_back({tau, z[0], z[2], blocks.kinetic(q, qd), blocks.weight_potential(q),
                                    blocks.overburden_work(q), z[4], dissipated_, ah_(tau)});
        });
    };
    setup.check_energy = [&](double at, const Vec<5>& z, double flight_dissipated) {
        const Vec2 q(z[0], z[1]), qd(z[2], z[3]);
        check_energies(at, std::abs(z[0]), blocks.kinetic(q, qd), blocks.weight_potential(q),
                       blocks.overburden_work(q), z[4], flight_dissipated);
    };
    const OffRollerEnd e =
        fly_off_roller(*model_.vssw_geometry(), {t, y[0], y[1], y[2], side_}, setup, out_.steps);
    ++out_.supports.roller_departures;
    out_.supports.time_off_roller += e.t - t;
    dissipated_ += e.dissipated;
    for (const TurningPoint& p : e.peaks) out_.peaks.push_back(p);
    out_.max_abs_theta = std::max(out_.max_abs_theta, e.max_abs_theta);
    t = e.t;
    y = {e.theta1, e.theta1_dot, e.work_ground};
    switch (e.how) {
        case OffRollerEnd::How::on_roller: check_balance(t, y); return std::nullopt;
        case OffRollerEnd::How::base_impact: return Event::impact;  // on the far guide at theta1 = 0: one-DOF again
        case OffRollerEnd::How::collapse: off_mechanism_ = true; return Event::collapse;
        case OffRollerEnd::How::end_time: off_mechanism_ = true; break;
    }
    return Event::none;
}

// Waits at rest from t; returns true with t at the lift-off time and side_ set, or false when the run is over.
bool Simulator::rest_phase(double& t, State& y) {
    y[0] = 0.0;
    y[1] = 0.0;
    const double rest_start = t;
    auto rest_state = [&](double) { return y; };
    auto lift = [&](double when) {
        emit_grid(rest_start, when, rest_state);
        t = when;
        side_ = ah_(when) > 0.0 ? -1 : 1;  // the wall's inertia pushes it against the ground acceleration
        out_.lift_offs.push_back(when);
        return true;
    };
    // The ground motion is left-continuous at its breakpoints: where it drops at a breakpoint (a cosine pulse's end),
    // a margin positive at that instant alone tips nothing. The wall lifts only where the margin is positive just
    // after the instant too.
    auto tips_from = [&](double when) {
        return tipping_margin(when) > 0.0 && tipping_margin(std::nextafter(when, opt_.t_end + 1.0)) > 0.0;
    };
    if (tips_from(t)) return lift(t);
    double scan = t;
    while (scan < opt_.t_end) {
        if (scan >= motion_end_) {  // no more ground motion: nothing can lift the wall again
            const double end = opt_.stop_at_rest ? std::max(scan, rest_start) : opt_.t_end;
            emit_grid(rest_start, end, rest_state);
            t = end;
            return false;
        }
        double next = std::min({next_breakpoint(scan), opt_.t_end, motion_end_});
        // An analytic signal's extrema too: between them and the breakpoints |a_h| is largest at an end, so no
        // excursion past the threshold falls between two looks (a 2 ms harmonic looked at every 1 ms saw its zeros).
        // With a vertical motion that varies too this holds for records (both linear between the union of their
        // samples, where the margin |a_h| X - (g + a_v) Y is convex), not for an analytic vertical signal, which can
        // rise with a_h and peak between looks (the command line offers vertical records only).
        next = std::min({next, scan + rest_scan_step_, ah_.next_extremum(scan), av_.next_extremum(scan)});
        if (tipping_margin(next) > 0.0) {
            // Narrow to the crossing, keeping the right end, where the margin is positive, so the flight starts.
            double lo = scan, hi = next;
            // A margin of exactly 0 counts as below: the bracket's right end then always lifts, and the search does
            // not stop on a run of exact zeros (near the threshold they span many ulps: a lift-off 1.01 times above it
            // started 0.6 ms late).
            shrink_bracket(
                [&](double x) {
                    const double m = tipping_margin(x);
                    return m > 0.0 ? m : std::min(m, -std::numeric_limits<double>::denorm_min());
                },
                lo, hi, opt_.event_time_tol);
            // hi only ever moves to where the margin is positive: the first instant found that lifts.
            if (tips_from(hi)) return lift(hi);
        }
        scan = next;
    }
    emit_grid(rest_start, opt_.t_end, rest_state);
    t = opt_.t_end;
    return false;
}

// Refines an event found on the continuous extension so that it lies on the integrator's own solution, not on its
// interpolant: Newton on the real step size. Once the correction dh is below kTaylorSpan, the last step's end is
// carried to the event by y + dh f(y): one step per event instead of two. Leaves the final state in `step`.
void Simulator::polish_event(Event ev, double t, const State& y, const State& dy, double h, RkStep<3>& step) const {
    for (int i = 0; i < kMaxNewtonIterations; ++i) {
        integrator_.step(t, y, dy, h, step);
        const double g = ev == Event::impact ? side_ * step.y1[0] : collapse_ - side_ * step.y1[0];
        const double slope = ev == Event::impact ? side_ * step.y1[1] : -side_ * step.y1[1];
        if (slope == 0.0) return;
        const double dh = -g / slope;
        if (std::abs(dh) < kTaylorSpan && std::abs(dh) < 0.5 * h) {
            const State& f = step.end_derivative();
            for (std::size_t n = 0; n < 3; ++n) step.y1[n] += dh * f[n];
            step.h = h + dh;
            return;
        }
        h = std::clamp(h + dh, 0.5 * h, 2.0 * h);
    }
}

// From (t, y) within kShortLandingSpan of a landing, with dy = f(t, y): classical Runge-Kutta steps, each aimed at
// the parabola's landing, until the gap is within kTaylorSpan, then y + dh f(y) as after a cut step. Returns the
// impact time with its state and that state's derivative in `landing` and `landing_dy` (from within kTaylorSpan of
// it), or nothing when a step would reach `limit` (the ground motion's next breakpoint) or the landing is not reached
// in kMaxShortLandingSteps: the caller then searches for it.
std::optional<double> Simulator::land_short(double t, State y, State dy, double limit, State& landing,
                                            State& landing_dy) const {
    for (int i = 0; i < kMaxShortLandingSteps; ++i) {
        const double d = parabola_landing(side_ * y[0], side_ * y[1], side_ * dy[1]);
        if (!(std::abs(d) < kShortLandingSpan) || t + d >= limit) return std::nullopt;
        if (std::abs(d) < kTaylorSpan) {
            for (std::size_t n = 0; n < 3; ++n) landing[n] = y[n] + d * dy[n];
            landing_dy = dy;
            return t + d;
        }
        State z{};
        for (std::size_t n = 0; n < 3; ++n) z[n] = y[n] + 0.5 * d * dy[n];
        const State k2 = integrator_.rhs(t + 0.5 * d, z);
        for (std::size_t n = 0; n < 3; ++n) z[n] = y[n] + 0.5 * d * k2[n];
        const State k3 = integrator_.rhs(t + 0.5 * d, z);
        for (std::size_t n = 0; n < 3; ++n) z[n] = y[n] + d * k3[n];
        const State k4 = integrator_.rhs(t + d, z);
        for (std::size_t n = 0; n < 3; ++n) y[n] += d / 6.0 * (dy[n] + 2.0 * (k2[n] + k3[n]) + k4[n]);
        t += d;
        dy = integrator_.rhs(t, y);
    }
    return std::nullopt;
}

// Could theta1' change sign inside the step? Checked on the cubic Hermite interpolant of theta1' built from its values
// and slopes at the two ends (no extra evaluation), at the ends and three interior points.
bool Simulator::may_turn(const RkStep<3>& step) const {
    const double v0 = step.y0[1], v1 = step.y1[1];
    const double a0 = step.k[0][1] * step.h, a1 = step.end_derivative()[1] * step.h;
    double prev = v0;
    for (double x : {0.25, 0.5, 0.75, 1.0}) {
        const double x2 = x * x, x3 = x2 * x;
        const double v = (2 * x3 - 3 * x2 + 1) * v0 + (x3 - 2 * x2 + x) * a0 + (-2 * x3 + 3 * x2) * v1 + (x3 - x2) * a1;
        if (prev != 0.0 && (v == 0.0 || (v > 0.0) != (prev > 0.0))) return true;
        prev = v;
    }
    return false;
}

Event Simulator::rocking_phase(double& t, State& y) {
    State dy = integrator_.rhs(t, y);
    RkStep<3> step, event_step;
    bool starts_at_zero = y[0] == 0.0;
    if (starts_at_zero && y[1] != 0.0) {
        // Cap the first step to 1.5 times the flight 2|v|/|a| predicted with the restoring acceleration at rest: the
        // real flight is longer (restoring moments fall as |theta1| grows), so the scan's first point (3/8 of the
        // flight) is still in the air, while a short flight usually ends inside this one step. Within a step the
        // side is fixed and the right-hand side smooth through theta1 = 0, so a step may overshoot the landing. (When
        // the parabola predicts the landing, the step is aimed at it instead: the flight itself, kShortLandingSpan.)
        const double a = std::abs(dy[1]);
        if (a > 0.0) h_ = std::min(h_, 3.0 * std::abs(y[1]) / a);
    }
    record_supports(t, y, dy[1]);
    // A flight from theta1 = 0 with the ground at rest is symmetric in time about its turning point (the equation of
    // motion is even in theta1' and has no time in it once the ground is still): it lands at 2 t_turn - t_launch.
    // The step that reaches that time is cut to end there, and when it lands within kTaylorSpan the impact is placed
    // by y + dh f(y) instead of by the search on the continuous extension and a re-step (a quarter of a free
    // vibration's right-hand sides). A prediction only: a step that does not land there goes on as any other. In the
    // other flights the parabola predicts instead (kShortLandingSpan).
    const double launch = t, launch_speed = std::abs(y[1]);
    bool symmetric = starts_at_zero && y[1] != 0.0 && t >= motion_end_;
    if (!symmetric) flights_ = FlightHistory{};
    // Before its turning point is known, the flight's end is predicted from the last two (FlightHistory).
    double aim = symmetric && opt_.predict_landings ? launch + flights_.predict(launch_speed)
                                                    : std::numeric_limits<double>::infinity();
    while (t < opt_.t_end) {
        if (unilateral() && last_roller_ < 0.0) {  // the roller cannot pull: the top leaves it
            symmetric = false;  // the flight goes on in another mechanism
            flights_ = FlightHistory{};
            aim = std::numeric_limits<double>::infinity();
            if (const std::optional<Event> ended = leave_roller(t, y)) return *ended;
            dy = integrator_.rhs(t, y);
            h_ = std::min(h_, kFirstStepAfterLanding);
            starts_at_zero = false;
            record_supports(t, y, dy[1]);
            // Landed where the roller must pull at once: rather than leave again with no time between, the next
            // one-DOF step is taken and the top leaves at its end (one step on a pulling roller).
            if (last_roller_ < 0.0) last_roller_ = 0.0;
            continue;
        }
        if (++out_.steps > kMaxIntegrationSteps) throw std::runtime_error("integration exceeded the step limit");
        const double breakpoint = next_breakpoint(t);
        if (!symmetric && opt_.predict_landings) {  // the ground moves: aim at the parabola's landing in this step
            aim = std::numeric_limits<double>::infinity();
            if (side_ * y[0] >= 0.0) {
                const double d = parabola_landing(side_ * y[0], side_ * y[1], side_ * dy[1]);
                if (d > 0.0 && d < h_ && t + d < breakpoint) aim = t + d;
            }
        }
        const double stop = std::min({breakpoint, opt_.t_end, aim > t ? aim : opt_.t_end});
        double h = std::min(h_, stop - t);
        const bool to_aim = stop == aim && h == stop - t;
        const double err = integrator_.step(t, y, dy, h, step);
        // A trial step that blew up (non-finite state or error) is rejected like any other, with a quarter step.
        const bool finite = std::isfinite(step.y1[0]) && std::isfinite(step.y1[1]) && std::isfinite(err);
        if (!finite || (err > 1.0 && !integrator_.fixed_step())) {
            ++out_.rejected_steps;
            h_ = finite ? integrator_.next_step(h, err) : 0.25 * h;
            if (h_ <= opt_.step.min_step)
                throw std::runtime_error(fmt::format("step size underflow at t = {} s (state {}, {})", t, y[0], y[1]));
            continue;
        }
        const double h_next = integrator_.next_step(h, err);

        // Events show at the step's end: the wall cannot cross theta1 = 0 and come back within one flight.
        Event ev = Event::none;
        if (side_ * step.y1[0] <= 0.0) ev = Event::impact;
        else if (side_ * step.y1[0] >= collapse_) ev = Event::collapse;
        double landing_dh = 0.0;  // the Taylor step to the landing from a step that ended at the aim
        bool landed = false;
        std::optional<double> short_landing;  // the impact time reached by land_short from the aimed step's end
        State landing{}, landing_dy{};        // and the state there, with its derivative
        if (to_aim) {
            aim = std::numeric_limits<double>::infinity();
            const double slope = side_ * step.y1[1];
            if (slope < 0.0) {
                landing_dh = -side_ * step.y1[0] / slope;
                landed = std::abs(landing_dh) < kTaylorSpan;
                if (!landed && !symmetric && std::abs(landing_dh) < kShortLandingSpan)
                    short_landing =
                        land_short(t + h, step.y1, step.end_derivative(), breakpoint, landing, landing_dy);
            }
            if (landed || short_landing) ev = Event::impact;
        }
        const bool turns = may_turn(step);
        // Where the step's motion ends: a landing placed from it (up to kShortLandingSpan past its end; the output
        // times in between are read off the continuous extension just past the step), else the step's end (a search
        // below may move it back).
        double event_time = short_landing ? *short_landing : landed ? t + h + landing_dh : t + h;
        const bool outputs = opt_.keep_samples && opt_.output_dt > 0.0 && next_output_ <= event_time + 1e-12;
        const bool search = ev != Event::none && !landed && !short_landing;
        if (search || turns || outputs) integrator_.make_dense(step);
        if (search) {
            // The first sub-interval of the continuous extension where the event function changes sign.
            double lo = t, hi = t + h;
            double prev = starts_at_zero ? 1.0 : (ev == Event::impact ? side_ * y[0] : collapse_ - side_ * y[0]);
            int first_change = 0;
            for (int k = 1; k <= kScanPoints; ++k) {
                const double tau = t + h * k / kScanPoints;
                const double th = k == kScanPoints ? step.y1[0] : step.component_at(tau, 0);
                const double g = ev == Event::impact ? side_ * th : collapse_ - side_ * th;
                if (prev > 0.0 && g <= 0.0) {
                    lo = tau - h / kScanPoints;
                    hi = tau;
                    first_change = k;
                    break;
                }
                prev = g;
            }
            // A flight from theta1 = 0 that is over before the scan's first point leaves no point in the air to
            // bracket from (the bracket would close onto the start): retry with a quarter step until one is seen.
            if (starts_at_zero && first_change == 1) {
                ++out_.rejected_steps;
                h_ = 0.25 * h;
                if (h_ <= opt_.step.min_step)
                    throw std::runtime_error(fmt::format("a flight from rest at t = {} s is shorter than the "
                                                         "smallest step",
                                                         t));
                continue;
            }
            ++out_.searched_events;
            shrink_bracket([&](double tau) {
                const double th = step.component_at(tau, 0);
                return ev == Event::impact ? side_ * th : collapse_ - side_ * th;
            }, lo, hi, opt_.event_time_tol);
            event_time = hi;
        }
        if (turns) {
            double tau_prev = t, v_prev = y[1];
            for (int k = 1; k <= kScanPoints; ++k) {
                const double tau = t + h * k / kScanPoints;
                if (tau_prev >= event_time) break;  // after the event: not part of this flight
                const double v = k == kScanPoints ? step.y1[1] : step.component_at(tau, 1);
                if (v_prev != 0.0 && (v == 0.0 || (v > 0.0) != (v_prev > 0.0))) {
                    double a = tau_prev, b = tau;
                    shrink_bracket([&](double x) { return step.component_at(x, 1); }, a, b, opt_.event_time_tol);
                    if (b <= event_time) {
                        const double th = step.component_at(b, 0);
                        out_.peaks.push_back({b, th});
                        out_.max_abs_theta = std::max(out_.max_abs_theta, std::abs(th));
                        if (symmetric && opt_.predict_landings && ev == Event::none) aim = 2.0 * b - launch;
                    }
                }
                tau_prev = tau;
                v_prev = v;
            }
        }
        if (outputs) emit_grid(t, event_time, [&](double tau) { return step.at(tau); });

        const bool on_breakpoint = ev == Event::none && t + h == stop;
        if (landed) {  // `step` stays the integrator's step (the roller's bracket below may read its extension)
            dy = step.end_derivative();
            for (std::size_t n = 0; n < 3; ++n) y[n] = step.y1[n] + landing_dh * dy[n];
            h += landing_dh;
        } else if (short_landing) {  // likewise
            y = landing;
            dy = landing_dy;
            h = event_time - t;
        } else if (ev != Event::none) {
            polish_event(ev, t, y, dy, event_time - t, event_step);
            h = event_step.h;
            y = event_step.y1;
            dy = event_step.end_derivative();
        } else {
            y = step.y1;
            dy = step.end_derivative();
        }
        const double roller_before = last_roller_;
        const bool first_tension = !out_.supports.roller_tension_at;
        t += h;
        h_ = h_next;
        starts_at_zero = false;
        record_supports(t, y, dy[1]);
        if (monitoring() && roller_before >= 0.0 && last_roller_ < 0.0 &&
            (first_tension || (unilateral() && ev == Event::none))) {
            // The roller turned tensile inside the step: place the moment on the continuous extension. (Past the
            // step's end, in a landing's last kShortLandingSpan, the landing's time stands for it.)
            if (!step.dense_ready) integrator_.make_dense(step);
            double lo = step.t0, hi = std::min(t, step.t0 + step.h);
            if (roller_at(step, hi) < 0.0)
                shrink_bracket([&](double tau) { return roller_at(step, tau); }, lo, hi, opt_.event_time_tol);
            else
                hi = t;
            if (first_tension) out_.supports.roller_tension_at = hi;
            if (unilateral() && ev == Event::none) {  // the top leaves the roller there, not at the step's end
                t = hi;
                y = step.at(hi);
            }
        }
        // A ground motion may jump at a breakpoint (a cosine pulse's end) and is left-continuous there: the next
        // step's first stage must see the value after the jump. Where both motions are continuous (a record's
        // interior samples: every breakpoint but its ends) the step's last stage is already that value, to rounding.
        if (on_breakpoint && !(ah_.continuous_at(t) && av_.continuous_at(t)))
            dy = integrator_.rhs(std::nextafter(t, opt_.t_end + 1.0), y);
        out_.max_abs_theta = std::max(out_.max_abs_theta, std::abs(y[0]));
        if (ev == Event::impact) y[0] = 0.0;
        if (opt_.keep_samples || ev != Event::none) check_balance(t, y);  // events always; every step when sampling
        if (opt_.output_dt <= 0.0) emit(t, y);
        if (ev == Event::impact && symmetric) flights_.add(t - launch, launch_speed);
        if (ev != Event::none) return ev;
    }
    return Event::none;
}

SimulationResult Simulator::run(InitialState init) {
    if (opt_.roller == Roller::unilateral && model_.vssw_geometry() && model_.kinematics() != Kinematics::exact)
        throw InputError("a unilateral roller needs the exact kinematics: the paper's Eq. (3) does not keep the top "
                         "corner on the roller's line, so the top can neither leave the roller nor land back on it");
    require(std::isfinite(init.theta), "initial rotation", "finite", init.theta);
    require(std::isfinite(init.theta_dot), "initial angular velocity", "finite", init.theta_dot);
    require(std::abs(init.theta) < collapse_, "|initial rotation| (rad)",
            fmt::format("below the collapse angle {} rad", collapse_), init.theta);
    validate(opt_);

    double t = 0.0;
    State y{init.theta, init.theta_dot, 0.0};
    initial_energy_ = model_.kinetic(y[0], y[1]) + model_.weight_potential(y[0]) - model_.overburden_work(y[0]);
    energy_scale_ = v_ref_;
    out_.max_abs_theta = std::abs(y[0]);
    out_.initial_abs_theta = std::abs(y[0]);
    // The output grid's size, up to kReservedSamples: the samples fill without reallocation and copying (they were
    // 9 % of `vssw check`'s instructions). Pages of a run that ends early are reserved, never touched.
    if (opt_.keep_samples && opt_.output_dt > 0.0)
        out_.samples.reserve(static_cast<std::size_t>(std::min(opt_.t_end / opt_.output_dt + 2.0, kReservedSamples)));
    emit_grid(-1.0, 0.0, [&](double) { return y; });
    if (opt_.output_dt <= 0.0) emit(t, y);

    bool rocking = y[0] != 0.0 || y[1] != 0.0;
    if (rocking) {
        side_ = y[0] != 0.0 ? (y[0] > 0.0 ? 1 : -1) : (y[1] > 0.0 ? 1 : -1);
        if (y[1] == 0.0) out_.peaks.push_back({0.0, y[0]});
    }
    while (t < opt_.t_end) {
        if (!rocking) {
            if (!rest_phase(t, y)) {
                out_.at_rest_at_end = true;
                break;
            }
            rocking = true;
            if (opt_.output_dt <= 0.0) emit(t, y);
        }
        const Event ev = rocking_phase(t, y);
        if (ev == Event::collapse) {
            out_.overturned = true;
            out_.t_overturn = t;
            break;
        }
        if (ev != Event::impact) break;  // end time reached

        const double v_before = y[1];
        const double m0 = rest_terms_.M;
        if (e_ <= 0.0) {  // a stocky wall whose impact stops it dead (Eq. 19 can be <= 0)
            out_.impacts.push_back({t, v_before, 0.0});
            dissipated_ += 0.5 * m0 * v_before * v_before;
            out_.rest_times.push_back(t);
            rocking = false;
            continue;
        }
        const double v_after = e_ * v_before;
        out_.impacts.push_back({t, v_before, v_after});
        dissipated_ += 0.5 * m0 * (v_before * v_before - v_after * v_after);
        side_ = -side_;
        y[1] = v_after;
        // Would the next flight be negligible while the ground cannot tip the wall? Then sum the geometric tail
        // of impacts (flight times 2|v| e^n / |a|) in closed form and come to rest.
        const double a_out = side_ * model_.acceleration(side_, 0.0, v_after, ah_(t), av_(t));
        if (a_out < 0.0 && v_after * v_after / (2.0 * -a_out) < opt_.rest_amplitude * alpha_) {
            const double tail = 2.0 * std::abs(v_after) / (-a_out * (1.0 - e_));
            dissipated_ += 0.5 * m0 * v_after * v_after;
            y[1] = 0.0;
            // The output grid during the tail: the wall is within rest_amplitude of rest, shown at rest.
            const double t_rest = std::min(t + tail, opt_.t_end);
            emit_grid(t, t_rest, [&](double) { return y; });
            t = t_rest;
            out_.rest_times.push_back(t);
            check_balance(t, y);
            if (opt_.output_dt <= 0.0) emit(t, y);
            rocking = false;
        }
    }
    check_balance(t, y);
    out_.t_final = t;
    return out_;
}

}  // namespace

Roller parse_roller(const std::string& text) {
    if (text == "bilateral") return Roller::bilateral;
    if (text == "unilateral") return Roller::unilateral;
    throw InputError("roller must be 'bilateral' or 'unilateral', got '" + text + "'");
}

const char* to_string(Roller roller) { return roller == Roller::bilateral ? "bilateral" : "unilateral"; }

LargestRotation largest_rotation(const SimulationResult& r) {
    if (r.overturned) return {r.max_abs_theta, r.t_overturn};
    LargestRotation peak{r.initial_abs_theta, 0.0};  // the start counts, moving or not
    for (const TurningPoint& p : r.peaks)
        if (std::abs(p.theta) > peak.abs_theta) peak = {std::abs(p.theta), p.t};
    // A step's end near a turning point can read above it by rounding (the points are located to rtol 1e-10): only
    // more than that is a swing still rising when the run ended.
    constexpr double kPastEveryPeak = 1e-8;
    if (r.max_abs_theta > peak.abs_theta * (1.0 + kPastEveryPeak)) return {r.max_abs_theta, r.t_final};
    return peak;
}

void validate(const SimulationOptions& options) {
    require(std::isfinite(options.t_end) && options.t_end > 0.0 && options.t_end <= kMaxEndTime, "end time (s)",
            fmt::format("positive and at most {:g} s", kMaxEndTime), options.t_end);
    // Tighter than ~1e-15 the error estimate is round-off; looser than 1e-2 the events are not worth locating.
    require(options.step.rtol >= 1e-15 && options.step.rtol <= 1e-2, "relative tolerance", "in [1e-15, 1e-2]",
            options.step.rtol);
    require(options.energy_ceiling > 0.0 && options.energy_ceiling < 1.0, "energy balance ceiling", "in (0, 1)",
            options.energy_ceiling);
    require(std::isfinite(options.output_dt) && options.output_dt >= 0.0, "output interval", "a finite number >= 0",
            options.output_dt);
    const bool bounded_output =
        options.output_dt == 0.0 || !options.keep_samples || options.t_end / options.output_dt <= kMaxOutputSamples;
    require(bounded_output, "output interval (s)",
            fmt::format("at least end time / {:g} = {:g} s", kMaxOutputSamples, options.t_end / kMaxOutputSamples),
            options.output_dt);
}

namespace {

// The first instant in [0, t_end] where g + a_v(t) <= 0. A record is linear between its samples, so its least value
// is at a sample; an analytic signal's at an extremum or a breakpoint (AnalyticShape); and the run's end counts too
// (a run that ends, overturned, between two of those).
std::optional<double> first_weightless(const GroundMotion& vertical, double g, double t_end) {
    if (vertical.is_zero() || vertical.pga() < g) return std::nullopt;
    auto weightless = [&](double t) { return g + vertical(t) <= 0.0; };
    std::vector<double> instants;
    if (!vertical.sample_times().empty()) {
        instants = vertical.sample_times();
    } else {
        instants = vertical.breakpoints();
        const double last = std::min(t_end, vertical.duration());
        for (double t = vertical.next_extremum(0.0); t <= last; t = vertical.next_extremum(t)) instants.push_back(t);
    }
    instants.push_back(t_end);
    std::sort(instants.begin(), instants.end());
    for (std::size_t i = 0; i < instants.size() && instants[i] <= t_end; ++i) {
        if (!weightless(instants[i])) continue;
        if (i == 0) return instants[i];
        // Monotone between two looks (linear between a record's samples): the crossing by bisection.
        double lo = instants[i - 1], hi = instants[i];
        shrink_bracket([&](double x) { return g + vertical(x); }, lo, hi, kWeightlessTimeTol);
        return weightless(hi) ? hi : instants[i];
    }
    return std::nullopt;
}

}  // namespace

SimulationResult simulate(const RockingModel& model, const GroundMotion& horizontal, const GroundMotion& vertical,
                          InitialState initial, const SimulationOptions& options) {
    Simulator sim(model, horizontal, vertical, options);
    SimulationResult r = sim.run(initial);
    r.weightless_at = first_weightless(vertical, model.gravity(), r.t_final);
    return r;
}

SimulationResult free_vibration(const RockingModel& model, double theta0, SimulationOptions options) {
    require(theta0 != 0.0, "initial rotation of a free vibration", "non-zero", theta0);
    const int side = theta0 < 0.0 ? -1 : 1;
    // theta1'' at an equilibrium is the round-off of an O(1) cancellation: compared with the pull at theta0 / 2.
    if (std::abs(theta0) < model.collapse_angle() &&
        std::abs(model.acceleration(side, theta0, 0.0, 0.0, 0.0)) <=
            1e-12 * std::abs(model.acceleration(side, 0.5 * theta0, 0.0, 0.0, 0.0)))
        throw InputError(fmt::format("initial rotation {} rad is an equilibrium of the {} model: released there the "
                                     "wall would neither rock nor fall",
                                     theta0, model.name()));
    options.stop_at_rest = true;
    if (options.t_end == SimulationOptions{}.t_end) options.t_end = 1e4;  // stops at rest long before
    const GroundMotion none = GroundMotion::none();
    return simulate(model, none, none, {theta0, 0.0}, options);
}

}  // namespace vssw
