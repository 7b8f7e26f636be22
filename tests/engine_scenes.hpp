#pragma once
// The walls and measurements the engine tests share: the cross-engine suite (tests/test_engines.cpp) and each engine
// folder's own tests (multibody/<engine>/tests/) release the same walls and read a run the same way.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "analytic/closed_forms.hpp"
#include "analytic/simulate.hpp"
#include "analytic/wall_scene.hpp"
#include "compare/experiments.hpp"
#include "compare/metrics.hpp"
#include "compare/targets.hpp"
#include "multibody/engine.hpp"
#include "tests/table1.hpp"

namespace vssw::testing {

inline multibody::WallScene fig6_vssw() { return multibody::WallScene::of(make_vssw(4.0, 0.4, 0.7)); }
inline multibody::WallScene fig6_parapet() { return multibody::WallScene::of(make_parapet(4.0, 0.4)); }
inline multibody::WallScene table1_specimen11(double xi) { return multibody::WallScene::of(make_vssw(table1(11), xi)); }

// The analytic model of a scene with exact kinematics: what an engine's bodies follow.
inline std::unique_ptr<RockingModel> analytic_reference(const multibody::WallScene& scene) {
    return vssw::analytic_model(scene, Kinematics::exact);
}

inline std::string fmt_scene(const multibody::WallScene& scene, double r) {
    return (scene.is_vssw() ? "VSSW h1/h " + std::to_string(scene.vssw->hinge_ratio()) + " xi " +
                                  std::to_string(scene.vssw->xi)
                            : std::string("parapet")) +
           " r " + std::to_string(r);
}

// Time of the first impact after a release at r alpha, from the engine's trajectory (the metric code's definition).
inline double first_impact(const multibody::Engine& engine, multibody::EngineSettings settings,
                           const multibody::WallScene& scene, double r) {
    multibody::Excitation ex;
    ex.theta0 = r * scene.alpha();
    ex.t_end = 1.2 * free_vibration(*analytic_reference(scene), ex.theta0).impacts.at(0).t;
    const auto q = compare::quarter_period(engine.simulate(scene, ex, settings));
    return q.value_or(NAN);
}

// An engine resolves a landing with every constraint of the new mechanism at once (base pivot, hinge, roller): its
// restitution should be the whole mechanism's plastic impact (analytic/closed_forms.hpp), not Eq. (19).
inline void expect_whole_mechanism_restitution(const multibody::Engine& engine,
                                               const multibody::EngineSettings& settings,
                                               const multibody::WallScene& scene) {
    const compare::FreeVibrationResult r = compare::run_free_vibration(engine, settings, scene);
    ASSERT_TRUE(r.restitution.has_value());
    EXPECT_NEAR(*r.restitution / restitution_whole_mechanism(*scene.vssw) - 1.0, 0.0, compare::kRestitutionTarget);
}

}  // namespace vssw::testing
