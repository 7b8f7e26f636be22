#include "simulate.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <iterator>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "bracket.hpp"
#include "error.hpp"
#include "landing_prediction.hpp"
#include "motion_at_stages.hpp"
#include "off_roller.hpp"
#include "support_monitor.hpp"

namespace vssw {
namespace {

using State = Vec<3>;  // theta1, theta1', work done by the ground motion

// The state on a step's continuous extension at tau, as a reader of its components (Simulator::guard).
auto on_extension(const RkStep<3>& step, double tau) {
    return [&step, tau](std::size_t i) { return step.component_at(tau, i); };
}

// Looks (bracket.hpp) at which a step's continuous extension is scanned for the first sign change of the flight's
// guards (the first step after an impact is capped to the predicted flight, so its first look is still in flight).
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
// The integrator's share of the energy balance error is at most this many times its relative tolerance: measured over
// the 26 shipped records at 0.3 g and 0.6 g on the Fig. 6 wall (exact kinematics, whole-mechanism impact, unilateral
// roller), 0.3 rtol at rtol 1e-6, 1.1 at 1e-7, 2.1 at 1e-8, 1.7 at 1e-9; up to 100 at the default 1e-10 (round-off).
constexpr double kBalanceErrorPerRtol = 100.0;
// A time that never comes: no landing predicted, no rest in sight.
constexpr double kNever = std::numeric_limits<double>::infinity();

// The events of the motion, a hybrid system (CVODE's root functions, Drake's guards and resets): in each mode a flow
// (rest_phase, rocking_phase, off_roller_phase) integrates until the first of the guards it watches crosses zero in its
// direction; the main loop (run) then asks the event's row for its reset, which returns the next mode. Modes: at rest,
// rocking on the roller (one DOF), off the roller (two DOF, a unilateral roller), over.
//   event            guard g(t, y)                      direction  reset (-> next mode)                      source
//   lift-off         the tipping margin at rest, |a_h|  rising     side against a_h, the flight starts     Eq. (12);
//                    X - (g + a_v) Y - N L                         (lift -> rocking)                       Eq. (17)
//   impact           side theta1                        falling    theta1'+ = e theta1'- on the other      Eq. (19) or
//                                                                  side, the rest guard asked (impact ->   the whole
//                                                                  rocking, or rest's reset)               mechanism's
//   turning point    theta1'                            either     a peak recorded (turn -> rocking)       Eq. (10)
//   overturning      collapse angle - side theta1       falling    the run ends (overturn -> over)         Eq. (26)
//   roller tension   minus the roller's reaction        rising     the first one recorded; a unilateral    Eq. (2)
//                                                                  roller lets the top go (leave ->
//                                                                  off roller)
//   rest             rest_amplitude alpha - the next    rising     the remaining impacts summed in closed  Eq. (19)'s
//                    flight's rise (rest_margin)                   form (settle -> at rest)                series
//   landing on the   the top corner's gap to the roller falling    plastic projection onto the one-DOF     Eq. (2)
//   roller           (off_roller.cpp's own table)                  mechanism (land -> rocking)
//   end              the end time - t (CVODE's tstop:   falling    the run ends (finish -> over)
//                    each flow stops there)
// Lift-off is watched at rest on the ground motion's own grid; rest at each impact (in impact's reset); impact,
// overturning, turning point and roller tension along every step of a flight (a predicted landing may place the
// impact instead: place_landing); landing on the roller, and its own impact and overturning, by off_roller_phase.
// Event::none: no event in a step.
enum class Event { none, lift_off, impact, turning_point, overturning, roller_tension, rest, landing_on_roller, end };
enum class Mode { at_rest, rocking, off_roller, over };

// The events that end a flight's step (the reset follows), in the order their guards are looked at.
constexpr Event kFlightEnds[] = {Event::impact, Event::overturning};

// How a step's motion is carried to where it ends (Simulator::apply): the step's own end; a landing within
// kTaylorSpan past it, by y + dh f(y); a landing within kShortLandingSpan, by land_short; or an event found by the
// search and placed on the integrator's own solution (polish_event).
enum class Reach { step_end, taylor, short_steps, polished };

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
          e_N_(model.eccentricity()),
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
        const double toward = a_h > 0.0 ? -1.0 : 1.0;  // a_h > 0 tips the wall toward theta1 < 0, which sees -e
        return std::abs(a_h) * r.X - ((g_ + a_v) * r.Y + N_ * (r.L + toward * e_N_ * r.Le));
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
                "{:.6g} rad), above the ceiling {:.3g}: the run is not a result ({})",
                out_.energy_balance_error, t, abs_theta, opt_.energy_ceiling, energy_failure_remedy(opt_)));
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
    // The roller's reaction at (t, y) on the current side [N/m], positive when it pushes.
    double roller_reaction(double t, const State& y) const {
        const double a_h = ah_(t), a_v = av_(t);
        const double acc =
            rocking_rates(model_.terms(side_ * y[0]), side_, y[1], a_h, a_v, g_, N_, e_N_).acceleration;
        return supports_.reactions(side_, y[0], y[1], acc, a_h, a_v).roller;
    }
    // The guards of the table above at (t, y), with y read through y(i), its component i: a State, or a step's
    // continuous extension (on_extension), where a guard that reads one component costs one. The motion's own guards
    // are inline (every step looks at them); those that evaluate the model are out of line (model_guard).
    template <class Component>
    double guard(Event e, double t, Component y) const {
        if (e == Event::impact) return side_ * y(0);
        if (e == Event::overturning) return collapse_ - side_ * y(0);
        if (e == Event::turning_point) return y(1);
        return model_guard(e, t, State{y(0), y(1), y(2)});
    }
    double guard(Event e, double t, const State& y) const {
        return guard(e, t, [&y](std::size_t i) { return y[i]; });
    }
    // Lift-off, roller tension and rest. Out of line, so that guard() stays small enough to inline.
    [[gnu::noinline]] double model_guard(Event e, double t, const State& y) const;
    // The restoring acceleration at rest on the current side, side theta1'' at theta1 = 0 (< 0: back to the ground).
    double restoring(double t, double theta_dot) const {
        return side_ * model_.acceleration(side_, 0.0, theta_dot, ah_(t), av_(t));
    }
    // The rest guard at an impact (y: theta1 = 0 and the velocity after it, side_ the new side): positive when the
    // next flight would rise less than rest_amplitude alpha while the ground cannot tip the wall.
    double rest_margin(double t, const State& y) const {
        const double a_out = restoring(t, y[1]);
        if (!(a_out < 0.0)) return -kNever;
        return opt_.rest_amplitude * alpha_ - y[1] * y[1] / (2.0 * -a_out);
    }
    bool unilateral() const { return opt_.roller == Roller::unilateral && supports_.active(); }
    // The supports are followed when asked for, and always under a unilateral roller (its departures need them).
    bool monitoring() const { return supports_.active() && (opt_.monitor_supports || unilateral()); }
    // A flight: the motion on one side between a lift-off or an impact and the next impact (rocking_phase). What
    // predicts its landing, the derivative at the current state and the storage of its steps.
    struct Flight {
        double launch = 0.0, launch_speed = 0.0;  // its start time and |theta1'| there
        bool symmetric = false;       // from theta1 = 0 with the ground still: it lands at 2 t_turn - t_launch
        bool starts_at_zero = false;  // the next step starts at theta1 = 0
        double aim = kNever;          // a predicted landing the next step is cut to end at
        State dy{};                   // f(t, y) at the current state
        RkStep<3> step, event_step;   // the trial step; the step re-taken to an event (polish_event)
    };
    // One step of a flight: where it stops and how its motion ends.
    struct Trial {
        double breakpoint = 0.0, stop = 0.0, h = 0.0, h_next = 0.0;
        bool to_aim = false;  // cut to end at the flight's aim
        Event ev = Event::none;  // what ends the flight in this step: none, impact or overturning
        Reach reach = Reach::step_end;
        double landing_dh = 0.0;        // Reach::taylor: the Taylor step from the step's end
        State landing{}, landing_dy{};  // Reach::short_steps: the state at the landing and its derivative
        double event_time = 0.0;        // where the step's motion ends
    };

    // The flows of the modes (at rest, rocking, off the roller): each runs from (t, y) until the first event it
    // watches, and returns it with (t, y) there.
    Event rest_phase(double& t, State& y);
    Event rocking_phase(double& t, State& y);
    Event off_roller_phase(double& t, State& y);
    // The resets of the table's rows: each applies its event at (t, y) and returns the mode that follows.
    Mode lift(double& t, State& y);
    Mode impact(double& t, State& y);
    Mode turn(double& t, State& y);
    Mode overturn(double& t, State& y);
    Mode leave(double& t, State& y);
    Mode settle(double& t, State& y);
    Mode land(double& t, State& y);
    Mode finish(double& t, State& y);
    void back_on_roller(Flight& f, double t, const State& y);
    Flight launch(double t, const State& y);
    double parabola_aim(double t, const State& y, const State& dy, double breakpoint) const;
    bool take_step(Flight& f, double t, const State& y, Trial& s);
    bool locate(Flight& f, double t, const State& y, Trial& s);
    void place_landing(Flight& f, double t, Trial& s) const;
    bool ends_past_flight(const RkStep<3>& step) const;
    bool search_flight_end(Flight& f, double t, const State& y, Trial& s);
    void record_turning_points(Flight& f, double t, const State& y, const Trial& s);
    bool apply(Flight& f, double& t, State& y, const Trial& s);
    std::optional<double> roller_tension_in(RkStep<3>& step, double roller_before, double t);
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
    double e_N_;  // N's eccentricity [m] (model.hpp)
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
    Flight flight_;          // the current flight, started by the lift-off's or the impact's reset
    mutable std::size_t breakpoint_hint_[2] = {0, 0};  // next_breakpoint's last answers (horizontal, vertical)
    SimulationResult out_;

public:
    // One row of the event table (the comment above Event): the event, the direction its guard (guard()) crosses
    // zero in, its reset, and the equation they come from.
    struct EventRow {
        Event event;
        Direction direction;
        Mode (Simulator::*reset)(double& t, State& y);
        const char* source;
    };
    static constexpr EventRow kEvents[] = {
        {Event::lift_off, Direction::rising, &Simulator::lift, "Eq. (12); Eq. (17) for a parapet"},
        {Event::impact, Direction::falling, &Simulator::impact, "Eq. (19), or the whole mechanism's impact"},
        {Event::turning_point, Direction::either, &Simulator::turn, "Eq. (10): theta1' = 0"},
        {Event::overturning, Direction::falling, &Simulator::overturn, "Eq. (26)"},
        {Event::roller_tension, Direction::rising, &Simulator::leave, "Eq. (2)'s constraint force"},
        {Event::rest, Direction::rising, &Simulator::settle, "Eq. (19)'s geometric series of impacts"},
        {Event::landing_on_roller, Direction::falling, &Simulator::land, "Eq. (2), restored plastically"},
        {Event::end, Direction::falling, &Simulator::finish, "the run's end time"},
    };
    // Rows are looked up by the event's number: they must follow the enum, one each.
    static constexpr bool rows_follow_events() {
        for (std::size_t i = 0; i < std::size(kEvents); ++i)
            if (static_cast<std::size_t>(kEvents[i].event) != i + 1) return false;
        return std::size(kEvents) == static_cast<std::size_t>(Event::end);
    }

private:
    static constexpr const EventRow& row(Event e) { return kEvents[static_cast<std::size_t>(e) - 1]; }
    static constexpr Direction direction(Event e) { return row(e).direction; }
    // The main loop's one question: the event's reset, applied.
    Mode fire(Event e, double& t, State& y) { return (this->*row(e).reset)(t, y); }
    // The flow of a mode other than over.
    Event flow(Mode m, double& t, State& y) {
        static constexpr Event (Simulator::*kFlows[])(double&, State&) = {
            &Simulator::rest_phase, &Simulator::rocking_phase, &Simulator::off_roller_phase};
        return (this->*kFlows[static_cast<std::size_t>(m)])(t, y);
    }
};
static_assert(Simulator::rows_follow_events(), "the event table's rows follow the Event enum");

// The flow off the roller: the top flies off it (off_roller.hpp) from (t, y) until it lands back on the roller, the
// base lands (the one-DOF impact, on the far guide), the upper block folds past its guide (overturning) or the run
// ends.
Event Simulator::off_roller_phase(double& t, State& y) {
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
        case OffRollerEnd::How::on_roller: return Event::landing_on_roller;
        case OffRollerEnd::How::base_impact: return Event::impact;  // on the far guide at theta1 = 0: one-DOF again
        case OffRollerEnd::How::collapse: off_mechanism_ = true; return Event::overturning;
        case OffRollerEnd::How::end_time: off_mechanism_ = true; break;
    }
    return Event::end;
}

// The flow at rest: waits from t until the lift-off guard crosses (Event::lift_off, t there) or the run ends at rest
// (Event::end). A run already at its end (a wall settled there) ends without waiting.
Event Simulator::rest_phase(double& t, State& y) {
    if (!(t < opt_.t_end)) return Event::end;
    y[0] = 0.0;
    y[1] = 0.0;
    const double rest_start = t;
    const auto margin = [&](double when) { return guard(Event::lift_off, when, y); };  // the table's lift-off guard
    auto rest_state = [&](double) { return y; };
    auto lift = [&](double when) {
        emit_grid(rest_start, when, rest_state);
        t = when;
        return Event::lift_off;
    };
    // The ground motion is left-continuous at its breakpoints: where it drops at a breakpoint (a cosine pulse's end),
    // a margin positive at that instant alone tips nothing. The wall lifts only where the margin is positive just
    // after the instant too.
    auto tips_from = [&](double when) {
        return margin(when) > 0.0 && margin(std::nextafter(when, opt_.t_end + 1.0)) > 0.0;
    };
    if (tips_from(t)) return lift(t);
    double scan = t;
    while (scan < opt_.t_end) {
        if (scan >= motion_end_) {  // no more ground motion: nothing can lift the wall again
            const double end = opt_.stop_at_rest ? std::max(scan, rest_start) : opt_.t_end;
            emit_grid(rest_start, end, rest_state);
            t = end;
            out_.at_rest_at_end = true;
            return Event::end;
        }
        double next = std::min({next_breakpoint(scan), opt_.t_end, motion_end_});
        // An analytic signal's extrema too: between them and the breakpoints |a_h| is largest at an end, so no
        // excursion past the threshold falls between two looks (a 2 ms harmonic looked at every 1 ms saw its zeros).
        // With a vertical motion that varies too this holds for records (both linear between the union of their
        // samples, where the margin |a_h| X - (g + a_v) Y is convex), not for an analytic vertical signal, which can
        // rise with a_h and peak between looks (the command line offers vertical records only).
        next = std::min({next, scan + rest_scan_step_, ah_.next_extremum(scan), av_.next_extremum(scan)});
        if (margin(next) > 0.0) {
            // Narrow to the crossing, keeping the right end, where the margin is positive, so the flight starts.
            double lo = scan, hi = next;
            // A margin of exactly 0 counts as below: the bracket's right end then always lifts, and the search does
            // not stop on a run of exact zeros (near the threshold they span many ulps: a lift-off 1.01 times above it
            // started 0.6 ms late).
            shrink_bracket(
                [&](double x) {
                    const double m = margin(x);
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
    out_.at_rest_at_end = true;
    return Event::end;
}

// Refines an event found on the continuous extension so that it lies on the integrator's own solution, not on its
// interpolant: Newton on the real step size. Once the correction dh is below kTaylorSpan, the last step's end is
// carried to the event by y + dh f(y): one step per event instead of two. Leaves the final state in `step`.
void Simulator::polish_event(Event ev, double t, const State& y, const State& dy, double h, RkStep<3>& step) const {
    for (int i = 0; i < kMaxNewtonIterations; ++i) {
        integrator_.step(t, y, dy, h, step);
        // The guard (impact or overturning) and its rate at the step's end.
        const double g = guard(ev, t + h, step.y1);
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

// The guards of the table that evaluate the model (guard() reads the motion's own).
double Simulator::model_guard(Event e, double t, const State& y) const {
    if (e == Event::roller_tension) return -roller_reaction(t, y);
    if (e == Event::rest) return rest_margin(t, y);
    return tipping_margin(t);  // lift-off
}

// The flow rocking on the roller: the current flight (flight_) steps, predicts, locates and applies until an event
// ends it (an impact or the overturning), a unilateral roller would pull (roller tension), or the run ends (end).
Event Simulator::rocking_phase(double& t, State& y) {
    Flight& f = flight_;
    while (t < opt_.t_end) {
        if (unilateral() && last_roller_ < 0.0) return Event::roller_tension;  // it cannot pull: the top leaves it
        if (++out_.steps > kMaxIntegrationSteps) throw std::runtime_error("integration exceeded the step limit");
        Trial s;
        s.breakpoint = next_breakpoint(t);
        if (!f.symmetric && opt_.predict_landings) f.aim = parabola_aim(t, y, f.dy, s.breakpoint);
        if (!take_step(f, t, y, s) || !locate(f, t, y, s)) continue;  // rejected, or retried shorter
        if (apply(f, t, y, s)) return s.ev;
    }
    return Event::end;
}

// A flight starts at (t, y): from theta1 = 0 (a lift-off or an impact) or anywhere (a release, the run's start).
Simulator::Flight Simulator::launch(double t, const State& y) {
    Flight f;
    f.dy = integrator_.rhs(t, y);
    f.starts_at_zero = y[0] == 0.0;
    if (f.starts_at_zero && y[1] != 0.0) {
        // Cap the first step to 1.5 times the flight 2|v|/|a| predicted with the restoring acceleration at rest: the
        // real flight is longer (restoring moments fall as |theta1| grows), so the scan's first point (3/8 of the
        // flight) is still in the air, while a short flight usually ends inside this one step. Within a step the
        // side is fixed and the right-hand side smooth through theta1 = 0, so a step may overshoot the landing. (When
        // the parabola predicts the landing, the step is aimed at it instead: the flight itself, kShortLandingSpan.)
        const double a = std::abs(f.dy[1]);
        if (a > 0.0) h_ = std::min(h_, 3.0 * std::abs(y[1]) / a);
    }
    record_supports(t, y, f.dy[1]);
    // A flight from theta1 = 0 with the ground at rest is symmetric in time about its turning point (the equation of
    // motion is even in theta1' and has no time in it once the ground is still): it lands at 2 t_turn - t_launch.
    // The step that reaches that time is cut to end there, and when it lands within kTaylorSpan the impact is placed
    // by y + dh f(y) instead of by the search on the continuous extension and a re-step (a quarter of a free
    // vibration's right-hand sides). A prediction only: a step that does not land there goes on as any other. In the
    // other flights the parabola predicts instead (kShortLandingSpan).
    f.launch = t;
    f.launch_speed = std::abs(y[1]);
    f.symmetric = f.starts_at_zero && y[1] != 0.0 && t >= motion_end_;
    if (!f.symmetric) flights_ = FlightHistory{};
    // Before its turning point is known, the flight's end is predicted from the last two (FlightHistory).
    if (f.symmetric && opt_.predict_landings) f.aim = f.launch + flights_.predict(f.launch_speed);
    return f;
}

// The top has landed back on the roller at (t, y): the one-DOF motion goes on from there.
void Simulator::back_on_roller(Flight& f, double t, const State& y) {
    f.dy = integrator_.rhs(t, y);
    h_ = std::min(h_, kFirstStepAfterLanding);
    f.starts_at_zero = false;
    record_supports(t, y, f.dy[1]);
    // Landed where the roller must pull at once: rather than leave again with no time between, the next one-DOF step
    // is taken and the top leaves at its end (one step on a pulling roller).
    if (last_roller_ < 0.0) last_roller_ = 0.0;
}

// Where the ground moves, the landing predicted by the parabola through theta1, theta1', theta1'' when it falls in
// the next step (of h_) before the breakpoint; kNever otherwise.
double Simulator::parabola_aim(double t, const State& y, const State& dy, double breakpoint) const {
    if (side_ * y[0] >= 0.0) {
        const double d = parabola_landing(side_ * y[0], side_ * y[1], side_ * dy[1]);
        if (d > 0.0 && d < h_ && t + d < breakpoint) return t + d;
    }
    return kNever;
}

// A trial step from (t, y) to the breakpoint, the end time or the aim, whichever comes first (h_ at most). False
// when it is rejected: h_ is cut and the step is to be taken again.
bool Simulator::take_step(Flight& f, double t, const State& y, Trial& s) {
    s.stop = std::min({s.breakpoint, opt_.t_end, f.aim > t ? f.aim : opt_.t_end});
    s.h = std::min(h_, s.stop - t);
    s.to_aim = s.stop == f.aim && s.h == s.stop - t;
    const double err = integrator_.step(t, y, f.dy, s.h, f.step);
    // A trial step that blew up (non-finite state or error) is rejected like any other, with a quarter step.
    const bool finite = std::isfinite(f.step.y1[0]) && std::isfinite(f.step.y1[1]) && std::isfinite(err);
    if (!finite || (err > 1.0 && !integrator_.fixed_step())) {
        ++out_.rejected_steps;
        h_ = finite ? integrator_.next_step(s.h, err) : 0.25 * s.h;
        if (h_ <= opt_.step.min_step)
            throw std::runtime_error(fmt::format("step size underflow at t = {} s (state {}, {})", t, y[0], y[1]));
        return false;
    }
    s.h_next = integrator_.next_step(s.h, err);
    return true;
}

// Where the accepted step's motion ends (s.ev, s.reach, s.event_time): at a landing placed from a step aimed at it,
// else at the first root over the flight's end guards, else at the step's end; with the turning points before it
// and the output grid up to it. False when a flight from theta1 = 0 is to be retried with a shorter step.
bool Simulator::locate(Flight& f, double t, const State& y, Trial& s) {
    if (s.to_aim) place_landing(f, t, s);
    if (s.reach == Reach::taylor) s.event_time = t + s.h + s.landing_dh;
    else if (s.reach == Reach::step_end) s.event_time = t + s.h;
    const bool turns = may_turn(f.step);
    // The output times up to the step's motion's end (a landing up to kShortLandingSpan past the step's end: the
    // times in between are read off the continuous extension just past the step).
    const bool outputs = opt_.keep_samples && opt_.output_dt > 0.0 && next_output_ <= s.event_time + 1e-12;
    if (turns || outputs) integrator_.make_dense(f.step);
    if (s.reach == Reach::step_end && ends_past_flight(f.step) && !search_flight_end(f, t, y, s)) return false;
    if (turns) record_turning_points(f, t, y, s);
    if (outputs) emit_grid(t, s.event_time, [&](double tau) { return f.step.at(tau); });
    return true;
}

// The step was cut to end at the predicted landing: when its end lies within kTaylorSpan of theta1 = 0 the impact is
// placed there by y + dh f(y) (Reach::taylor); within kShortLandingSpan, in a flight the symmetry does not predict,
// land_short reaches it (Reach::short_steps). Otherwise the step goes on as any other.
void Simulator::place_landing(Flight& f, double t, Trial& s) const {
    f.aim = kNever;
    const RkStep<3>& step = f.step;
    const double slope = side_ * step.y1[1];
    if (!(slope < 0.0)) return;
    s.landing_dh = -side_ * step.y1[0] / slope;
    if (std::abs(s.landing_dh) < kTaylorSpan) {
        s.ev = Event::impact;
        s.reach = Reach::taylor;
    } else if (!f.symmetric && std::abs(s.landing_dh) < kShortLandingSpan) {
        const std::optional<double> when =
            land_short(t + s.h, step.y1, step.end_derivative(), s.breakpoint, s.landing, s.landing_dy);
        if (!when) return;
        s.ev = Event::impact;
        s.reach = Reach::short_steps;
        s.event_time = *when;
    }
}

// Whether the step ends past one of the flight's ends (on the ground or past the collapse angle). Events show at the
// step's end: the wall cannot cross theta1 = 0 and come back within one flight. Most steps end in the air: this is
// all they look at.
bool Simulator::ends_past_flight(const RkStep<3>& step) const {
    for (const Event e : kFlightEnds)
        if (past(direction(e), guard(e, step.t0 + step.h, step.y1))) return true;
    return false;
}

// The first root over the flight's end guards (impact, overturning) that the step crosses, found on the continuous
// extension at kScanPoints looks. False when a flight from theta1 = 0 is to be retried with a shorter step.
bool Simulator::search_flight_end(Flight& f, double t, const State& y, Trial& s) {
    RkStep<3>& step = f.step;
    const auto on_step = [&](Event e) {
        // A flight launched from theta1 = 0 is above the ground from its start (its impact guard is 0 there).
        const double before = e == Event::impact && f.starts_at_zero ? 1.0 : guard(e, t, y);
        return StepGuard{direction(e), before, guard(e, t + s.h, step.y1), [this, e, &step](double tau) {
                             integrator_.make_dense(step);
                             return guard(e, tau, on_extension(step, tau));
                         }};
    };
    const Looks looks{t, s.h, kScanPoints, true};
    const auto root = first_root_over(kFlightEnds, looks, opt_.event_time_tol, on_step);
    if (!root) return true;
    // A flight from theta1 = 0 that is over before the scan's first point leaves no point in the air to bracket from
    // (the bracket would close onto the start): retry with a quarter step until one is seen.
    if (f.starts_at_zero && root->second.look == 1) {
        ++out_.rejected_steps;
        h_ = 0.25 * s.h;
        if (h_ <= opt_.step.min_step)
            throw std::runtime_error(
                fmt::format("a flight from rest at t = {} s is shorter than the smallest step", t));
        return false;
    }
    ++out_.searched_events;
    s.ev = root->first;
    s.reach = Reach::polished;
    s.event_time = root->second.t;
    return true;
}

// The turning points inside the step before its motion's end, recorded as peaks. In a symmetric flight the first one
// predicts the landing at 2 t_turn - t_launch.
void Simulator::record_turning_points(Flight& f, double t, const State& y, const Trial& s) {
    const RkStep<3>& step = f.step;
    const auto velocity = [&](double tau) { return guard(Event::turning_point, tau, on_extension(step, tau)); };
    const StepGuard turning{direction(Event::turning_point), guard(Event::turning_point, t, y),
                            guard(Event::turning_point, t + s.h, step.y1), velocity};
    const auto record = [&](Root r) {
        if (r.t <= s.event_time) {
            double at = r.t;
            State there = step.at(r.t);
            fire(Event::turning_point, at, there);
            if (f.symmetric && opt_.predict_landings && s.ev == Event::none) f.aim = 2.0 * r.t - f.launch;
        }
        return true;
    };
    scan_and_bracket(turning, Looks{t, s.h, kScanPoints}, opt_.event_time_tol, record, s.event_time);
}

// Carries (t, y) to where the step's motion ends, records the supports there and the roller's tension inside the
// step (where a unilateral roller lets the top go, the motion stops there instead), and checks the energy balance.
// True when an event ends the flight (s.ev).
bool Simulator::apply(Flight& f, double& t, State& y, const Trial& s) {
    const RkStep<3>& step = f.step;
    const bool on_breakpoint = s.ev == Event::none && t + s.h == s.stop;
    double h = s.h;
    switch (s.reach) {
        case Reach::taylor:  // `step` stays the integrator's step (the roller's bracket below may read its extension)
            f.dy = step.end_derivative();
            for (std::size_t n = 0; n < 3; ++n) y[n] = step.y1[n] + s.landing_dh * f.dy[n];
            h += s.landing_dh;
            break;
        case Reach::short_steps:  // likewise
            y = s.landing;
            f.dy = s.landing_dy;
            h = s.event_time - t;
            break;
        case Reach::polished:
            polish_event(s.ev, t, y, f.dy, s.event_time - t, f.event_step);
            h = f.event_step.h;
            y = f.event_step.y1;
            f.dy = f.event_step.end_derivative();
            break;
        case Reach::step_end:
            y = step.y1;
            f.dy = step.end_derivative();
            break;
    }
    const double roller_before = last_roller_;
    const bool first_tension = !out_.supports.roller_tension_at;
    t += h;
    h_ = s.h_next;
    f.starts_at_zero = false;
    record_supports(t, y, f.dy[1]);
    const bool lets_go = unilateral() && s.ev == Event::none;  // the top leaves the roller where it pulls
    if (monitoring() && (first_tension || lets_go)) {
        const std::optional<double> tension = roller_tension_in(f.step, roller_before, t);
        if (tension && first_tension) out_.supports.roller_tension_at = *tension;
        if (tension && lets_go) {  // there, not at the step's end
            t = *tension;
            y = step.at(*tension);
        }
    }
    // A ground motion may jump at a breakpoint (a cosine pulse's end) and is left-continuous there: the next
    // step's first stage must see the value after the jump. Where both motions are continuous (a record's
    // interior samples: every breakpoint but its ends) the step's last stage is already that value, to rounding.
    if (on_breakpoint && !(ah_.continuous_at(t) && av_.continuous_at(t)))
        f.dy = integrator_.rhs(std::nextafter(t, opt_.t_end + 1.0), y);
    out_.max_abs_theta = std::max(out_.max_abs_theta, std::abs(y[0]));
    if (s.ev == Event::impact) y[0] = 0.0;
    if (opt_.keep_samples || s.ev != Event::none) check_balance(t, y);  // events always; every step when sampling
    if (opt_.output_dt <= 0.0) emit(t, y);
    if (s.ev == Event::impact && f.symmetric) flights_.add(t - f.launch, f.launch_speed);
    return s.ev != Event::none;
}

// The roller-tension guard across the step (the supports' reactions recorded at its start, roller_before, and at its
// motion's end t): the moment it turned tensile, bracketed on the step's continuous extension up to t (past the
// step's end, in a landing's last kShortLandingSpan, the landing's time t stands for it). Nothing when not across.
std::optional<double> Simulator::roller_tension_in(RkStep<3>& step, double roller_before, double t) {
    if (!crosses(direction(Event::roller_tension), -roller_before, -last_roller_)) return std::nullopt;
    integrator_.make_dense(step);
    const auto tension = [&](double tau) { return guard(Event::roller_tension, tau, on_extension(step, tau)); };
    const Looks looks{step.t0, step.h, 1, false, std::min(t, step.t0 + step.h)};
    double at = t;
    const StepGuard g{direction(Event::roller_tension), -roller_before, tension(looks.end), tension};
    scan_and_bracket(g, looks, opt_.event_time_tol, [&](Root r) {
        at = r.t;
        return false;
    });
    return at;
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

    Mode mode = Mode::at_rest;
    if (y[0] != 0.0 || y[1] != 0.0) {  // released or launched: the first flight starts here
        side_ = y[0] != 0.0 ? (y[0] > 0.0 ? 1 : -1) : (y[1] > 0.0 ? 1 : -1);
        if (y[1] == 0.0) fire(Event::turning_point, t, y);  // a release is a turning point
        flight_ = launch(t, y);
        mode = Mode::rocking;
    }
    // The hybrid system: each mode's flow runs to its first event, whose row's reset gives the next mode.
    while (mode != Mode::over) mode = fire(flow(mode, t, y), t, y);
    check_balance(t, y);
    out_.t_final = t;
    return out_;
}

// The lift-off's reset at (t, y), at rest: the wall tips against the ground acceleration and its flight starts.
Mode Simulator::lift(double& t, State& y) {
    side_ = ah_(t) > 0.0 ? -1 : 1;  // the wall's inertia pushes it against the ground acceleration
    out_.lift_offs.push_back(t);
    if (opt_.output_dt <= 0.0) emit(t, y);
    flight_ = launch(t, y);
    return Mode::rocking;
}

// The impact's reset at (t, y), theta1 = 0: Eq. (19)'s map theta1'+ = e theta1'- onto the other side (or the impact
// law's e), the kinetic energy lost dissipated. Then the rest guard: when it is across, rest's reset follows;
// otherwise the next flight starts, unless the run is over.
Mode Simulator::impact(double& t, State& y) {
    const double v_before = y[1];
    const double m0 = rest_terms_.M;
    if (e_ <= 0.0) {  // an impact ratio of 0 (make_vssw refuses walls whose Eq. 19 gives e <= 0): stops dead
        out_.impacts.push_back({t, v_before, 0.0});
        dissipated_ += 0.5 * m0 * v_before * v_before;
        out_.rest_times.push_back(t);
        return Mode::at_rest;
    }
    const double v_after = e_ * v_before;
    out_.impacts.push_back({t, v_before, v_after});
    dissipated_ += 0.5 * m0 * (v_before * v_before - v_after * v_after);
    side_ = -side_;
    y[1] = v_after;
    if (past(direction(Event::rest), guard(Event::rest, t, y))) return fire(Event::rest, t, y);
    // A landing placed by y + dh f(y) may lie up to kTaylorSpan past a step that stopped at the end time: no flight.
    if (!(t < opt_.t_end)) return Mode::over;
    flight_ = launch(t, y);
    return Mode::rocking;
}

// The turning point's reset at (t, y): a peak recorded; the flight goes on.
Mode Simulator::turn(double& t, State& y) {
    out_.peaks.push_back({t, y[0]});
    out_.max_abs_theta = std::max(out_.max_abs_theta, std::abs(y[0]));
    return Mode::rocking;
}

// The overturning's reset: the run ends at t.
Mode Simulator::overturn(double& t, State&) {
    out_.overturned = true;
    out_.t_overturn = t;
    return Mode::over;
}

// The roller tension's reset under a unilateral roller (a bilateral one pulls, and its first tension is only
// recorded: apply): the top leaves the roller and the flight goes on in the two-DOF mechanism, where neither of its
// landing predictions holds.
Mode Simulator::leave(double&, State&) {
    flight_.symmetric = false;
    flights_ = FlightHistory{};
    flight_.aim = kNever;
    return Mode::off_roller;
}

// The landing on the roller's reset at (t, y) (the plastic projection itself is off_roller.cpp's): the one-DOF
// flight goes on from there.
Mode Simulator::land(double& t, State& y) {
    check_balance(t, y);
    back_on_roller(flight_, t, y);
    return Mode::rocking;
}

// The end's reset: the run ends where it is.
Mode Simulator::finish(double&, State&) { return Mode::over; }

// The rest reset after an impact at (t, y): the next flight would be negligible while the ground cannot tip the wall,
// so the remaining impacts, a geometric series of flights 2|v| e^n / |a|, are summed in closed form and the wall comes
// to rest at their end.
Mode Simulator::settle(double& t, State& y) {
    const double v_after = y[1];
    const double tail = 2.0 * std::abs(v_after) / (-restoring(t, v_after) * (1.0 - e_));
    dissipated_ += 0.5 * rest_terms_.M * v_after * v_after;
    y[1] = 0.0;
    // The output grid during the tail: the wall is within rest_amplitude of rest, shown at rest.
    const double t_rest = std::min(t + tail, opt_.t_end);
    emit_grid(t, t_rest, [&](double) { return y; });
    t = t_rest;
    out_.rest_times.push_back(t);
    check_balance(t, y);
    if (opt_.output_dt <= 0.0) emit(t, y);
    return Mode::at_rest;
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

std::string energy_failure_remedy(const SimulationOptions& options) {
    const double rtol = options.step.rtol, integrator_share = kBalanceErrorPerRtol * rtol;
    if (integrator_share >= options.energy_ceiling)
        return fmt::format("at a relative tolerance of {:g} the integrator's error can reach the ceiling: a tighter "
                           "one may help", rtol);
    return fmt::format("not the integrator's error, at most {:.3g} at a relative tolerance of {:g}, so a tighter one "
                       "gives the same failure: a defect in the model's events, to be reported with this run",
                       integrator_share, rtol);
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
    // Rounded corners roll: the pivots move along the arcs as the wall turns, which the equation of motion (10) does
    // not hold. The model gives their threshold in closed form only (docs/model/analytic-core.md, "Rounded corners").
    if (model.flat_share() < 1.0)
        throw InputError(fmt::format("corner radius r/b {:g}: the analytic model's motion is the sharp blocks' (its "
                                     "threshold, Eq. 12r / 17r, is all it gives for rounded corners); the engines "
                                     "measure the rest",
                                     1.0 - model.flat_share()));
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
