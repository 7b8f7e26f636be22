#pragma once
// The verdict of one stress case on one backend, and what makes a run of `vssw stress` fail.
#include <string>

namespace vssw::stress {

enum class Verdict { ok, refused, failed };

// Why a case failed. `reported`: the backend said so itself (EngineFailure, the analytic model's energy balance or
// step limit) - an honest answer. The others are what stress testing is for: a hang (timed_out), a crash, NaN in
// the output, or a result that contradicts the analytic model where the case has a known answer (wrong).
enum class Failure { none, reported, wrong, nan, timed_out, crashed };

struct CaseResult {
    std::string name;    // the case
    std::string engine;
    Verdict verdict = Verdict::ok;
    Failure failure = Failure::none;
    std::string reason;  // why refused or failed; for ok, what was checked
    double time_s = 0.0; // wall time of the child process
};

const char* to_string(Verdict v);
const char* to_string(Failure f);
// A hang, a crash, NaN or a wrong answer: `vssw stress` exits non-zero when any case has one.
inline bool is_unsafe(const CaseResult& r) {
    return r.failure == Failure::wrong || r.failure == Failure::nan || r.failure == Failure::timed_out ||
           r.failure == Failure::crashed;
}

}  // namespace vssw::stress
