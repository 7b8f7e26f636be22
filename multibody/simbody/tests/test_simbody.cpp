// Simbody's own tests (multibody/simbody/): the compliant route's corner contacts against Simbody's contact
// subsystem, and the rigid route's debug text kept off stdout. Registered by multibody/simbody/engine.cmake and built
// into vssw_engine_tests (tests/CMakeLists.txt); each skips without Simbody in the build.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <string>

#include "analytic/closed_forms.hpp"
#include "compare/experiments.hpp"
#include "multibody/engine.hpp"
#include "tests/engine_available.hpp"
#include "tests/engine_scenes.hpp"

namespace vssw {
namespace {

using multibody::WallScene;
using testing::engine_available;
using testing::fig6_parapet;
using testing::fig6_vssw;
using testing::fmt_scene;

// Simbody's compliant route evaluates its corner contacts itself (multibody/simbody/corner_contacts.hpp) with the
// force law of Simbody's CompliantContactSubsystem, which it replaced for speed: both must give the same wall. The
// two sum the same forces in a different order and take different integrator steps from there, so they agree to the
// integrator's accuracy (1e-5), not to rounding. Measured at the defaults: period 6e-6, restitution 5e-5 (Fig. 6
// VSSW), both 1e-7 (parapet); a change of the law shows far above the bounds (a dissipation of 100 instead of
// 1000 s/m moves the Fig. 6 restitution by 1.3 %, docs/contributing/engines.md).
constexpr double kSameLawPeriod = 5e-5;       // about 10x the measured difference, 1e-4 of the period target
constexpr double kSameLawRestitution = 5e-4;  // 10x the measured difference, 1/40 of the restitution target

// Debian's libsimbody prints debug text on stdout at every rigid step; QuietStdout drops it (without formatting it)
// while a run steps and gives stdout back afterwards: nothing of it may reach file descriptor 1, and what the
// program prints after the run must. Suite named in lower case for `ctest -R simbody`.
TEST(simbody_quiet_stdout, DebugTextIsDroppedAndStdoutComesBack) {
    if (!engine_available("simbody-rigid"))
        GTEST_SKIP() << "Simbody not compiled in";
    const auto engine = multibody::make_engine("simbody-rigid");
    const WallScene scene = fig6_vssw();
    multibody::Excitation ex;
    ex.theta0 = 0.5 * scene.alpha();
    ex.t_end = 0.05;  // 100 steps, each printing when the library is built without NDEBUG
    std::fflush(stdout);
    std::FILE* capture = std::tmpfile();
    ASSERT_NE(capture, nullptr);
    const int saved = ::dup(1);
    ASSERT_GE(saved, 0);
    ::dup2(::fileno(capture), 1);
    (void)engine->simulate(scene, ex, engine->default_settings());
    std::printf("after the run\n");
    std::fflush(stdout);
    ::dup2(saved, 1);
    ::close(saved);
    std::rewind(capture);
    std::string text;
    for (int c = std::fgetc(capture); c != EOF; c = std::fgetc(capture)) text.push_back(static_cast<char>(c));
    std::fclose(capture);
    EXPECT_EQ(text, "after the run\n");
}

// Suite named in lower case so that `ctest -R simbody` runs it with the cross-engine cases.
TEST(simbody_compliant, CornerContactsReproduceTheContactSubsystem) {
    if (!engine_available("simbody")) GTEST_SKIP() << "Simbody not compiled in";
    const auto engine = multibody::make_engine("simbody");
    multibody::EngineSettings subsystem = engine->default_settings();
    subsystem.knobs["contact_subsystem"] = 1.0;
    for (const WallScene& scene : {fig6_vssw(), fig6_parapet()}) {
        SCOPED_TRACE(fmt_scene(scene, 0.5));
        const auto corners = compare::run_free_vibration(*engine, engine->default_settings(), scene);
        const auto tracked = compare::run_free_vibration(*engine, subsystem, scene);
        ASSERT_TRUE(corners.period && tracked.period && corners.restitution && tracked.restitution);
        EXPECT_NEAR(*corners.period / *tracked.period - 1.0, 0.0, kSameLawPeriod);
        EXPECT_NEAR(*corners.restitution / *tracked.restitution - 1.0, 0.0, kSameLawRestitution);
    }
}

}  // namespace
}  // namespace vssw
