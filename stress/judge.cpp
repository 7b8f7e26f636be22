#include "stress/judge.hpp"

#include <cmath>
#include <memory>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "compare/metrics.hpp"
#include "multibody/engine.hpp"

namespace vssw::stress {
namespace {

using multibody::Trajectory;

CaseResult make(const Case& c, const std::string& engine, Verdict v, Failure f, std::string reason) {
    return {c.name, engine, v, f, std::move(reason), 0.0};
}

// The first sample with a non-finite value, if any.
std::optional<double> first_nan(const Trajectory& t) {
    for (const auto& s : t.samples)
        if (!std::isfinite(s.t) || !std::isfinite(s.theta1) || !std::isfinite(s.theta1_dot) || !std::isfinite(s.theta2) ||
            !std::isfinite(s.top_dy) || !std::isfinite(s.kinetic) || !std::isfinite(s.potential))
            return s.t;
    return std::nullopt;
}

// The analytic model on the same scene and motion: the known answer of the checks that need one.
Trajectory analytic_answer(const Setup& s) {
    const auto analytic = multibody::make_engine("analytic");
    multibody::EngineSettings settings = analytic->default_settings();
    settings.sample_dt = s.settings.sample_dt;
    return analytic->simulate(s.scene, s.excitation, settings);
}

// Each check of the setup in turn: the first that fails is the reason (Failure::wrong); all held, what was held.
CaseResult check(const Case& c, const std::string& engine, const Setup& s, const Trajectory& t) {
    std::vector<std::string> held;
    const bool needs_answer = s.overturn_as_analytic || s.period_tol;
    Trajectory answer;
    if (needs_answer) answer = analytic_answer(s);  // its own failure propagates: "failed: reported" (judge)
    // The analytic model's answer is known only where its own assumptions hold: a support that would have to pull
    // (the roller, the base, the hinge: analytic/validity.hpp) means the real wall leaves the rocking mechanism, and an
    // engine need not follow the model there. A friction warning (measured against a design value of 0.6, below the
    // scene's friction 2) does not void it.
    std::string void_reason;
    for (const std::string& w : answer.warnings)
        if (void_reason.empty() && w.find("friction coefficient") == std::string::npos) void_reason = w;
    // Only the checks against the analytic answer are voided; the case's own bounds (below) still hold.
    if (!void_reason.empty())
        held.push_back("not held against the analytic model, whose assumptions fail: " + void_reason);
    if (s.overturn_as_analytic && void_reason.empty()) {
        if (t.overturned != answer.overturned)
            return make(c, engine, Verdict::failed, Failure::wrong,
                        fmt::format("{} where the analytic model {}", t.overturned ? "overturned" : "did not overturn",
                                    answer.overturned ? "overturns" : "does not"));
        held.push_back(answer.overturned ? "overturned as analytic" : "no overturning, as analytic");
    }
    if (s.period_tol && void_reason.empty()) {
        const auto mine = compare::quarter_period(t), theirs = compare::quarter_period(answer);
        if (theirs && !mine)
            return make(c, engine, Verdict::failed, Failure::wrong,
                        fmt::format("no first impact where the analytic model has one at {:.4f} s", *theirs));
        if (mine && theirs) {
            const double err = *mine / *theirs - 1.0;
            if (!(std::abs(err) <= *s.period_tol))
                return make(c, engine, Verdict::failed, Failure::wrong,
                            fmt::format("first impact at {:.4f} s, analytic {:.4f} s ({:+.2f} %, allowed {:.0f} %)",
                                        *mine, *theirs, 100.0 * err, 100.0 * *s.period_tol));
            held.push_back(fmt::format("first impact {:+.3f} % of analytic", 100.0 * err));
        }
    }
    if (s.max_theta) {
        const double m = compare::max_abs_theta(t);
        if (!(m <= *s.max_theta))
            return make(c, engine, Verdict::failed, Failure::wrong,
                        fmt::format("max |theta1| {:.3g} rad past the allowed {:.3g} rad", m, *s.max_theta));
        held.push_back(fmt::format("max |theta1| {:.2g} rad", m));
    }
    if (s.final_theta) {
        const double last = t.samples.empty() ? 0.0 : std::abs(t.samples.back().theta1);
        if (!(last <= *s.final_theta))
            return make(c, engine, Verdict::failed, Failure::wrong,
                        fmt::format("|theta1| {:.3g} rad at the end, not back at rest (allowed {:.3g})", last,
                                    *s.final_theta));
        held.push_back("back at rest");
    }
    if (s.must_rest) {
        if (!t.at_rest_at_end)
            return make(c, engine, Verdict::failed, Failure::wrong,
                        fmt::format("not at rest by {:.1f} s", s.excitation.t_end));
        held.push_back(fmt::format("at rest at {:.3f} s", t.samples.empty() ? 0.0 : t.samples.back().t));
    }
    if (held.empty() || !void_reason.empty()) held.insert(held.begin(), "no failure, no NaN");
    return make(c, engine, Verdict::ok, Failure::none, fmt::format("{}", fmt::join(held, "; ")));
}

}  // namespace

CaseResult judge(const Case& c, const std::string& engine_name, bool quick) {
    Setup s;
    std::unique_ptr<multibody::Engine> engine;
    try {
        engine = multibody::make_engine_in_process(engine_name);  // judge() runs in a child of stress/run.cpp
        s = c.setup(engine_name, engine->default_settings(), quick);
        engine->check_settings(s.settings);
    } catch (const std::exception& e) {  // InputError, or a ground motion's own argument check
        return make(c, engine_name, Verdict::refused, Failure::none, e.what());
    }
    Trajectory t;
    try {
        t = engine->simulate(s.scene, s.excitation, s.settings);
    } catch (const InputError& e) {
        return make(c, engine_name, Verdict::refused, Failure::none, e.what());
    } catch (const std::exception& e) {  // EngineFailure, the analytic integrator's runtime_error
        return make(c, engine_name, Verdict::failed, Failure::reported, e.what());
    }
    if (const auto at = first_nan(t))
        return make(c, engine_name, Verdict::failed, Failure::nan, fmt::format("NaN in the output at t = {:.4f} s", *at));
    if (t.samples.empty()) return make(c, engine_name, Verdict::failed, Failure::wrong, "no samples");
    try {
        return check(c, engine_name, s, t);
    } catch (const std::exception& e) {
        return make(c, engine_name, Verdict::failed, Failure::reported,
                    fmt::format("the analytic model's answer failed: {}", e.what()));
    }
}

namespace {
Verdict verdict_of(const std::string& s) {
    if (s == "ok") return Verdict::ok;
    if (s == "refused") return Verdict::refused;
    return Verdict::failed;
}
Failure failure_of(const std::string& s) {
    for (Failure f : {Failure::none, Failure::reported, Failure::wrong, Failure::nan, Failure::timed_out,
                      Failure::crashed})
        if (s == to_string(f)) return f;
    return Failure::wrong;
}
}  // namespace

std::string encode(const CaseResult& r) {
    return fmt::format("{}\t{}\t{}", to_string(r.verdict), to_string(r.failure), r.reason);
}

CaseResult decode(const std::string& line) {
    CaseResult r;
    const size_t a = line.find('\t');
    const size_t b = a == std::string::npos ? a : line.find('\t', a + 1);
    if (b == std::string::npos) {
        r.verdict = Verdict::failed;
        r.failure = Failure::crashed;
        r.reason = "unreadable answer from the child process";
        return r;
    }
    r.verdict = verdict_of(line.substr(0, a));
    r.failure = failure_of(line.substr(a + 1, b - a - 1));
    r.reason = line.substr(b + 1);
    return r;
}

const char* to_string(Verdict v) {
    switch (v) {
        case Verdict::ok: return "ok";
        case Verdict::refused: return "refused";
        case Verdict::failed: return "failed";
    }
    return "failed";
}

const char* to_string(Failure f) {
    switch (f) {
        case Failure::none: return "none";
        case Failure::reported: return "reported";
        case Failure::wrong: return "wrong";
        case Failure::nan: return "nan";
        case Failure::timed_out: return "timed_out";
        case Failure::crashed: return "crashed";
    }
    return "wrong";
}

}  // namespace vssw::stress
