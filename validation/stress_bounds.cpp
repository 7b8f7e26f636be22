#include "validation/stress_bounds.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "multibody/engine.hpp"
#include "stress/case.hpp"
#include "stress/run.hpp"

namespace vssw::validation {
namespace {

void add_once(std::vector<std::string>& list, const std::string& item) {
    if (std::find(list.begin(), list.end(), item) == list.end()) list.push_back(item);
}

}  // namespace

stress::RunOptions plan_stress_bounds(const std::vector<StressBound>& bounds, const std::string& path,
                                      int threads) {
    const std::vector<std::string> available = multibody::available_engines();
    stress::RunOptions run;
    run.quick = true;
    run.time_limit_s = stress::kQuickTimeLimit;  // the verdicts `vssw stress --quick` gives
    run.threads = threads;
    for (const StressBound& b : bounds) {
        for (const std::string& id : b.case_ids) {
            if (stress::find_case(id) == nullptr)
                throw InputError(fmt::format("bounds file {}: no stress case '{}'", path, id));
            add_once(run.cases, id);
        }
        for (const std::string& e : b.engines.empty() ? available : b.engines) {
            if (std::find(available.begin(), available.end(), e) == available.end())
                throw InputError(fmt::format("bounds file {}: engine '{}' is not in this build (available: {})", path, e,
                                             fmt::join(available, ", ")));
            add_once(run.engines, e);
        }
    }
    return run;
}

std::vector<BoundVerdict> check_stress_bounds(const std::vector<StressBound>& bounds,
                                                       const stress::RunOptions& run) {
    if (bounds.empty()) return {};
    const std::vector<std::string> available = multibody::available_engines();
    const std::vector<stress::CaseResult> results = stress::run_cases(run);
    std::vector<BoundVerdict> verdicts;
    for (const StressBound& b : bounds)
        for (const std::string& id : b.case_ids)
            for (const std::string& e : b.engines.empty() ? available : b.engines) {
                const auto r = std::find_if(results.begin(), results.end(),
                                            [&](const stress::CaseResult& x) { return x.name == id && x.engine == e; });
                if (r == results.end())
                    throw std::logic_error(fmt::format("stress run gave no verdict for {} on {}", id, e));
                BoundVerdict v;
                v.engine = e;
                v.case_id = id;
                v.metric = "stress";
                v.value = v.lo = v.hi = NAN;
                v.allowed_label = fmt::format("{}", fmt::join(b.allowed, "|"));
                v.value_label = stress::to_string(r->verdict);
                if (r->verdict == stress::Verdict::failed) v.value_label += std::string(" (") + stress::to_string(r->failure) + ")";
                // A hang, a crash, NaN or a wrong answer never holds, whatever the file allows: "failed" there means a
                // failure the backend reports itself.
                v.held = !stress::is_unsafe(*r) &&
                         std::find(b.allowed.begin(), b.allowed.end(), stress::to_string(r->verdict)) != b.allowed.end();
                if (!v.held) v.note = r->reason;
                verdicts.push_back(v);
            }
    return verdicts;
}

}  // namespace vssw::validation
