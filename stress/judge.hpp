#pragma once
// One stress case on one backend, in this process: builds the run, simulates, and judges the result (case.hpp's
// checks). run.hpp calls it inside a child process; the tests may call it directly.
#include <string>

#include "stress/case.hpp"
#include "stress/verdict.hpp"

namespace vssw::stress {

// Never throws for anything the case or the backend does: a refusal (InputError) or a failure (EngineFailure, the
// integrator's own std::runtime_error) becomes the verdict. time_s is left 0.
CaseResult judge(const Case& c, const std::string& engine, bool quick);

// The verdict as one line for the pipe, and back (run.hpp).
std::string encode(const CaseResult& r);
CaseResult decode(const std::string& line);

}  // namespace vssw::stress
