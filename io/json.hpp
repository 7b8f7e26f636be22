#pragma once
// JSON as vssw writes it: keys in the order they were set (easier to read than sorted), and an absent quantity
// (e.g. Eq. 26 for a hinge at or below mid-height, a metric that could not be measured) as null.
#include <cmath>
#include <optional>

#include <nlohmann/json.hpp>

namespace vssw::study {

using Json = nlohmann::ordered_json;

inline Json or_null(const std::optional<double>& value) { return value ? Json(*value) : Json(nullptr); }
// A number, or null when it is NaN or infinite (JSON has neither; a metric that could not be measured is NaN).
inline Json finite_or_null(double value) { return std::isfinite(value) ? Json(value) : Json(nullptr); }

}  // namespace vssw::study
