#pragma once
// JSON as vssw writes it: keys in the order they were set (easier to read than sorted), and an absent quantity
// (e.g. Eq. 26 for a hinge at or below mid-height, a metric that could not be measured) as null.
#include <cmath>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace vssw::io {

using Json = nlohmann::ordered_json;

// The text of a JSON value, as every writer and message of vssw makes it (tests/json_writers.py keeps a bare
// dump() out of the code): a string that is not UTF-8 (a name from the file system may hold any byte) gets U+FFFD in
// place of each bad byte instead of throwing, which would end a command after its work was done. indent -1: one line.
template <class AnyJson>
std::string dump_json(const AnyJson& value, int indent = -1) {
    return value.dump(indent, ' ', false, AnyJson::error_handler_t::replace);
}

inline Json or_null(const std::optional<double>& value) { return value ? Json(*value) : Json(nullptr); }
// A number, or null when it is NaN or infinite (JSON has neither; a metric that could not be measured is NaN).
inline Json finite_or_null(double value) { return std::isfinite(value) ? Json(value) : Json(nullptr); }

}  // namespace vssw::io
