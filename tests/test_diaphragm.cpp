// The flexible top support's diaphragm, Eq. (9d) (docs/model/top-support.md): its integration against closed forms
// and an independent integrator, its rigid limit, and its range checks.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "analytic/diaphragm.hpp"
#include "analytic/error.hpp"
#include "analytic/ground_motion.hpp"
#include "analytic/model.hpp"
#include "analytic/top_support_model.hpp"
#include "analytic/wall.hpp"
#include "analytic/wall_scene.hpp"

namespace vssw {
namespace {

constexpr double kTwoPi = 6.283185307179586;

// A constant acceleration is linear between any nodes: the closed form is met to rounding, here a few hundred ulps of
// the static offset a/omega^2 summed over the nodes a run crosses.
constexpr double kExact = 1e-12;
// A sine is sampled 128 times between extrema: its linear interpolation errs by at most (pi/128)^2/8 = 7.5e-5 of the
// amplitude, and the steady response by as much.
constexpr double kInterpolated = 2e-4;

// u_d of Eq. (9d) under a constant a from t = 0 (the step response), with its rate: the textbook closed form.
TopOffset step_response(double a, double period, double zeta, double t) {
    const double w = kTwoPi / period, wd = w * std::sqrt(1.0 - zeta * zeta);
    const double decay = std::exp(-zeta * w * t);
    const double u = -a / (w * w) * (1.0 - decay * (std::cos(wd * t) + zeta * w / wd * std::sin(wd * t)));
    const double v = -a / wd * decay * std::sin(wd * t);
    return {u, v, -a - 2.0 * zeta * w * v - w * w * u};
}

TEST(Diaphragm, RigidIsNoOffset) {
    const TopSupportMotion top(sine_pulse(3.0, 0.5), Diaphragm{});
    EXPECT_TRUE(top.is_rigid());
    const TopOffset o = top(0.2);
    EXPECT_EQ(o.u, 0.0);
    EXPECT_EQ(o.v, 0.0);
    EXPECT_EQ(o.a, 0.0);
}

// A constant acceleration on [0, D] is a step at 0 less a step at D: the response holds the step's closed form while
// the ground pushes and the difference of two after it (the free ring-down). A wrong damping must fail the check.
TEST(Diaphragm, StepInputFollowsTheClosedForm) {
    const double a = 2.5, period = 0.2, zeta = 0.05, duration = 0.73;
    const TopSupportMotion top(constant_motion(a, duration), Diaphragm{period, zeta});
    const double scale = a * std::pow(period / kTwoPi, 2);  // the static offset a / omega^2
    for (double t : {0.0, 0.013, 0.1, 0.37, 0.7299, 0.9, 1.6, 3.0}) {
        SCOPED_TRACE(t);
        TopOffset want = step_response(a, period, zeta, t);
        if (t > duration) {
            const TopOffset off = step_response(a, period, zeta, t - duration);
            want = {want.u - off.u, want.v - off.v, want.a - off.a};
        }
        const TopOffset got = top(t);
        const double w = kTwoPi / period;
        EXPECT_NEAR(got.u, want.u, kExact * scale);
        EXPECT_NEAR(got.v, want.v, kExact * scale * w);
        EXPECT_NEAR(got.a, want.a, kExact * scale * w * w);
        // The absolute acceleration of the top is a_h + u_d''.
        EXPECT_NEAR(top.absolute_acceleration(t), (t <= duration ? a : 0.0) + got.a, kExact * scale * w * w);
    }
    // The check tells the damping: the undamped closed form is far from the damped response a cycle later.
    EXPECT_GT(std::abs(top(0.45).u - step_response(a, period, 0.0, 0.45).u), 100.0 * kExact * scale);
}

// Under a long harmonic the transient dies out (zeta 0.2: below e^-15 of its start after 10 s, even at T_d = 0.8 s)
// and the offset's amplitude is the textbook steady state a / omega^2 / sqrt((1 - r^2)^2 + (2 zeta r)^2),
// r = Omega / omega.
TEST(Diaphragm, HarmonicReachesTheSteadyStateAmplitude) {
    const double a = 1.0, T = 0.5, zeta = 0.2;
    for (double period : {0.1, 0.3, 0.5, 0.8}) {  // below, near and at resonance, above
        SCOPED_TRACE(period);
        const TopSupportMotion top(harmonic(a, T, 12.0), Diaphragm{period, zeta});
        const double w = kTwoPi / period, r = period / T;
        const double steady = a / (w * w) / std::hypot(1.0 - r * r, 2.0 * zeta * r);
        double peak = 0.0;
        for (int i = 0; i < 4000; ++i) peak = std::max(peak, std::abs(top(10.0 + 2.0 * T * i / 4000.0).u));
        EXPECT_NEAR(peak / steady, 1.0, kInterpolated);
    }
}

// A record (linear between samples) against an independent integration: classical Runge-Kutta on Eq. (9d) with a
// step far below the record's, whose own error (h^4) is below 1e-10 of the peak.
TEST(Diaphragm, RecordMatchesAnIndependentIntegration) {
    std::vector<double> t, a;
    for (int i = 0; i <= 200; ++i) {  // 2 s at 100 Hz from 0.05 s (quiet before), a deterministic wiggle
        t.push_back(0.05 + 0.01 * i);
        a.push_back(3.0 * std::sin(0.37 * i) * std::cos(0.091 * i * i));
    }
    // Back to zero at the end, so that a(t) has no jump for the fixed-step integrator to straddle (it starts at 0).
    t.push_back(t.back() + 0.01);
    a.push_back(0.0);
    const GroundMotion record = GroundMotion::sampled(t, a, "wiggle");
    const Diaphragm d{0.25, 0.07};
    const TopSupportMotion top(record, d);
    // The largest gap between the closed form and classical Runge-Kutta on Eq. (9d) at `damping`, h = 1e-5 s.
    auto worst_gap = [&](double damping) {
        const double w = kTwoPi / d.period;
        auto rhs = [&](double time, double u, double v) { return -record(time) - 2.0 * damping * w * v - w * w * u; };
        const double h = 1e-5;
        double u = 0.0, v = 0.0, time = 0.0, worst = 0.0;
        for (int k = 0; k < 300000; ++k) {  // to 3 s: the last second rings down
            const double k1u = v, k1v = rhs(time, u, v);
            const double k2u = v + 0.5 * h * k1v, k2v = rhs(time + 0.5 * h, u + 0.5 * h * k1u, v + 0.5 * h * k1v);
            const double k3u = v + 0.5 * h * k2v, k3v = rhs(time + 0.5 * h, u + 0.5 * h * k2u, v + 0.5 * h * k2v);
            const double k4u = v + h * k3v, k4v = rhs(time + h, u + h * k3u, v + h * k3v);
            u += h / 6.0 * (k1u + 2.0 * k2u + 2.0 * k3u + k4u);
            v += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
            time = (k + 1) * h;
            if ((k + 1) % 1000 == 0) worst = std::max(worst, std::abs(top(time).u - u));
        }
        return worst;
    };
    constexpr double kIndependent = 1e-8;  // of the peak: RK4's error at h = 1e-5 s is below 1e-10 of it
    EXPECT_LT(worst_gap(d.damping), kIndependent * top.peak_offset());
    // The check tells a damping ratio 0.01 off.
    EXPECT_GT(worst_gap(d.damping + 0.01), 100.0 * kIndependent * top.peak_offset());
    EXPECT_GT(top.peak_offset(), 0.0);
}

// T_d -> 0: the diaphragm follows the ground quasi-statically, u_d = -a_h T_d^2 / (4 pi^2) + O(T_d^3): its peak over a
// sine pulse, over the quasi-static estimate, tends to 1, and the offset falls as T_d^2 (second order).
TEST(Diaphragm, RigidLimitIsReachedAtSecondOrder) {
    const double ap = 3.0, Tp = 0.5;
    double previous = 0.0;
    for (double period : {0.04, 0.02, 0.01}) {
        SCOPED_TRACE(period);
        const TopSupportMotion top(sine_pulse(ap, Tp), Diaphragm{period, 0.05});
        const double quasi_static = ap * period * period / (kTwoPi * kTwoPi);
        constexpr double kQuasiStatic = 0.1;  // the dynamic part, ~ (T_d / T_p) and its ringing: 8 % at 0.04 s
        EXPECT_NEAR(top.peak_offset() / quasi_static, 1.0, kQuasiStatic);
        if (previous > 0.0) {
            constexpr double kOrder = 0.3;  // halving T_d divides the offset by 4 within the O(T_d^3) part
            EXPECT_NEAR(std::log2(previous / top.peak_offset()), 2.0, kOrder);
        }
        previous = top.peak_offset();
    }
}

TEST(Diaphragm, RangesAreChecked) {
    const double kNaN = std::numeric_limits<double>::quiet_NaN(), kInf = std::numeric_limits<double>::infinity();
    for (double bad : {-0.1, kMaxDiaphragmPeriod * 1.01, kNaN, kInf})
        EXPECT_THROW(require_diaphragm(Diaphragm{bad, 0.05}), InputError) << bad;
    for (double bad : {-0.01, 1.0, kNaN})
        EXPECT_THROW(require_diaphragm(Diaphragm{0.2, bad}), InputError) << bad;
    EXPECT_NO_THROW(require_diaphragm(Diaphragm{0.0, 0.0}));
    EXPECT_NO_THROW(require_diaphragm(Diaphragm{kMaxDiaphragmPeriod, kMaxDiaphragmDamping}));
}

// A parapet has no top support: a flexible diaphragm on it is refused with the reason; the analytic model refuses
// a flexible top under a ground motion and takes it without one (u_d = 0: the paper's model as it is).
TEST(Diaphragm, WallsRefuseWhatTheyCannotHold) {
    Wall parapet = Wall::of(make_parapet(2.0, 0.3));
    parapet.diaphragm.period = 0.2;
    EXPECT_THROW(require_one_description(parapet), InputError);
    Wall vssw = Wall::of(make_vssw(4.0, 0.4, 0.7));
    vssw.diaphragm.period = 0.2;
    EXPECT_NO_THROW(require_one_description(vssw));
    EXPECT_THROW(require_model_follows_top(vssw, sine_pulse(3.0, 0.5)), InputError);
    EXPECT_NO_THROW(require_model_follows_top(vssw, GroundMotion::none()));
    vssw.diaphragm.period = 0.0;
    EXPECT_NO_THROW(require_model_follows_top(vssw, sine_pulse(3.0, 0.5)));
}


// The bodies of the exact VSSW in the mechanism's frame with the top held at w (Eq. 1 with Eq. 2d): the lower centre
// and its turn q, the upper centre and psi = alpha2 + theta2, and N's point (the top face's centre) height.
struct Bodies {
    double x1, y1, turn1, x2, y2, turn2, y_load;
};
Bodies bodies(const VsswGeometry& g, double q, double w) {
    const double a = g.alpha1 - q, psi = std::asin(g.s * std::sin(a) + w / (2.0 * g.R2));
    const double hinge_x = -2.0 * g.R1 * std::sin(a), hinge_y = 2.0 * g.R1 * std::cos(a), theta2 = psi - g.alpha2;
    return {-g.R1 * std::sin(a), g.R1 * std::cos(a), q, hinge_x + g.R2 * std::sin(psi), hinge_y + g.R2 * std::cos(psi),
            psi, hinge_y + 2.0 * g.h2 * std::cos(theta2) - g.b * std::sin(theta2)};
}

// Eq. (10d)'s left side against d'Alembert's principle on the bodies' positions: along q(tau) = q + v tau + A tau^2/2
// with the top at w(tau) = w + w' tau + w'' tau^2/2, the inertia forces sum_i m_i a_i . dr_i/dq + I_i turn_i''
// dturn_i/dq by finite differences. Without the moving constraint's velocity term dM/dt q' the check must fail.
TEST(TopSupportModel, EquationOfMotionIsDAlembertsOnTheBodies) {
    const VsswGeometry g = make_vssw(4.88, 0.2, 0.5);
    constexpr double kFiniteDifference = 1e-6;  // of the force's scale: central differences' h^2 and rounding/h^2
    for (double q : {0.2 * g.alpha1, 0.6 * g.alpha1}) {
        const double travel = 2.0 * g.R1 * (g.sin_a1 - std::sin(g.alpha1 - q));
        for (double w : {-0.003, 0.3 * travel}) {
            SCOPED_TRACE(::testing::Message() << "q " << q << " w " << w);
            ASSERT_TRUE(holds_mechanism(g, q, w));
            const TopOffsetState top{w, 0.05, -2.0};
            const double v = 0.3, A = 1.5, h = 1e-4, dq = 1e-6;
            auto at = [&](double tau) {
                return bodies(g, q + v * tau + 0.5 * A * tau * tau, w + top.w_dot * tau + 0.5 * top.w_ddot * tau * tau);
            };
            const Bodies b0 = at(0.0), bp = at(h), bm = at(-h);
            const Bodies qp = bodies(g, q + dq, w), qm = bodies(g, q - dq, w);
            auto acc = [&](double Bodies::*f) { return (bp.*f - 2.0 * b0.*f + bm.*f) / (h * h); };
            auto lever = [&](double Bodies::*f) { return (qp.*f - qm.*f) / (2.0 * dq); };
            const double inertia =
                g.m1 * (acc(&Bodies::x1) * lever(&Bodies::x1) + acc(&Bodies::y1) * lever(&Bodies::y1)) +
                g.I1 * acc(&Bodies::turn1) * lever(&Bodies::turn1) +
                g.m2 * (acc(&Bodies::x2) * lever(&Bodies::x2) + acc(&Bodies::y2) * lever(&Bodies::y2)) +
                g.I2 * acc(&Bodies::turn2) * lever(&Bodies::turn2);
            const RheonomicTerms t = top_support_terms(g, q, top);
            const double scale = t.M * A;
            EXPECT_NEAR(t.M * A + t.C * v * v + t.dM_dt * v + t.F, inertia, kFiniteDifference * scale);
            EXPECT_GT(std::abs(t.M * A + t.C * v * v + t.F - inertia), 100.0 * kFiniteDifference * scale);
            EXPECT_NEAR(t.X, g.m1 * lever(&Bodies::x1) + g.m2 * lever(&Bodies::x2), kFiniteDifference * std::abs(t.X));
            EXPECT_NEAR(t.Y, g.m1 * lever(&Bodies::y1) + g.m2 * lever(&Bodies::y2), kFiniteDifference * std::abs(t.X));
            EXPECT_NEAR(t.L, lever(&Bodies::y_load), kFiniteDifference * g.R1);
        }
    }
}

// w = 0 is the paper's constraint: Eq. (10d)'s terms are the exact model's Eq. (10) terms and the top's own terms
// vanish.
TEST(TopSupportModel, StillTopIsTheExactModel) {
    const VsswGeometry g = make_vssw(4.0, 0.4, 0.7);
    const auto model = make_vssw_model(g, Kinematics::exact);
    constexpr double kRounding = 1e-12;  // the same formulas in another order
    for (double q : {0.0, 0.3 * g.alpha1, 0.9 * g.alpha1}) {
        const ModelTerms m = model->terms(q);
        const RheonomicTerms t = top_support_terms(g, q, TopOffsetState{});
        EXPECT_NEAR(t.M / m.M, 1.0, kRounding);
        EXPECT_NEAR(t.C, m.C, kRounding * m.M);
        EXPECT_NEAR(t.X / m.X, 1.0, kRounding);
        EXPECT_NEAR(t.Y, m.Y, kRounding * std::abs(m.X));
        EXPECT_NEAR(t.L, m.L, kRounding * g.R1);
        EXPECT_EQ(t.dM_dt, 0.0);
        EXPECT_EQ(t.F, 0.0);
    }
}

// Eq. (9e): at rest only the side with sigma u_d <= 0 has the mechanism; at the bound the upper block stands square on
// the lower one (theta2 = 0). And the lagging top: under a sine pulse the diaphragm's offset has the sign of -a_h when
// the ground first reaches the wall's threshold, so toward the side the ground tips it (sigma = -sgn a_h) sigma u_d > 0
// and Eq. (9e) fails at lift-off, whatever the diaphragm's period from stiff to soft.
TEST(TopSupportModel, TheLaggingTopLeavesThePapersMechanismAtLiftOff) {
    const VsswGeometry g = make_vssw(4.88, 0.2, 0.5);
    EXPECT_TRUE(holds_mechanism(g, 0.0, -1e-4));
    EXPECT_FALSE(holds_mechanism(g, 0.0, 1e-4));
    const double q = 0.4 * g.alpha1, bound = 2.0 * g.R1 * (g.sin_a1 - std::sin(g.alpha1 - q));
    EXPECT_TRUE(holds_mechanism(g, q, 0.999 * bound));
    EXPECT_FALSE(holds_mechanism(g, q, 1.001 * bound));
    EXPECT_NEAR(bodies(g, q, bound).turn2 - g.alpha2, 0.0, 1e-12);
    const double threshold = make_vssw_model(g, Kinematics::exact)->rest_threshold(0.0);
    const GroundMotion pulse = sine_pulse(1.22 * threshold, 0.5);
    double t_c = 0.0;
    while (std::abs(pulse(t_c)) < threshold) t_c += 1e-5;  // the first time the ground can tip the wall
    for (double period : {0.02, 0.1, 0.2, 0.3}) {
        const double u = TopSupportMotion(pulse, Diaphragm{period, 0.05})(t_c).u;
        const double sigma = pulse(t_c) > 0.0 ? -1.0 : 1.0;
        EXPECT_GT(sigma * u, 0.0) << period;
        EXPECT_FALSE(holds_mechanism(g, 0.0, sigma * u)) << period;
    }
}

}  // namespace
}  // namespace vssw
