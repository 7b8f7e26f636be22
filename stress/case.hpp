#pragma once
// A stress case (`vssw stress`): a hard input for every backend, what it runs and what is checked of the result.
// The cases themselves are in cases.cpp; judge.hpp runs one in-process; run.hpp runs them all, each in a child
// process with a time limit (multibody/host/child_process.hpp).
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "multibody/engine.hpp"

namespace vssw::stress {

// What a case runs on one backend. Built inside the child: a scene or setting the library refuses throws InputError
// there, which is the verdict "refused" with the library's message.
struct Setup {
    multibody::WallScene scene;
    multibody::Excitation excitation;
    multibody::EngineSettings settings;
    // The checks beyond "no failure, no NaN" (a run that ended with EngineFailure or NaN is never ok):
    bool overturn_as_analytic = false;    // overturned exactly when the analytic model (same scene and motion) does
    std::optional<double> period_tol;     // first-impact time within this relative tolerance of the analytic model's
    std::optional<double> max_theta;      // max |theta1| <= this [rad] (the wall did not rock where it cannot)
    std::optional<double> final_theta;    // |theta1| of the last sample <= this [rad] (back at rest on its base)
    bool must_rest = false;               // the run ended at rest before t_end (Trajectory::at_rest_at_end)
};

struct Case {
    std::string name;   // stable: bounds files and CI name it
    std::string what;   // what it stresses and what is checked, one line (docs/guide/stress.md, stress.md)
    bool quick = false; // in `vssw stress --quick`
    // The run on a backend (`engine` its name, `defaults` its default settings; `quick` shortens durations). Throws
    // InputError when the backend cannot take the case (a knob it does not have): the verdict "refused".
    std::function<Setup(const std::string& engine, const multibody::EngineSettings& defaults, bool quick)> setup;
};

// Every case, in report order (cases.cpp).
const std::vector<Case>& all_cases();
// The case with that name, or nullptr.
const Case* find_case(const std::string& name);

}  // namespace vssw::stress
