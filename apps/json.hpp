#pragma once
// JSON as the commands write it: keys in the order they were set (easier to read than sorted), and an absent
// quantity (e.g. Eq. 26 for a hinge at or below mid-height) as null.
#include <optional>

#include <nlohmann/json.hpp>

namespace vssw::cli {

using Json = nlohmann::ordered_json;

inline Json or_null(const std::optional<double>& value) { return value ? Json(*value) : Json(nullptr); }

}  // namespace vssw::cli
