// The report's "What the paper's assumptions cost" (validation/assumptions_part.hpp): the shipped study run for the
// analytic model and an engine, its changes against the closed forms, and the files it must refuse.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "analytic/closed_forms.hpp"
#include "analytic/data_dir.hpp"
#include "analytic/error.hpp"
#include "analytic/wall.hpp"
#include "compare/targets.hpp"
#include "tests/engine_available.hpp"
#include "tests/temp_files.hpp"
#include "validation/assumptions_part.hpp"

namespace {

using namespace vssw;
using vssw::testing::TempDir;

// The threshold is found by bisection to a relative bracket of 1e-4 (compare::ThresholdOptions::rel_tol); a ratio of
// two such thresholds is within twice that.
constexpr double kRatioOfBisections = 2e-4;

const validation::RelaxationEffect* find(const validation::AssumptionsPart& p, const std::string& parameter,
                                         const std::string& metric) {
    for (const validation::RelaxationEffect& e : p.effects)
        if (e.parameter == parameter && e.metric == metric) return &e;
    return nullptr;
}

// N moved to the corner the wall tips toward lowers the Fig. 6 VSSW's threshold (xi 0.1) by Eq. (12e) over Eq. (12):
// the model's change is that ratio, and an engine's, judged as the report judges thresholds, follows it.
TEST(ReportRelaxations, TheEccentricThresholdsChangeIsEq12eOverEq12InTheModelAndTheEngine) {
    const TempDir dir;
    std::vector<std::string> engines;
    if (vssw::testing::engine_available("ode")) engines.push_back("ode");
    const std::string file = validation::assumptions_study_file("default", engines);
    validation::AssumptionsRunOptions options;
    options.plots = false;
    options.threads = 2;
    const validation::AssumptionsPart p = validation::run_assumptions_part(file, engines, dir / "relaxations", options);
    // The refusals are the analytic model's alone: it does not simulate a rounded wall (it gives Eq. 12r's threshold)
    // nor follow a flexible top (Eq. 9e); ODE expresses every relaxation.
    ASSERT_EQ(p.refusals.size(), 2u);
    for (const std::string& r : p.refusals) EXPECT_EQ(r.rfind("analytic: ", 0), 0u) << r;

    const VsswGeometry centred = make_vssw(4.0, 0.4, 0.7, 0.1);
    const double expected = eq12_threshold(with_eccentricity(centred, 1.0)) / eq12_threshold(centred) - 1.0;
    const validation::RelaxationEffect* threshold = find(p, "overburden_eccentricity", "threshold_g");
    ASSERT_NE(threshold, nullptr);
    EXPECT_LT(expected, -0.05);  // a change the check can see: N's lever at rest falls from 2 + k to 2
    EXPECT_NEAR(threshold->model, expected, kRatioOfBisections);
    if (!engines.empty()) {
        // (1 + change) is a ratio of two thresholds, each within the threshold target of the model's.
        EXPECT_NEAR(threshold->engines_lo, expected, 2.0 * compare::kThresholdTarget);
        EXPECT_NEAR(threshold->engines_hi, expected, 2.0 * compare::kThresholdTarget);
        EXPECT_EQ(threshold->engine_pairs, 1);
    }
    ASSERT_NE(find(p, "overburden_eccentricity", "period"), nullptr);

    // Corners rounded to r = 0.1 b: Eq. (12r) with N centred is the sharp threshold times 1 - r/b, in the model by
    // construction and in the engine as measured.
    const validation::RelaxationEffect* rounded = find(p, "corner_radius", "threshold_g");
    ASSERT_NE(rounded, nullptr);
    EXPECT_NEAR(rounded->model, -0.1, kRatioOfBisections);
    if (!engines.empty()) {
        EXPECT_NEAR(rounded->engines_lo, -0.1, 2.0 * compare::kThresholdTarget);
    }
    // Friction: the model cannot slide, so its threshold and period do not move at all.
    for (const char* metric : {"threshold_g", "period"}) {
        const validation::RelaxationEffect* friction = find(p, "friction", metric);
        ASSERT_NE(friction, nullptr) << metric;
        EXPECT_EQ(friction->model, 0.0) << metric;
    }
}

TEST(ReportRelaxations, AStudyThatRelaxesNothingOrDoesNotReadIsRefused) {
    const TempDir dir;
    const std::filesystem::path plain = dir / "plain.toml";
    std::ofstream(plain) << "metrics = [\"threshold_g\"]\nengines = [\"analytic\"]\n[wall]\nheight = 4\n"
                            "thickness = 0.4\nhinge = 0.7\nxi = [0.1, 0.2]\n[excitation]\nkind = \"threshold\"\n";
    try {
        (void)validation::assumptions_study_file(plain.string(), {});
        ADD_FAILURE() << "a study varying no physical assumption was taken";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("varies none of the paper's physical assumptions"), std::string::npos)
            << e.what();
    }
    EXPECT_THROW((void)validation::assumptions_study_file((dir / "missing.toml").string(), {}), InputError);
    EXPECT_EQ(validation::assumptions_study_file("none", {}), "");
}

}  // namespace
