#include "stress/run.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "compare/task_pool.hpp"
#include "multibody/engine.hpp"
#include "stress/case.hpp"
#include "stress/judge.hpp"

namespace vssw::stress {

using multibody::ChildEnd;
using multibody::ChildResult;

CaseResult result_of(const ChildResult& child, const std::string& name, const std::string& engine) {
    CaseResult r;
    if (child.end == ChildEnd::completed) {
        r = decode(child.output);
    } else {
        r.verdict = Verdict::failed;
        r.failure = child.end == ChildEnd::timed_out ? Failure::timed_out
                    : child.end == ChildEnd::threw   ? Failure::reported
                                                     : Failure::crashed;
        r.reason = multibody::describe_failure(child);
    }
    r.name = name;
    r.engine = engine;
    r.time_s = child.time_s;
    return r;
}

const Case& require_case(const std::string& name) {
    const Case* c = find_case(name);
    if (c == nullptr) {
        std::vector<std::string> names;
        for (const Case& k : all_cases()) names.push_back(k.name);
        throw InputError(fmt::format("no stress case '{}' (cases: {})", name, fmt::join(names, ", ")));
    }
    return *c;
}

std::vector<CaseResult> run_cases(const RunOptions& o) {
    std::vector<const Case*> chosen;
    for (const std::string& name : o.cases) chosen.push_back(&require_case(name));
    if (o.cases.empty())
        for (const Case& c : all_cases())
            if (!o.quick || c.quick) chosen.push_back(&c);
    const std::vector<std::string> available = multibody::available_engines();
    for (const std::string& e : o.engines)
        if (std::find(available.begin(), available.end(), e) == available.end())
            throw InputError(fmt::format("engine '{}' is not available in this build (available: {})", e,
                                         fmt::join(available, ", ")));
    std::vector<std::pair<const Case*, std::string>> runs;
    for (const Case* c : chosen)
        for (const std::string& e : o.engines) runs.emplace_back(c, e);
    std::vector<CaseResult> results(runs.size());
    // Every child is a process of its own, so no engine's library state is shared: no exclusive groups. The order is
    // the list's (equal costs).
    std::vector<compare::PoolTask> tasks(runs.size());
    compare::run_pool(tasks, {false}, o.threads, [&](std::size_t i) {
        const auto& [c, engine] = runs[i];
        const bool quick = o.quick;
        const ChildResult child =
            multibody::run_in_child([c = c, engine = engine, quick] { return encode(judge(*c, engine, quick)); },
                                    o.time_limit_s);
        results[i] = result_of(child, c->name, engine);
    });
    return results;
}

}  // namespace vssw::stress
