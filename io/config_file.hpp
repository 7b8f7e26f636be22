#pragma once
// Reading a configuration file written by people (a study file, a bounds file): TOML or JSON, told apart by the
// file's extension, read into the one JSON value it stands for so that one validation serves both formats.
//
// Refused with an InputError naming the file (`what` says which kind, e.g. "study file"): a missing or non-regular
// file, a name not ending in .toml or .json, a syntax error (with its line and column for TOML), a non-ASCII TOML file
// (toml++ 3.3 has undefined behaviour on some non-ASCII characters; found by fuzzing), a JSON key given twice in one
// object (TOML refuses that itself), and arrays or objects nested deeper than kMaxConfigNesting.
#include <string>

#include <nlohmann/json.hpp>

namespace vssw::io {

// The deepest nesting of arrays and objects a configuration may have. The schemas need 4; 256 is toml++'s own limit
// for TOML (TOML_MAX_NESTED_VALUES), so both formats refuse the same. Without a limit, a value nested some 10^5 deep
// (found by tests/fuzz/fuzz_bounds_file.cpp) overflowed the stack in nlohmann's recursive dump().
constexpr int kMaxConfigNesting = 256;

// "toml" or "json" from the path's extension; InputError "<what> <path>: the name must end in .toml or .json".
std::string config_format(const std::string& path, const std::string& what);
// The text of `format` ("toml" or "json") as JSON; `name` and `what` are used in messages.
nlohmann::json parse_config(const std::string& text, const std::string& format, const std::string& name,
                            const std::string& what);
// config_format + reading the file + parse_config.
nlohmann::json read_config_file(const std::string& path, const std::string& what);

}  // namespace vssw::io
