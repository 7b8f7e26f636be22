#pragma once
// A shipped study run by the report for the report's engines (the earthquake part, the assumptions part).
#include <string>
#include <vector>

#include "study/spec.hpp"

namespace vssw::validation {

// The study file with its engines replaced by the analytic model (the reference) and the report's; the settings it
// gives engines that are not run are dropped (the report chooses the engines, at the file's settings for those it
// names).
study::StudySpec with_engines(const std::string& file, const std::vector<std::string>& engines);

}  // namespace vssw::validation
