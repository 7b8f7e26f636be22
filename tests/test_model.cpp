// The rocking models: the exact kinematics satisfy the roller (Eq. 2) and come from one Lagrangian; the paper's and
// the exact kinematics agree near rest and coincide at mid-height; the threshold is Eq. (12) for both and does not
// depend on size; the mirror rule makes theta -> -theta a symmetry.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "analytic/closed_forms.hpp"
#include "analytic/model.hpp"
#include "analytic/error.hpp"
#include "analytic/simulate.hpp"

namespace vssw {
namespace {

constexpr double kRoundoff = 1e-12;          // exact identities in double precision (relative)
constexpr double kFiniteDifferenceRel = 1e-7; // central differences, step 1e-5: O(h^2) truncation, relative
constexpr double kStep = 1e-5;

double central_difference(const std::function<double(double)>& f, double q) {
    return (f(q + kStep) - f(q - kStep)) / (2.0 * kStep);
}

TEST(Model, ExactKinematicsKeepTheTopCornerOnTheRoller) {
    // Positions from Eq. (1) with theta2 from Eq. (2): the pivot-side top corner stays on x = 0 (the roller).
    const VsswGeometry w = make_vssw(4.0, 0.4, 0.7);
    for (double q : {0.0, 0.05, 0.1, 0.3, 0.5}) {
        const double theta2 = *eq2_theta2_exact(w, q);
        const double hinge_x = -2.0 * w.R1 * std::sin(w.alpha1 - q);
        const double top_x = hinge_x + 2.0 * w.R2 * std::sin(w.alpha2 + theta2);
        EXPECT_NEAR(top_x, 0.0, kRoundoff);
    }
}

TEST(Model, PaperKinematicsDriftOffTheRollerAsRotationGrows) {
    // Eq. (3) is a linearisation: the top corner leaves the roller line at second order in theta1.
    const VsswGeometry w = make_vssw(4.0, 0.4, 0.7);
    double previous = 0.0;
    for (double q : {0.01, 0.05, 0.1}) {
        const double top_x = -2.0 * w.R1 * std::sin(w.alpha1 - q) + 2.0 * w.R2 * std::sin(w.alpha2 - w.k * q);
        EXPECT_GT(std::abs(top_x), previous);
        previous = std::abs(top_x);
    }
}

class ExactLagrangian : public ::testing::TestWithParam<double> {};

// Sum of m_i x_Gi from Eq. (1a-b) with theta2 given: the horizontal lever X(q) is its derivative.
double horizontal_moment(const VsswGeometry& w, double q, double theta2) {
    const double x1 = -w.R1 * std::sin(w.alpha1 - q);
    const double x2 = -2.0 * w.R1 * std::sin(w.alpha1 - q) + w.R2 * std::sin(w.alpha2 + theta2);
    return w.m1 * x1 + w.m2 * x2;
}

TEST_P(ExactLagrangian, HorizontalLeverIsTheDerivativeOfTheCentresOfMassPositions) {
    // X enters only through the ground's force, whose work uses the same X, so the energy balance cannot check it.
    const VsswGeometry w = make_vssw(4.0, 0.4, GetParam(), 0.2);
    const auto exact = make_vssw_model(w, Kinematics::exact), paper = make_vssw_model(w, Kinematics::paper);
    for (double q : {0.01, 0.05, 0.1, 0.2}) {
        const double dx_exact =
            central_difference([&](double x) { return horizontal_moment(w, x, *eq2_theta2_exact(w, x)); }, q);
        const double dx_paper =
            central_difference([&](double x) { return horizontal_moment(w, x, eq3_theta2_linear(w, x)); }, q);
        EXPECT_NEAR(exact->terms(q).X, dx_exact, kFiniteDifferenceRel * exact->terms(q).M);
        EXPECT_NEAR(paper->terms(q).X, dx_paper, kFiniteDifferenceRel * paper->terms(q).M);
    }
}

TEST_P(ExactLagrangian, CoriolisAndLeversAreDerivativesOfMassPotentialAndLoadHeight) {
    const VsswGeometry w = make_vssw(4.0, 0.4, GetParam(), 0.2);
    const auto m = make_vssw_model(w, Kinematics::exact);
    for (double q : {0.01, 0.05, 0.1, 0.2}) {
        const ModelTerms t = m->terms(q);
        const double dM = central_difference([&](double x) { return m->terms(x).M; }, q);
        const double dY = central_difference([&](double x) { return m->mass_moment_height(x); }, q);
        const double dL = central_difference([&](double x) { return m->load_height(x); }, q);
        EXPECT_NEAR(t.C, 0.5 * dM, kFiniteDifferenceRel * t.M);
        EXPECT_NEAR(t.Y, dY, kFiniteDifferenceRel * t.M);
        EXPECT_NEAR(t.L, dL, kFiniteDifferenceRel * w.h());
    }
}

TEST_P(ExactLagrangian, PaperModelIsLagrangianToo) {
    // Eq. (10)-(11) as printed are the Euler-Lagrange equation of Z = 1/2 R1^2 C_A theta1'^2 and Eq. (6) with Eq. (3).
    const VsswGeometry w = make_vssw(4.0, 0.4, GetParam(), 0.2);
    const auto m = make_vssw_model(w, Kinematics::paper);
    for (double q : {0.01, 0.05, 0.1}) {
        const ModelTerms t = m->terms(q);
        EXPECT_NEAR(t.C, 0.5 * central_difference([&](double x) { return m->terms(x).M; }, q),
                    kFiniteDifferenceRel * t.M);
        EXPECT_NEAR(t.Y, central_difference([&](double x) { return m->mass_moment_height(x); }, q),
                    kFiniteDifferenceRel * t.M);
        EXPECT_NEAR(t.L, central_difference([&](double x) { return m->load_height(x); }, q),
                    kFiniteDifferenceRel * w.h());
    }
}

TEST_P(ExactLagrangian, StageRatesAreTheEquationOfMotionFromTheTerms) {
    // rates() is what the integrator evaluates: the terms multiplied through by their common denominator, one
    // division. It must be rocking_rates(terms()) to rounding, on both sides, up to near the collapse angle, with
    // both ground motions (a wrong sign or a dropped power of the cosine changes it at the first digit).
    // The same function evaluated in another order: rounding, amplified where the terms of Eq. (10) cancel, hence
    // relative to the size of the largest of them rather than to the result.
    constexpr double kReformulated = 1e-12;
    const VsswGeometry w = make_vssw(4.0, 0.4, GetParam(), 0.2);
    const double a_h = 2.5, a_v = -1.5, theta_dot = 0.3;
    for (Kinematics k : {Kinematics::paper, Kinematics::exact}) {
        const auto m = make_vssw_model(w, k);
        for (double f : {0.0, 0.01, 0.3, 0.7, 0.95, 0.999}) {
            const double q = f * m->collapse_angle();
            const ModelTerms t = m->terms(q);
            const double term_size =
                (std::abs(a_h * t.X) + std::abs((w.g + a_v) * t.Y) + std::abs(w.N * t.L) +
                 std::abs(t.C) * theta_dot * theta_dot) / t.M;
            const double force_size = std::abs(a_h * t.X) + std::abs(a_v * t.Y);
            for (int side : {1, -1}) {
                const RockingRates want = rocking_rates(t, side, theta_dot, a_h, a_v, w.g, w.N, 0.0);
                const RockingRates got = m->rates(side, q, theta_dot, a_h, a_v);
                EXPECT_NEAR(got.acceleration, want.acceleration, kReformulated * term_size)
                    << to_string(k) << " q " << q << " side " << side;
                EXPECT_NEAR(got.ground_force, want.ground_force, kReformulated * force_size)
                    << to_string(k) << " q " << q << " side " << side;
                // The wrappers hand the model's own rates() on, to the bit (the terms() route would round otherwise).
                const std::unique_ptr<RockingModel> wrappers[] = {
                    with_restitution(make_vssw_model(w, k), 0.9),
                    with_stop_angle(make_vssw_model(w, k), 0.5 * m->collapse_angle())};
                for (const auto& wrapped : wrappers) {
                    const RockingRates r = wrapped->rates(side, q, theta_dot, a_h, a_v);
                    EXPECT_EQ(r.acceleration, got.acceleration) << wrapped->name() << " q " << q;
                    EXPECT_EQ(r.ground_force, got.ground_force) << wrapped->name() << " q " << q;
                }
            }
        }
    }
}

INSTANTIATE_TEST_SUITE_P(HingeRatios, ExactLagrangian, ::testing::Values(0.46, 0.5, 0.6, 0.7, 0.8));

TEST(Model, PaperAndExactAgreeAsRotationVanishes) {
    const VsswGeometry w = make_vssw(4.0, 0.4, 0.7, 0.1);
    const auto paper = make_vssw_model(w, Kinematics::paper), exact = make_vssw_model(w, Kinematics::exact);
    double previous = INFINITY;
    for (double q : {1e-1, 1e-2, 1e-3, 1e-4}) {
        const double a_p = paper->acceleration(1, q, 0.0, 0.0, 0.0), a_e = exact->acceleration(1, q, 0.0, 0.0, 0.0);
        const double diff = std::abs(a_p - a_e);
        EXPECT_LT(diff, previous);  // the gap closes with theta1
        previous = diff;
    }
    // and at rest the two are the same equation
    EXPECT_NEAR(paper->acceleration(1, 0.0, 0.3, 1.0, 0.5), exact->acceleration(1, 0.0, 0.3, 1.0, 0.5), kRoundoff);
}

TEST(Model, PaperAndExactCoincideWhenTheHingeIsAtMidHeight) {
    const VsswGeometry w = make_vssw(4.0, 0.4, 0.5, 0.3);  // alpha1 = alpha2: Eq. (3) is exact
    const auto paper = make_vssw_model(w, Kinematics::paper), exact = make_vssw_model(w, Kinematics::exact);
    for (double q : {0.01, 0.05, 0.09, 0.2}) {
        const ModelTerms p = paper->terms(q), e = exact->terms(q);
        EXPECT_NEAR(p.M, e.M, kRoundoff * e.M);
        EXPECT_NEAR(p.C, e.C, kRoundoff * e.M);
        EXPECT_NEAR(p.X, e.X, kRoundoff * e.M);
        EXPECT_NEAR(p.Y, e.Y, kRoundoff * e.M);
        EXPECT_NEAR(p.L, e.L, kRoundoff);
        EXPECT_NEAR(paper->potential(q), exact->potential(q), kRoundoff * e.M);
    }
}

TEST(Model, RestThresholdIsEq12ForBothKinematicsAndWithVerticalMotion) {
    for (double xi : {0.0, 0.1, 0.5}) {
        for (double r : {0.46, 0.6, 0.75}) {
            const VsswGeometry w = make_vssw(4.88, 0.356, r, xi);
            for (Kinematics k : {Kinematics::paper, Kinematics::exact}) {
                const auto m = make_vssw_model(w, k);
                for (double a_v : {0.0, 2.0, -3.0})
                    EXPECT_NEAR(m->rest_threshold(a_v), eq12_threshold(w, a_v), kRoundoff * w.g);
            }
        }
    }
    for (double xi : {0.0, 0.3}) {
        const ParapetGeometry p = make_parapet(0.9, 0.11, xi);
        EXPECT_NEAR(make_parapet_model(p)->rest_threshold(0.0), eq17_parapet_threshold(p), kRoundoff * p.g);
    }
}

TEST(Model, ThresholdDoesNotDependOnSize) {
    for (double scale : {0.25, 1.0, 7.0}) {
        const auto m = make_vssw_model(make_vssw(4.0 * scale, 0.4 * scale, 0.7, 0.1), Kinematics::exact);
        const auto ref = make_vssw_model(make_vssw(4.0, 0.4, 0.7, 0.1), Kinematics::exact);
        EXPECT_NEAR(m->rest_threshold(0.0), ref->rest_threshold(0.0), kRoundoff * 10);
    }
}

TEST(Model, MirrorRuleMakesThetaToMinusThetaASymmetry) {
    // theta -> -theta with a_h -> -a_h maps solutions to solutions: theta1'' flips sign.
    const VsswGeometry w = make_vssw(4.0, 0.4, 0.65, 0.2);
    for (Kinematics k : {Kinematics::paper, Kinematics::exact}) {
        const auto m = make_vssw_model(w, k);
        for (double q : {0.02, 0.1}) {
            const double plus = m->acceleration(1, q, 0.4, 1.5, 0.7);
            const double minus = m->acceleration(-1, -q, -0.4, -1.5, 0.7);
            EXPECT_NEAR(plus, -minus, kRoundoff * std::abs(plus));
        }
    }
}

TEST(Model, PotentialHasItsMaximumAtAlpha1WithoutOverburden) {
    // Fig. 2: rest is a minimum, theta1 = alpha1 a maximum (exactly, for the exact kinematics and N = 0).
    const VsswGeometry w = make_vssw(4.0, 0.4, 0.7);
    const auto m = make_vssw_model(w, Kinematics::exact);
    EXPECT_NEAR(m->terms(w.alpha1).Y, 0.0, kRoundoff * m->terms(0.0).Y);
    EXPECT_GT(m->potential(w.alpha1), m->potential(0.95 * w.alpha1));
    EXPECT_GT(m->potential(w.alpha1), m->potential(1.05 * w.alpha1));
}

TEST(Model, CollapseAngleIsEq26OrTheLowerBodyLyingFlat) {
    constexpr double kHalfPi = 1.5707963267948966;
    constexpr double kMarginRel = 1e-5;  // the documented relative margin (1e-6) short of Eq. (26), with headroom
    const VsswGeometry high = make_vssw(4.0, 0.4, 0.7);
    const auto m = make_vssw_model(high, Kinematics::exact);
    EXPECT_NEAR(m->collapse_angle(), *eq26_limit_rotation(high), kMarginRel * m->collapse_angle());
    EXPECT_LT(m->collapse_angle(), *eq26_limit_rotation(high));
    EXPECT_DOUBLE_EQ(make_vssw_model(make_vssw(4.0, 0.4, 0.46), Kinematics::paper)->collapse_angle(), kHalfPi);
    EXPECT_DOUBLE_EQ(make_parapet_model(make_parapet(4.0, 0.4))->collapse_angle(), kHalfPi);
}


TEST(Model, WithRestitutionChangesOnlyTheImpactRatio) {
    const VsswGeometry w = make_vssw(4.0, 0.4, 0.7);
    const double e = restitution_whole_mechanism(w);
    const SimulationResult own = free_vibration(*make_vssw_model(w, Kinematics::exact), 0.5 * w.alpha1);
    const SimulationResult other =
        free_vibration(*with_restitution(make_vssw_model(w, Kinematics::exact), e), 0.5 * w.alpha1);
    // The flight before the first impact is the same motion (same terms), the impact applies the ratio given.
    ASSERT_FALSE(own.impacts.empty());
    ASSERT_FALSE(other.impacts.empty());
    EXPECT_EQ(other.impacts[0].t, own.impacts[0].t);
    EXPECT_EQ(other.impacts[0].theta_dot_before, own.impacts[0].theta_dot_before);
    EXPECT_NEAR(other.impacts[0].theta_dot_after / other.impacts[0].theta_dot_before, e, kRoundoff);
    EXPECT_NEAR(own.impacts[0].theta_dot_after / own.impacts[0].theta_dot_before, eq19_restitution(w),
                kRoundoff);
    // A lower ratio dissipates more: the wall stops sooner.
    EXPECT_LT(other.impacts.size(), own.impacts.size());
}

TEST(Model, WithRestitutionRefusesARatioOutsideZeroToOne) {
    const VsswGeometry w = make_vssw(4.0, 0.4, 0.7);
    EXPECT_THROW(with_restitution(make_vssw_model(w, Kinematics::exact), 1.5), InputError);
    EXPECT_THROW(with_restitution(make_vssw_model(w, Kinematics::exact), -0.1), InputError);
    EXPECT_THROW(with_restitution(make_vssw_model(w, Kinematics::exact), std::nan("")), InputError);
}

}  // namespace
}  // namespace vssw
