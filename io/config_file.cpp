#include "io/config_file.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <vector>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "analytic/error.hpp"
#include "analytic/input_file.hpp"

namespace vssw::io {
namespace {

using nlohmann::json;

json toml_to_json(const std::string& text, const std::string& name, const std::string& what) {
    // ASCII only: toml++ 3.3 (Debian) reaches TOML_UNREACHABLE on some non-ASCII characters where whitespace may
    // stand (e.g. U+0237 at the start of a line; found under UBSan). Telling those places from strings and comments
    // would mean lexing TOML ourselves; every key and value of our schemas is ASCII, so only non-ASCII comments are
    // lost.
    const auto non_ascii =
        std::find_if(text.begin(), text.end(), [](char c) { return (static_cast<unsigned char>(c) & 0x80) != 0; });
    if (non_ascii != text.end()) {
        const auto line = 1 + std::count(text.begin(), non_ascii, '\n');
        throw InputError(fmt::format("{} {}: line {}: a non-ASCII character (byte 0x{:02X}); TOML {}s must be ASCII",
                                     what, name, line, static_cast<unsigned char>(*non_ascii), what));
    }
    toml::table table;
    try {
        table = toml::parse(text, name);
    } catch (const toml::parse_error& e) {
        const auto& where = e.source().begin;
        throw InputError(fmt::format("{} {}: TOML syntax error at line {}, column {}: {}", what, name, where.line,
                                     where.column, e.description()));
    }
    std::ostringstream text_json;
    text_json << toml::json_formatter{table};
    return json::parse(text_json.str());
}

json json_without_duplicates(const std::string& text, const std::string& name, const std::string& what) {
    // A key given twice in one object would silently take the last value (TOML refuses it): refuse it too.
    std::vector<std::set<std::string>> keys;  // per open object
    std::string duplicate;
    int depth = 0;
    bool too_deep = false;
    const json::parser_callback_t no_duplicates = [&](int, json::parse_event_t event, json& parsed) {
        if (event == json::parse_event_t::object_start || event == json::parse_event_t::array_start)
            too_deep |= ++depth > kMaxConfigNesting;
        if (event == json::parse_event_t::object_end || event == json::parse_event_t::array_end) --depth;
        if (event == json::parse_event_t::object_start) keys.emplace_back();
        if (event == json::parse_event_t::object_end && !keys.empty()) keys.pop_back();
        if (event == json::parse_event_t::key && !keys.empty() && !keys.back().insert(parsed.get<std::string>()).second)
            duplicate = parsed.get<std::string>();
        return true;
    };
    json doc;
    try {
        doc = json::parse(text, no_duplicates);
    } catch (const json::parse_error& e) {
        throw InputError(fmt::format("{} {}: JSON syntax error: {}", what, name, e.what()));
    } catch (const json::exception& e) {  // e.g. a number too large for a double
        throw InputError(fmt::format("{} {}: JSON error: {}", what, name, e.what()));
    }
    if (too_deep)
        throw InputError(fmt::format("{} {}: arrays and objects nested deeper than {} levels", what, name,
                                     kMaxConfigNesting));
    if (!duplicate.empty())
        throw InputError(fmt::format("{} {}: key '{}' given twice in one table", what, name, duplicate));
    return doc;
}

}  // namespace

std::string config_format(const std::string& path, const std::string& what) {
    const auto ends_with = [&](const std::string& suffix) {
        return path.size() >= suffix.size() && path.compare(path.size() - suffix.size(), suffix.size(), suffix) == 0;
    };
    if (ends_with(".toml")) return "toml";
    if (ends_with(".json")) return "json";
    throw InputError(fmt::format("{} {}: the name must end in .toml or .json (the format)", what, path));
}

json parse_config(const std::string& text, const std::string& format, const std::string& name,
                  const std::string& what) {
    if (format == "toml") return toml_to_json(text, name, what);
    if (format == "json") return json_without_duplicates(text, name, what);
    throw InputError(fmt::format("{} format '{}': toml or json", what, format));
}

json read_config_file(const std::string& path, const std::string& what) {
    const std::string format = config_format(path, what);
    return parse_config(read_input_file(path, what, kMaxTextFileBytes), format, path, what);
}

}  // namespace vssw::io
