// Accuracy of an engine against the analytic model (exact kinematics) on the reference walls
// (docs/contributing/engines.md), at three steps: prints a Markdown table (relative errors of threshold, period and
// first-impact restitution) for docs/contributing/engines.md.
//   build/bench/vssw_engine_accuracy bullet [dt1 dt2 dt3]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "analytic/closed_forms.hpp"
#include "analytic/specimens.hpp"
#include "compare/experiments.hpp"
#include "multibody/engine.hpp"

using namespace vssw;

namespace {

struct NamedWall {
    std::string name;
    multibody::WallScene scene;
};

std::vector<NamedWall> walls() {
    std::vector<NamedWall> w;
    w.push_back({"Fig. 6 VSSW 4 x 0.4 m, h1/h 0.7", multibody::WallScene::of(make_vssw(4.0, 0.4, 0.7))});
    // Table 1 specimens 1, 7 and 15 (hinges at 0.69, 0.50, 0.60) at the three overburdens of the issue.
    const std::vector<Specimen> table1 = read_table1(default_table1_path());
    for (double xi : {0.0, 0.1, 0.5}) {
        for (int number : {1, 7, 15}) {
            const Specimen& s = table1_specimen(table1, number);
            char name[80];
            std::snprintf(name, sizeof name, "T1 #%d %.2f x %.3f, h1/h %.2f, xi %.1f", s.number, s.height, s.thickness,
                          s.hinge_ratio, xi);
            w.push_back({name, multibody::WallScene::of(make_vssw(s, xi))});
        }
    }
    w.push_back({"Fig. 6 PW 4 x 0.4 m (h/b 10)", multibody::WallScene::of(make_parapet(4.0, 0.4))});
    w.push_back({"PW 0.9 x 0.11 m (Lam, h/b 8.2)", multibody::WallScene::of(make_parapet(0.9, 0.11))});
    w.push_back({"PW 3 x 0.6 m (h/b 5)", multibody::WallScene::of(make_parapet(3.0, 0.6))});
    w.push_back({"PW 4 x 0.2 m (h/b 20)", multibody::WallScene::of(make_parapet(4.0, 0.2))});
    return w;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: vssw_engine_accuracy ENGINE [dt ...]\n");
        return 2;
    }
    try {
        const auto engine = multibody::make_engine_in_process(argv[1]);
        std::vector<double> steps;
        for (int i = 2; i < argc; ++i) {
            char* end = nullptr;
            const double dt = std::strtod(argv[i], &end);
            if (end == argv[i] || *end != '\0' || !(dt > 0.0)) {
                std::fprintf(stderr, "vssw_engine_accuracy: step '%s' is not a positive number (seconds)\n", argv[i]);
                return 2;
            }
            steps.push_back(dt);
        }
        if (steps.empty()) steps = {1e-3, 2e-4, 5e-5};
        std::printf("| wall | dt [s] | threshold | period (r = 0.5) | restitution | restitution vs whole mechanism | "
                    "wall time [s] |\n");
        std::printf("|---|---|---|---|---|---|---|\n");
        for (const NamedWall& w : walls()) {
            for (double dt : steps) {
                multibody::EngineSettings s = engine->default_settings();
                s.dt = dt;
                try {
                    const auto t0 = std::chrono::steady_clock::now();
                    const compare::EngineComparison c = compare::compare_with_analytic(*engine, s, w.scene, 0.5);
                    const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
                    // The plastic impact of the whole new mechanism (roller included; docs/contributing/engines.md
                    // "Bullet"), VSSW only.
                    const double whole =
                        w.scene.vssw ? c.restitution.engine / restitution_whole_mechanism(*w.scene.vssw) - 1.0 : NAN;
                    std::printf("| %s | %g | %+.2e | %+.2e | %+.2e | %+.2e | %.1f |\n", w.name.c_str(), dt,
                                c.threshold_g.rel_error, c.period.rel_error, c.restitution.rel_error, whole, sec);
                } catch (const multibody::EngineFailure& e) {
                    std::printf("| %s | %g | failed: %s | | | | |\n", w.name.c_str(), dt, e.what());
                }
                std::fflush(stdout);
            }
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "vssw_engine_accuracy: %s\n", e.what());
        return 2;
    }
    return 0;
}
