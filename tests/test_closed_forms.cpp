// Closed forms against each other, against their stated limits, and against the mechanics they summarise
// (angular momentum from the velocity fields of Eq. 5, potential and kinetic energy of Eqs. 6-7; Eqs. 4 and 7 against
// the two blocks of two_block.hpp).
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "analytic/closed_forms.hpp"
#include "analytic/model.hpp"
#include "analytic/two_block.hpp"

namespace vssw {
namespace {

constexpr double kRoundoff = 1e-12;       // identities that hold exactly, evaluated in double precision
constexpr double kFiniteDifference = 1e-7;  // central differences with step 1e-5: O(h^2) truncation
constexpr double kLimitXi = 1e9;           // "xi -> infinity" for the limits of Eqs. (15), (16), (18)
constexpr double kLimitTolerance = 1e-4;   // the limits converge as 1/sqrt(xi) or faster: 1e9 gives ~1e-4.5

const double kSqrt2 = std::sqrt(2.0);

TEST(ClosedForms, Eq13IsEq12WithoutOverburden) {
    for (double r : {0.46, 0.5, 0.6, 0.7, 0.9}) {
        const VsswGeometry w = make_vssw(3.05, 0.143, r);
        for (double a_v : {0.0, -2.0, 3.0}) {
            EXPECT_NEAR(eq12_threshold(w, a_v), eq13_threshold_no_overburden(w, a_v), kRoundoff * w.g);
        }
    }
}

TEST(ClosedForms, Eq14IsEq12InUnitsOfG) {
    for (double xi : {0.0, 0.1, 0.5, 2.0}) {
        for (double r : {0.5, 0.6, 0.75}) {
            const VsswGeometry w = make_vssw(4.88, 0.356, r, xi);
            EXPECT_NEAR(eq12_threshold(w) / w.g, eq14_threshold_over_g(w.b, w.h(), w.h1, xi), kRoundoff);
        }
    }
}

TEST(ClosedForms, Eq15MinimisesEq14AndTendsToTwoMinusRootTwo) {
    for (double xi : {0.05, 0.1, 0.5, 3.0}) {
        const double best = eq15_optimal_hinge_ratio(xi);
        const double at_best = eq14_threshold_over_g(1.0, 1.0, best, xi);
        for (double step : {-1e-3, 1e-3}) EXPECT_LT(at_best, eq14_threshold_over_g(1.0, 1.0, best + step, xi));
    }
    EXPECT_NEAR(eq15_optimal_hinge_ratio(kLimitXi), 2.0 - kSqrt2, kLimitTolerance);
    EXPECT_DOUBLE_EQ(eq15_optimal_hinge_ratio(0.0), 1.0);  // no overburden: the hinge goes to the top
}

TEST(ClosedForms, Eq16Limits) {
    // Large tensile strength and no overburden: mid-height. Both large: 2 - sqrt(2). t = 0 is close to Eq. (15).
    EXPECT_NEAR(eq16_cracking_hinge_ratio(0.0, 1e9), 0.5, kLimitTolerance);
    // "for both t and xi increasing ... again 2 - sqrt(2)" holds when xi outgrows t (with t = xi it is 3 - sqrt(6)).
    EXPECT_NEAR(eq16_cracking_hinge_ratio(kLimitXi, 10.0), 2.0 - kSqrt2, kLimitTolerance);
    EXPECT_NEAR(eq16_cracking_hinge_ratio(kLimitXi, kLimitXi), 3.0 - std::sqrt(6.0), kLimitTolerance);
    constexpr double kFig3aCloseness = 0.02;  // the paper: "the difference ... is negligible" (Fig. 3a)
    for (double xi : {0.1, 0.5, 1.0}) EXPECT_NEAR(eq16_cracking_hinge_ratio(xi, 0.0), eq15_optimal_hinge_ratio(xi),
                                                   kFig3aCloseness);
}

TEST(ClosedForms, Eq18IsEq14OverEq17AtTheOptimalHingeAndTendsTo3Plus2Root2) {
    for (double xi : {0.0, 0.1, 0.5, 4.0}) {
        const double r = eq15_optimal_hinge_ratio(xi);
        if (r >= 1.0) continue;  // xi = 0: the hinge at the top, no VSSW
        const VsswGeometry w = make_vssw(4.0, 0.4, r, xi);
        const ParapetGeometry p = make_parapet(4.0, 0.4, xi);
        EXPECT_NEAR(eq12_threshold(w) / eq17_parapet_threshold(p), eq18_threshold_ratio(xi), 1e-10);
    }
    EXPECT_NEAR(eq18_threshold_ratio(kLimitXi), 3.0 + 2.0 * kSqrt2, kLimitTolerance);
}

// Angular momentum of both bodies about the new base pivot O' just before and after an impact, from the velocity
// fields of Eq. (5) and its mirror image; the ratio that conserves it must be Eq. (19).
double restitution_from_angular_momentum(const VsswGeometry& w) {
    const double theta2_rate = -w.k;  // d theta2 / d theta1 at rest (Eq. 4)
    // Pivot O at the origin, the wall on x < 0 (Eq. 1); O' = (-2b, 0); centroids at rest.
    const std::array<double, 2> g1{-w.b, w.h1}, g2{-w.b, 2.0 * w.h1 + w.h2}, o_new{-2.0 * w.b, 0.0};
    auto cross = [&](const std::array<double, 2>& r, const std::array<double, 2>& v) {
        return (r[0] - o_new[0]) * v[1] - (r[1] - o_new[1]) * v[0];
    };
    // Before: unit rate about O. Eq. (5a-b) at theta1 = 0 (i points along -x in the paper's figure, so x flips).
    const double a1 = w.alpha1, a2 = w.alpha2;
    const std::array<double, 2> v1{w.R1 * std::cos(a1), w.R1 * std::sin(a1)};
    const std::array<double, 2> v2{w.R1 * std::cos(a1), w.R1 * (2.0 * std::sin(a1) + std::cos(a1) * std::tan(a2))};
    // Rotation rates in the counter-clockwise sense: the lower body turns clockwise here, the upper one back.
    const double before = w.m1 * cross(g1, v1) + w.m2 * cross(g2, v2) - w.I1 - w.I2 * theta2_rate;
    // After: the mirror image about the centreline x = -b, turning about O' at unit rate.
    const std::array<double, 2> u1{-v1[0], v1[1]}, u2{-v2[0], v2[1]};
    const double after = w.m1 * cross(g1, u1) + w.m2 * cross(g2, u2) + w.I1 + w.I2 * theta2_rate;
    // theta1' keeps its sign through the impact in the paper's convention (the wall passes to the other side).
    return -before / after;
}

TEST(ClosedForms, Eq19EqualsAngularMomentumBalance) {
    for (double r : {0.46, 0.5, 0.6, 0.7, 0.8}) {
        for (double thickness : {0.143, 0.356, 0.6}) {
            const VsswGeometry w = make_vssw(3.05, thickness, r);
            EXPECT_NEAR(eq19_restitution(w), restitution_from_angular_momentum(w), kRoundoff);
        }
    }
}

// The plastic impact with every constraint of the new mechanism: project the pre-impact velocity field (Eq. 5 at
// theta1 = 0, both bodies: vx, vy, omega) onto the mirrored post-impact field in the kinetic-energy metric.
double whole_mechanism_by_projection(const VsswGeometry& w) {
    const double k = w.k;  // |d theta2/d theta1| at rest (Eq. 4)
    // Before: unit rate about the pivot (+b, 0) (centred coordinates, the wall tipping to +x); omega counter-clockwise.
    const std::array<double, 6> before = {w.R1 * std::cos(w.alpha1), w.R1 * std::sin(w.alpha1), -1.0,
                                          w.R1 * std::cos(w.alpha1),
                                          w.R1 * (2.0 * std::sin(w.alpha1) + std::cos(w.alpha1) * std::tan(w.alpha2)), k};
    // After: the mirror image (x -> -x, omega -> -omega) turning the other way, per unit theta1' of the same sign.
    const std::array<double, 6> after = {before[0], -before[1], before[2], before[3], -before[4], before[5]};
    const std::array<double, 6> mass = {w.m1, w.m1, w.I1, w.m2, w.m2, w.I2};
    double cross = 0.0, norm = 0.0;
    for (int i = 0; i < 6; ++i) {
        cross += after[i] * mass[i] * before[i];
        norm += after[i] * mass[i] * after[i];
    }
    return cross / norm;
}

TEST(ClosedForms, WholeMechanismImpactIsTheProjectionOntoTheNewMechanism) {
    for (double r : {0.46, 0.5, 0.6, 0.7, 0.8}) {
        for (double thickness : {0.143, 0.356}) {
            const VsswGeometry w = make_vssw(3.05, thickness, r);
            EXPECT_NEAR(restitution_whole_mechanism(w), whole_mechanism_by_projection(w), kRoundoff);
            // The roller's impulse only takes energy away: the whole mechanism dissipates more than Eq. (19) says.
            EXPECT_LT(restitution_whole_mechanism(w), eq19_restitution(w));
        }
    }
}

TEST(ClosedForms, VsswDissipatesMoreThanParapetOfSameSize) {
    // Fig. 5b: e(VSSW) < e(PW) for equal b and h.
    for (double r : {0.5, 0.6, 0.7}) {
        for (double thickness : {0.143, 0.356}) {
            EXPECT_LT(eq19_restitution(make_vssw(3.05, thickness, r)),
                      housner_restitution(make_parapet(3.05, thickness).alpha));
        }
    }
}

TEST(ClosedForms, Eq11SIsHalfTheDerivativeOfEq11A) {
    // Z = 1/2 R1^2 C_A theta1'^2 (Eq. 7): the Coriolis term of a Lagrangian system is half of dC_A/dtheta1.
    for (double r : {0.46, 0.5, 0.7}) {
        const VsswGeometry w = make_vssw(4.0, 0.4, r, 0.2);
        for (double q : {0.0, 0.02, 0.08, 0.15}) {
            constexpr double h = 1e-5;
            const double dCA = (eq11_coefficients(w, q + h).C_A - eq11_coefficients(w, q - h).C_A) / (2 * h);
            EXPECT_NEAR(eq11_coefficients(w, q).C_S, 0.5 * dCA, kFiniteDifference * std::abs(dCA) + 1e-9);
        }
    }
}

TEST(ClosedForms, Eq11VAndNAreTheGradientsOfEq6AndEq8) {
    const VsswGeometry w = make_vssw(4.0, 0.4, 0.65, 0.3);
    for (double q : {0.01, 0.05, 0.12}) {
        constexpr double h = 1e-5;
        auto V = [&](double x) { return eq6_potential(w, x, eq3_theta2_linear(w, x)); };
        EXPECT_NEAR(w.R1 * w.g * eq11_coefficients(w, q).C_V, (V(q + h) - V(q - h)) / (2 * h),
                    kFiniteDifference * w.R1 * w.g * w.m1);
        // Eq. (8) is minus N times the lever of Eq. (11e).
        EXPECT_NEAR(eq8_overburden_work(w, q, eq3_theta2_linear(w, q)), -w.N * w.R1 * eq11_coefficients(w, q).C_N,
                    kRoundoff * w.N * w.R1);
    }
}

TEST(ClosedForms, Eq24IsTheVelocityThatCarriesRestToAlpha1) {
    // With N = 0 the exact kinematics put the upper diagonal vertical at theta1 = alpha1, as Eq. (24) assumes.
    for (double r : {0.5, 0.6, 0.7}) {
        const VsswGeometry w = make_vssw(4.0, 0.4, r);
        const auto exact = make_vssw_model(w, Kinematics::exact);
        EXPECT_NEAR(eq24_reference_velocity(w), exact->reference_velocity(), kRoundoff * 10);
    }
}

TEST(ClosedForms, Eq26IsWhereTheRollerCanNoLongerHoldTheTop) {
    // At Eq. (26) the hinge is 2 R2 from the roller line: Eq. (2) has a solution just below, none just above.
    const VsswGeometry w = make_vssw(4.0, 0.4, 0.7);
    const auto lim = eq26_limit_rotation(w);
    ASSERT_TRUE(lim.has_value());
    EXPECT_NEAR(2.0 * w.R1 * std::sin(*lim - w.alpha1), 2.0 * w.R2, kRoundoff);
    EXPECT_TRUE(eq2_theta2_exact(w, *lim - 1e-9).has_value());
    EXPECT_FALSE(eq2_theta2_exact(w, *lim + 1e-6).has_value());
    // At or below mid-height it does not exist (sin alpha1 >= sin alpha2).
    EXPECT_FALSE(eq26_limit_rotation(make_vssw(4.0, 0.4, 0.5)).has_value());
    EXPECT_FALSE(eq26_limit_rotation(make_vssw(4.0, 0.4, 0.46)).has_value());
}

// Eq. (4) is the rate of Eq. (2), theta2' / theta1' on the exact mechanism (as a magnitude: theta2 turns against
// theta1). Checked against the tangent of the two blocks' mechanism, t with J_g t = 0 for the top corner's constraint
// on the roller (two_block.hpp), and against a central difference of Eq. (2).
TEST(ClosedForms, Eq4IsTheUpperBodysRateOnTheRoller) {
    for (double r : {0.46, 0.5, 0.7, 0.8}) {
        const VsswGeometry w = make_vssw(4.0, 0.4, r);
        const TwoBlockWall wall(w, 1);
        for (double f : {0.0, 0.3, 0.8, 1.2}) {
            const double theta1 = f * w.alpha1;
            const double theta2 = *eq2_theta2_exact(w, theta1);
            const double rate = -wall.mechanism_tangent(wall.on_roller(theta1), Guide::roller)(1);
            EXPECT_NEAR(eq4_velocity_ratio(w, theta1, theta2), rate, kRoundoff * rate);
            if (theta1 == 0.0) continue;  // Eq. (2) holds for theta1 of either sign; its difference is one-sided there
            constexpr double h = 1e-5;
            const double slope = (*eq2_theta2_exact(w, theta1 + h) - *eq2_theta2_exact(w, theta1 - h)) / (2 * h);
            EXPECT_NEAR(eq4_velocity_ratio(w, theta1, theta2), -slope, kFiniteDifference * rate);
        }
    }
}

// Eq. (7) is the two blocks' kinetic energy on the exact mechanism: checked against T = 1/2 q'^T M q' of the two
// blocks (two_block.hpp: from each centroid's velocity and each block's rotation, not from Eq. 5), q' along the
// mechanism's tangent. With Eq. (3) in it, it is 1/2 R1^2 C_A theta1'^2 (Eq. 11a).
TEST(ClosedForms, Eq7IsTheTwoBlocksKineticEnergy) {
    constexpr double theta1_dot = 0.37;  // [rad/s]
    for (double r : {0.46, 0.5, 0.7, 0.8}) {
        const VsswGeometry w = make_vssw(4.0, 0.4, r);
        const TwoBlockWall wall(w, 1);
        for (double f : {0.0, 0.3, 0.8, 1.2}) {
            const double theta1 = f * w.alpha1;
            const Vec2 q = wall.on_roller(theta1);
            const double blocks = wall.kinetic(q, wall.mechanism_tangent(q, Guide::roller) * theta1_dot);
            EXPECT_NEAR(eq7_kinetic(w, theta1, *eq2_theta2_exact(w, theta1), theta1_dot), blocks, kRoundoff * blocks);
            const double eq11a = 0.5 * w.R1 * w.R1 * eq11_coefficients(w, theta1).C_A * theta1_dot * theta1_dot;
            EXPECT_NEAR(eq7_kinetic(w, theta1, eq3_theta2_linear(w, theta1), theta1_dot), eq11a, kRoundoff * eq11a);
        }
    }
}

TEST(ClosedForms, Eq2AndEq3AgreeForSmallRotationsAndExactlyAtMidHeight) {
    const VsswGeometry w = make_vssw(4.0, 0.4, 0.7);
    for (double q : {1e-4, 1e-3, 1e-2}) {
        // Eq. (3) is Eq. (2)'s tangent at rest: the difference is second order in theta1.
        const double diff = std::abs(*eq2_theta2_exact(w, q) - eq3_theta2_linear(w, q));
        EXPECT_LT(diff, 10.0 * q * q);
    }
    const VsswGeometry mid = make_vssw(4.0, 0.4, 0.5);
    for (double q : {0.01, 0.1, 0.3}) EXPECT_NEAR(*eq2_theta2_exact(mid, q), eq3_theta2_linear(mid, q), kRoundoff);
}

TEST(ClosedForms, Eq3StraysFromTheRollerAtSecondOrderExceptAtMidHeight) {
    const VsswGeometry w = make_vssw(4.0, 0.4, 0.7);
    // Second order: halving theta1 quarters the drift (to within the third-order term).
    constexpr double kSecondOrderRatio = 4.0, kRatioSlack = 0.05;
    EXPECT_NEAR(eq3_roller_drift(w, 2e-3) / eq3_roller_drift(w, 1e-3), kSecondOrderRatio, kRatioSlack);
    const auto limit = eq3_validity_limit(w, 0.01);
    ASSERT_TRUE(limit.has_value());
    EXPECT_NEAR(std::abs(eq3_roller_drift(w, *limit)), 0.01 * 2.0 * w.b, kRoundoff);
    // At mid-height Eq. (3) is exact: no drift, ever.
    const VsswGeometry mid = make_vssw(4.0, 0.4, 0.5);
    EXPECT_NEAR(eq3_roller_drift(mid, 0.3), 0.0, kRoundoff);
    EXPECT_FALSE(eq3_validity_limit(mid, 0.01).has_value());
    // A higher hinge strays sooner (Table 1's specimens 10 and 7 have the same height).
    EXPECT_LT(*eq3_validity_limit(make_vssw(4.88, 0.194, 0.75), 0.01) / make_vssw(4.88, 0.194, 0.75).alpha1,
              *eq3_validity_limit(make_vssw(4.88, 0.194, 0.6), 0.01) / make_vssw(4.88, 0.194, 0.6).alpha1);
}

TEST(ClosedForms, Eq22ShrinksWithAmplitudeOnlyThroughTheArccosh) {
    // T is size-independent in shape: T * P depends on theta10/A only (Eq. 22), and grows with amplitude.
    const VsswGeometry small = make_vssw(3.0, 0.2, 0.6), large = make_vssw(6.0, 0.4, 0.6);
    EXPECT_NEAR(eq22_period(small, 0.5 * eq21_A(small)) * eq21_P(small),
                eq22_period(large, 0.5 * eq21_A(large)) * eq21_P(large), kRoundoff * 10);
    EXPECT_LT(eq22_period(small, 0.2 * eq21_A(small)), eq22_period(small, 0.8 * eq21_A(small)));
    EXPECT_NEAR(eq21_A(make_vssw(4, 0.4, 0.5)), make_vssw(4, 0.4, 0.5).alpha1, kRoundoff);  // A = alpha1 at mid-height
}

TEST(ClosedForms, HousnerRestitutionIsAngularMomentumAboutTheNewCorner) {
    const ParapetGeometry p = make_parapet(2.0, 0.3);
    // H before = I_O w - 2 m b^2 w... written from the centroid velocity: v = R w perpendicular to the diagonal.
    const double w = 1.0;
    const double before = p.I_G * w + p.m * p.R * w * p.R * std::cos(2.0 * p.alpha);
    const double after = p.I_O * w;
    EXPECT_NEAR(before / after, housner_restitution(p.alpha), kRoundoff);
}

}  // namespace
}  // namespace vssw
