#pragma once
// `vssw compare` under a record or a pulse: the engines and the analytic model from rest under one ground motion, each
// run's peak rotation, its time and overturning. It is a one-case study built from values its caller has checked (the
// wall as built, the record as read, the engines' settings), measured by the study's code (study/measure.hpp), so
// that it gives the numbers of a study file with the same keys.
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "analytic/ground_motion.hpp"
#include "multibody/host/analytic_engine.hpp"
#include "multibody/engine.hpp"
#include "study/grid.hpp"

namespace vssw::study {

// The ground motion: a record (its file as named, read unscaled in m/s^2), or a pulse. A record is scaled by `scale`
// or to `pga_g`; a pulse's amplitude is multiplied by `scale` or set to `pga_g` (a pulse's peak is its amplitude).
struct ResponseMotion {
    std::string file;  // empty for a pulse
    GroundMotion record = GroundMotion::none();
    std::string shape;  // sine, cosine, ricker or harmonic
    double amplitude_g = 0.0, pulse_period = 0.0, duration = 0.0;  // [g], [s], [s] (harmonic only)
    std::optional<double> scale, pga_g;
};

// An engine and its settings (checked by the caller); "analytic" stands for the reference, which runs first whether
// named or not, with its own settings and the reference's assumptions.
struct ResponseEngine {
    std::string name;
    multibody::EngineSettings settings;
};

struct ResponseRun {
    std::string engine, version;
    std::string settings;  // as a study writes them ("dt=0.0002 iterations=30"); "" at the engine's defaults
    double peak = std::numeric_limits<double>::quiet_NaN();  // peak |theta1| / alpha
    double peak_time = std::numeric_limits<double>::quiet_NaN();
    double overturned = std::numeric_limits<double>::quiet_NaN();  // 1 or 0; NaN when the run failed
    double t_overturn = std::numeric_limits<double>::quiet_NaN();
    std::string status = "ok";  // or "failed: <reason>"
    std::string warnings;       // the analytic model's own assumptions failing along the run, "; "-joined
    // Finite friction (the wall's friction given): the response metrics of the same names (compare/metric_catalog),
    // NaN where a run has none (slips: the engines; the friction needed: the analytic model).
    double base_slip = std::numeric_limits<double>::quiet_NaN(), hinge_slip = base_slip;  // largest, in b
    double residual_base_slip = base_slip, residual_hinge_slip = base_slip;             // at the end, in b
    double slid_before_rocking = base_slip;                                             // 1 or 0
    double base_friction_needed = base_slip, hinge_friction_needed = base_slip;
};

struct ResponseComparison {
    CaseSpec the_case;
    std::vector<ResponseRun> runs;  // in the order run: the reference first (unless it is not a model, see below)
};

// Runs every engine and the reference. InputError before anything runs when the reference is the paper's kinematics
// with the unilateral roller and no engine is left to run (a study leaves such a run out), or when an engine's step
// cannot resolve the wall or the motion (as a study refuses it).
ResponseComparison compare_response(const multibody::WallScene& wall, const multibody::AnalyticAssumptions& reference,
                                    const ResponseMotion& motion, const std::vector<ResponseEngine>& engines);

}  // namespace vssw::study
