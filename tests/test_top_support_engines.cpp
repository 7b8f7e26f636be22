// A flexible top support in the engines (docs/model/top-support.md): every backend moves its roller with the
// diaphragm's u_d(t) of Eq. (9d) or refuses it naming why; those that move it approach the rigid top's run as T_d
// falls and agree with each other under a pulse on a Table 1 wall (the analytic model cannot follow this mechanism).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "analytic/error.hpp"
#include "analytic/ground_motion.hpp"
#include "analytic/wall.hpp"
#include "multibody/engine.hpp"
#include "multibody/kit/run_monitor.hpp"
#include "multibody/kit/wall_parts.hpp"
#include "tests/table1.hpp"

namespace vssw {
namespace {

using multibody::WallScene;

// Table 1 #7 (4.88 m by 0.2 m, h1/h 0.5, no overburden): no engine's defaults were measured on it (they were on
// Fig. 6's wall).
WallScene held_out_wall(double period) {
    WallScene scene = WallScene::of(make_vssw(testing::table1(7), 0.0));
    scene.diaphragm = Diaphragm{period, 0.05};
    return scene;
}

// A sine pulse of 0.5 s: 0.2 g (1.22 times the wall's threshold, 0.164 g) rocks it to an eighth of alpha1 under a
// rigid top; 0.25 g (1.52 times) to 0.7 alpha1, and with a 0.2 or 0.3 s diaphragm it overturns.
multibody::Excitation pulse(double amplitude_g) {
    multibody::Excitation ex;
    ex.horizontal = sine_pulse(amplitude_g * kStandardGravity, 0.5);
    ex.t_end = 2.5;
    ex.motion_only = true;
    return ex;
}

struct Response {
    double peak;  // largest |theta1| / alpha1
    bool overturned;
    double end;   // the run's last sample [s]: when it overturned
};

// The backend's run of the held-out wall, or nothing when it refuses a flexible top. A refusal must name the
// diaphragm (never silently ignored): InputError from an engine, EngineFailure from the analytic model.
std::optional<Response> run(const std::string& engine_name, double period, double amplitude_g) {
    const auto engine = multibody::make_engine(engine_name);
    const WallScene scene = held_out_wall(period);
    try {
        const multibody::Trajectory tr = engine->simulate(scene, pulse(amplitude_g), engine->default_settings());
        Response r{0.0, tr.overturned, tr.samples.back().t};
        for (const auto& s : tr.samples) r.peak = std::max(r.peak, std::abs(s.theta1) / scene.alpha());
        return r;
    } catch (const std::exception& e) {
        if (period == 0.0) throw;
        const std::string what = e.what();
        EXPECT_NE(what.find("flexible diaphragm"), std::string::npos) << what;
        return std::nullopt;
    }
}

class TopSupport : public ::testing::TestWithParam<std::string> {};

// Every backend moves its roller or refuses: a backend that ignored the diaphragm would give its rigid peak at
// T_d = 0.2 s, where the top's lag nearly triples it (measured: ODE 0.124 -> 0.352 alpha1, Box2D 0.130 -> 0.362).
TEST_P(TopSupport, MovesItsRollerOrSaysWhyNot) {
    const Response rigid = *run(GetParam(), 0.0, 0.2);
    const auto soft = run(GetParam(), 0.2, 0.2);
    if (!soft) GTEST_SKIP() << GetParam() << " refuses a flexible top support (its reason checked above)";
    constexpr double kMoved = 0.5;  // a factor 2.8 measured: far past any engine's own spread (5.6 %, below)
    EXPECT_GT(soft->peak / rigid.peak - 1.0, kMoved);
}

// T_d -> 0: a 5 ms diaphragm moves the top by u_d ~ a T_d^2 / (4 pi^2) = 1.5e-6 m (b = 0.1 m): under 0.25 g (a
// peak of 0.7 alpha1) the run is the rigid top's. (Near the threshold, under 0.2 g, a peak of 0.13 alpha1 moves by up
// to 7 % for offsets of 1e-7 to 1e-5 m in some engines: the response there is sensitive to any perturbation,
// docs/model/top-support.md, "The engines".)
TEST_P(TopSupport, StiffDiaphragmIsTheRigidTop) {
    const Response rigid = *run(GetParam(), 0.0, 0.25);
    const auto stiff = run(GetParam(), 0.005, 0.25);
    if (!stiff) GTEST_SKIP() << GetParam() << " refuses a flexible top support (its reason checked above)";
    constexpr double kStiff = 1e-3;  // measured: within 0.03 % (Bullet, ODE, Box2D, DART)
    EXPECT_NEAR(stiff->peak / rigid.peak, 1.0, kStiff);
    EXPECT_FALSE(stiff->overturned);
}

// With the other relaxations: rounded corners (r/b 0.1) and a finite friction (0.8 at the base and the hinge, far above
// what the pulse asks) on the same wall. An engine that moves its roller still moves it (the roller holds the nominal
// top corners, rounded or not): the 0.2 s diaphragm still raises the peak well past the rounded rigid top's. An engine
// that cannot do one of them refuses the run naming why, never a silent rigid or sharp run.
TEST_P(TopSupport, MovesItsRollerOnARoundedWallWithFriction) {
    if (GetParam() == "analytic") GTEST_SKIP() << "the analytic model follows neither (checked elsewhere)";
    const auto engine = multibody::make_engine(GetParam());
    const auto peak = [&](double period) -> std::optional<double> {
        WallScene scene = WallScene::of(with_corner_radius(make_vssw(testing::table1(7), 0.0), 0.1));
        scene.diaphragm = Diaphragm{period, 0.05};
        scene.friction = 0.8;
        scene.slip_measured = true;
        try {
            const multibody::Trajectory tr = engine->simulate(scene, pulse(0.2), engine->default_settings());
            double p = 0.0;
            for (const auto& s : tr.samples) p = std::max(p, std::abs(s.theta1) / scene.alpha());
            return p;
        } catch (const InputError& e) {
            const std::string what = e.what();
            EXPECT_TRUE(what.find("diaphragm") != std::string::npos || what.find("corner") != std::string::npos ||
                        what.find("friction") != std::string::npos)
                << what;
            return std::nullopt;
        }
    };
    const auto rigid = peak(0.0);
    if (!rigid) GTEST_SKIP() << GetParam() << " refuses a rounded wall or the friction (its reason checked above)";
    const auto soft = peak(0.2);
    if (!soft) GTEST_SKIP() << GetParam() << " refuses a flexible top support (its reason checked above)";
    constexpr double kMoved = 0.5;  // as for the sharp wall above: a roller left in place would give the rigid peak
    EXPECT_GT(*soft / *rigid - 1.0, kMoved);
}

// GoogleTest's names allow no '-' (simbody-rigid).
std::string backend_name(const ::testing::TestParamInfo<std::string>& param_info) {
    std::string n = param_info.param;
    std::replace(n.begin(), n.end(), '-', '_');
    return n;
}
INSTANTIATE_TEST_SUITE_P(Engines, TopSupport, ::testing::ValuesIn(multibody::available_engines()), backend_name);

// The engines that move their roller have independent contact schemes (ODE's LCP rows, Box2D's sequential impulses
// on circles and guides, DART's LCP on spheres and guide boxes, Bullet's sequential impulses on corner rows): their
// spread is the answer's uncertainty where the model cannot follow. Under 0.2 g they agree on the peak as well as
// they do with a rigid top; under 0.25 g a 0.2 or 0.3 s diaphragm overturns the wall in all of them, at the same
// time. The rigid top's peak is far outside the soft one's band: the check can fail.
TEST(TopSupportAgreement, EnginesThatMoveTheRollerAgree) {
    std::vector<std::string> movers;
    for (const std::string& name : multibody::available_engines())
        if (name != "analytic" && run(name, 0.2, 0.2)) movers.push_back(name);
    if (movers.size() < 2) GTEST_SKIP() << "fewer than two engines of this build move their roller";
    // Measured: rigid 6.0 % apart (Bullet 0.1230, ODE 0.1235, Box2D 0.1304, DART 0.1300); at T_d 0.2 s 3.3 %, at
    // 0.3 s 4.5 %.
    constexpr double kPeakSpread = 0.07;
    // Measured: 1.5 % at T_d 0.2 s (1.458, 1.459, 1.438, 1.438 s), 0.5 % at 0.3 s (1.322, 1.324, 1.318, 1.318 s).
    constexpr double kOverturnTime = 0.03;
    for (double period : {0.2, 0.3}) {
        SCOPED_TRACE(period);
        const Response a = *run(movers[0], period, 0.2), fall_a = *run(movers[0], period, 0.25);
        const Response rigid = *run(movers[0], 0.0, 0.2);
        EXPECT_GT(std::abs(rigid.peak / a.peak - 1.0), 5.0 * kPeakSpread);  // the check tells T_d from rigid
        EXPECT_TRUE(fall_a.overturned);
        for (std::size_t i = 1; i < movers.size(); ++i) {
            SCOPED_TRACE(movers[0] + " / " + movers[i]);
            const Response b = *run(movers[i], period, 0.2), fall_b = *run(movers[i], period, 0.25);
            EXPECT_FALSE(a.overturned || b.overturned);
            EXPECT_NEAR(a.peak / b.peak, 1.0, kPeakSpread);
            EXPECT_TRUE(fall_b.overturned);
            EXPECT_NEAR(fall_a.end / fall_b.end, 1.0, kOverturnTime);
        }
    }
    EXPECT_FALSE(run(movers[0], 0.0, 0.25)->overturned);  // a rigid top keeps the wall standing under 0.25 g
}

// The run monitor's energy check: off only where the roller moves, i.e. a flexible top under a ground motion (its
// work is the engine's, unbounded by the ground's pseudo-forces). A still state given 4 rad/s from nowhere at 0.3
// alpha1 is refused under a rigid top, and under a flexible one without shaking, where the roller stays put; under a
// pulse the flexible top's check is off and only the geometric checks stand.
TEST(TopSupportMonitor, EnergyCheckIsOffOnlyWhereTheRollerMoves) {
    constexpr double kDt = 1e-3;  // [s] any step: one check
    const auto energy_from_nowhere = [&](const WallScene& scene, const multibody::Excitation& ex) {
        multibody::RunMonitor monitor("test", scene, ex, kDt, {});
        const multibody::WallState s = multibody::still_state_at(scene, 0.3 * scene.alpha(), 4.0);
        try {
            monitor.check(kDt, s);
        } catch (const multibody::EngineFailure& e) {
            return std::string(e.what()).find("gained") != std::string::npos;
        }
        return false;
    };
    multibody::Excitation still;
    still.t_end = 1.0;
    EXPECT_TRUE(energy_from_nowhere(held_out_wall(0.0), still));
    EXPECT_TRUE(energy_from_nowhere(held_out_wall(0.2), still));
    EXPECT_TRUE(energy_from_nowhere(held_out_wall(0.0), pulse(0.2)));
    EXPECT_FALSE(energy_from_nowhere(held_out_wall(0.2), pulse(0.2)));
}

}  // namespace
}  // namespace vssw
