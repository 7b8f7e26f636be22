#pragma once
// The known differences: a cross-engine test (Engines/CrossEngine.*) that a backend cannot pass, skipped with the
// measured values and the reason, never loosened per case (docs/contributing/tests.md). Each engine declares its own
// in its folder, multibody/<engine>/tests/known_differences.cpp, registered before main runs:
//
//   const bool registered = vssw::testing::register_known_differences({
//       {"foo", "VsswRestitution", "Foo resolves the landing ... Measured on the Fig. 6 wall: ..."},
//   });
//
// and the cross-engine suite finds them by backend and test, naming no engine.
#include <optional>
#include <string>
#include <vector>

namespace vssw::testing {

struct KnownDifference {
    std::string backend;  // as on the command line: "simbody-rigid"
    std::string test;     // a CrossEngine test's name without its backend, or the trait kCannotMoveSupports
    std::string reason;   // the skip's message: what was measured and why
};

// The trait of a backend that cannot move its supports (only pseudo-forces): it skips every moving-supports test.
inline const std::string kCannotMoveSupports = "MovingSupports";

// Adds the entries to the one list; returns true, for a namespace-scope constant that runs it before main.
bool register_known_differences(const std::vector<KnownDifference>& entries);

const std::vector<KnownDifference>& known_differences();

// The reason when `backend` has a known difference for `test`.
std::optional<std::string> known_difference(const std::string& backend, const std::string& test);

// The entries that skip nothing or say two things, one line each: a backend this project has no adapter for, a test
// that is neither one of `tests` nor the trait kCannotMoveSupports (a test renamed or removed leaves a stale skip),
// a backend and test listed twice.
std::vector<std::string> stale_known_differences(const std::vector<KnownDifference>& entries,
                                                 const std::vector<std::string>& backends,
                                                 const std::vector<std::string>& tests);

}  // namespace vssw::testing
