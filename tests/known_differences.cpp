// The one list of known differences, filled by each engine folder's multibody/<engine>/tests/known_differences.cpp.
#include "tests/known_differences.hpp"

#include <algorithm>
#include <set>
#include <utility>

namespace vssw::testing {
namespace {

// A function's static, so that it exists before any file's registration runs, whatever the order of their statics.
std::vector<KnownDifference>& entries_list() {
    static std::vector<KnownDifference> list;
    return list;
}

bool contains(const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

bool register_known_differences(const std::vector<KnownDifference>& entries) {
    entries_list().insert(entries_list().end(), entries.begin(), entries.end());
    return true;
}

const std::vector<KnownDifference>& known_differences() { return entries_list(); }

std::optional<std::string> known_difference(const std::string& backend, const std::string& test) {
    for (const KnownDifference& d : entries_list())
        if (d.backend == backend && d.test == test) return d.reason;
    return std::nullopt;
}

std::vector<std::string> stale_known_differences(const std::vector<KnownDifference>& entries,
                                                 const std::vector<std::string>& backends,
                                                 const std::vector<std::string>& tests) {
    std::vector<std::string> stale;
    std::set<std::pair<std::string, std::string>> seen;
    for (const KnownDifference& d : entries) {
        const std::string key = d.backend + "/" + d.test;
        if (!contains(backends, d.backend)) stale.push_back(key + ": no backend is named " + d.backend);
        if (d.test != kCannotMoveSupports && !contains(tests, d.test))
            stale.push_back(key + ": no cross-engine test is named " + d.test);
        if (!seen.insert({d.backend, d.test}).second) stale.push_back(key + ": listed twice");
    }
    return stale;
}

}  // namespace vssw::testing
