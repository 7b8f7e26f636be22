#include "apps/bounds_file.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <toml++/toml.h>

#include "analytic/error.hpp"

namespace vssw::cli {
namespace {

using nlohmann::json;

// TOML is read into the JSON value it stands for, so that one validation serves both formats.
json toml_to_json(const std::string& text, const std::string& name) {
    // A TOML bounds file must be ASCII. toml++ 3.3 (Debian) has undefined behaviour on some non-ASCII characters
    // where whitespace may stand (its generated Unicode whitespace test reaches TOML_UNREACHABLE for e.g. U+0237 at
    // the start of a line; found by tests/fuzz/fuzz_bounds_file.cpp under UBSan). Telling those places from strings
    // and comments would mean lexing TOML ourselves; everything the schema holds (keys, case ids, metrics, numbers)
    // is ASCII, so only non-ASCII comments are lost.
    const auto non_ascii =
        std::find_if(text.begin(), text.end(), [](char c) { return (static_cast<unsigned char>(c) & 0x80) != 0; });
    if (non_ascii != text.end()) {
        const auto line = 1 + std::count(text.begin(), non_ascii, '\n');
        throw InputError(fmt::format("bounds file {}: line {}: a non-ASCII character (byte 0x{:02X}); TOML "
                                     "bounds files must be ASCII",
                                     name, line, static_cast<unsigned char>(*non_ascii)));
    }
    toml::table table;
    try {
        table = toml::parse(text, name);
    } catch (const toml::parse_error& e) {
        const auto& where = e.source().begin;
        throw InputError(fmt::format("bounds file {}: TOML syntax error at line {}, column {}: {}", name, where.line,
                                     where.column, e.description()));
    }
    std::ostringstream text_json;
    text_json << toml::json_formatter{table};
    return json::parse(text_json.str());
}

// Deepest nesting of arrays and objects a JSON bounds file may have: the schema needs 4 (top table, list of bounds,
// bound, list of cases); 256 is toml++'s own limit for TOML (TOML_MAX_NESTED_VALUES), so both formats refuse the
// same. Without a limit, a value nested some 10^5 deep (found by the fuzz harness tests/fuzz/fuzz_bounds_file.cpp)
// overflowed the stack in nlohmann's recursive dump() when the error message quoted it.
constexpr int kMaxJsonNesting = 256;

json parse_json(const std::string& text, const std::string& name) {
    // A key given twice in one object would silently take the last value (TOML refuses it): refuse it too.
    std::vector<std::set<std::string>> keys;  // per open object
    std::string duplicate;
    int depth = 0;
    bool too_deep = false;
    const json::parser_callback_t no_duplicates = [&](int, json::parse_event_t event, json& parsed) {
        if (event == json::parse_event_t::object_start || event == json::parse_event_t::array_start)
            too_deep |= ++depth > kMaxJsonNesting;
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
        throw InputError(fmt::format("bounds file {}: JSON syntax error: {}", name, e.what()));
    } catch (const json::exception& e) {  // e.g. a number too large for a double
        throw InputError(fmt::format("bounds file {}: JSON error: {}", name, e.what()));
    }
    if (too_deep)
        throw InputError(fmt::format("bounds file {}: arrays and objects nested deeper than {} levels", name,
                                     kMaxJsonNesting));
    if (!duplicate.empty()) throw InputError(fmt::format("bounds file {}: key '{}' given twice in one table", name, duplicate));
    return doc;
}

class EntryReader {
public:
    EntryReader(const json& entry, std::string where, std::set<std::string> known)
        : entry_(entry), where_(std::move(where)) {
        if (!entry_.is_object()) throw InputError(where_ + ": must be a table of keys");
        for (const auto& item : entry_.items())
            if (known.count(item.key()) == 0)
                throw InputError(fmt::format("{}: unknown key '{}' (known: {})", where_, item.key(),
                                             fmt::join(known, ", ")));
    }
    bool has(const char* key) const { return entry_.contains(key); }
    std::string text(const char* key) const {
        const json& v = required(key);
        if (!v.is_string() || v.get<std::string>().empty())
            throw InputError(fmt::format("{}: '{}' must be a non-empty string, got {}", where_, key, v.dump()));
        return v.get<std::string>();
    }
    double number(const char* key) const { return finite(required(key), key); }
    double non_negative(const char* key) const {
        const double x = number(key);
        if (x < 0.0) throw InputError(fmt::format("{}: '{}' must be >= 0, got {}", where_, key, x));
        return x;
    }
    std::vector<std::string> texts(const char* key) const {
        const json& v = required(key);
        if (!v.is_array() || v.empty())
            throw InputError(fmt::format("{}: '{}' must be a non-empty list of case ids, got {}", where_, key, v.dump()));
        std::vector<std::string> out;
        for (const json& x : v) {
            if (!x.is_string() || x.get<std::string>().empty())
                throw InputError(fmt::format("{}: '{}' holds {}, not a case id", where_, key, x.dump()));
            out.push_back(x.get<std::string>());
        }
        return out;
    }
    std::pair<double, double> range(const char* key) const {
        const json& v = required(key);
        if (!v.is_array() || v.size() != 2)
            throw InputError(fmt::format("{}: '{}' must be [min, max], got {}", where_, key, v.dump()));
        const double lo = finite(v[0], key), hi = finite(v[1], key);
        if (lo > hi) throw InputError(fmt::format("{}: '{}' = [{}, {}] has min > max", where_, key, lo, hi));
        return {lo, hi};
    }
    const std::string& where() const { return where_; }

private:
    const json& required(const char* key) const {
        if (!entry_.contains(key)) throw InputError(fmt::format("{}: '{}' is missing", where_, key));
        return entry_.at(key);
    }
    double finite(const json& v, const char* key) const {
        // JSON has no NaN; TOML's nan and inf come through the JSON formatter as strings or non-numbers.
        if (!v.is_number() || !std::isfinite(v.get<double>()))
            throw InputError(fmt::format("{}: '{}' must be a finite number, got {}", where_, key, v.dump()));
        return v.get<double>();
    }

    const json& entry_;
    std::string where_;
};

const json& list_of_tables(const json& doc, const char* key, const std::string& name) {
    static const json kEmpty = json::array();
    if (!doc.contains(key)) return kEmpty;
    const json& v = doc.at(key);
    if (!v.is_array())
        throw InputError(fmt::format("bounds file {}: '{}' must be a list of tables ([[{}]] in TOML)", name, key, key));
    return v;
}

compare::Bounds to_bounds(const json& doc, const std::string& name) {
    if (!doc.is_object()) throw InputError(fmt::format("bounds file {}: the top level must be a table", name));
    for (const auto& item : doc.items())
        if (item.key() != "suite" && item.key() != "analytic" && item.key() != "engine")
            throw InputError(
                fmt::format("bounds file {}: unknown key '{}' (known: suite, analytic, engine)", name, item.key()));
    compare::Bounds bounds;
    if (doc.contains("suite")) {
        if (!doc["suite"].is_string())
            throw InputError(fmt::format("bounds file {}: 'suite' must be a string, got {}", name, doc["suite"].dump()));
        bounds.suite = doc["suite"].get<std::string>();
    }
    int i = 0;
    for (const json& entry : list_of_tables(doc, "analytic", name)) {
        const EntryReader r(entry, fmt::format("bounds file {}: analytic bound #{}", name, ++i),
                            {"case", "metric", "reference", "max_drift"});
        bounds.analytic.push_back({r.text("case"), r.text("metric"), r.number("reference"), r.non_negative("max_drift")});
    }
    i = 0;
    for (const json& entry : list_of_tables(doc, "engine", name)) {
        const EntryReader r(entry, fmt::format("bounds file {}: engine bound #{}", name, ++i),
                            {"engine", "cases", "metric", "max_error", "error"});
        compare::EngineBound b{r.text("engine"), r.texts("cases"), r.text("metric"), 0.0, 0.0};
        if (b.engine == "analytic")
            throw InputError(r.where() + ": engine 'analytic' is the reference; bound its drift in [[analytic]]");
        std::set<std::string> seen;
        for (const std::string& id : b.case_ids)
            if (!seen.insert(id).second)
                throw InputError(fmt::format("{}: 'cases' names a case twice: '{}'", r.where(), id));
        if (r.has("max_error") == r.has("error"))
            throw InputError(r.where() + ": give exactly one of 'max_error' (|rel_error| <= x) and 'error' ([min, max])");
        if (r.has("max_error")) {
            b.max_error = r.non_negative("max_error");
            b.min_error = -b.max_error;
        } else {
            std::tie(b.min_error, b.max_error) = r.range("error");
        }
        bounds.engines.push_back(b);
    }
    if (bounds.analytic.empty() && bounds.engines.empty())
        throw InputError(fmt::format("bounds file {}: no bounds ([[analytic]] or [[engine]] entries)", name));
    return bounds;
}

std::string extension_format(const std::string& path) {
    const auto ends_with = [&](const std::string& suffix) {
        return path.size() >= suffix.size() && path.compare(path.size() - suffix.size(), suffix.size(), suffix) == 0;
    };
    if (ends_with(".toml")) return "toml";
    if (ends_with(".json")) return "json";
    throw InputError(fmt::format("bounds file {}: the name must end in .toml or .json (the format)", path));
}

}  // namespace

compare::Bounds parse_bounds(const std::string& text, const std::string& format, const std::string& name) {
    if (format == "toml") return to_bounds(toml_to_json(text, name), name);
    if (format == "json") return to_bounds(parse_json(text, name), name);
    throw InputError(fmt::format("bounds format '{}': toml or json", format));
}

compare::Bounds read_bounds_file(const std::string& path) {
    const std::string format = extension_format(path);
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw InputError(fmt::format("bounds file {}: no such file (or not a regular file)", path));
    std::ifstream in(path);
    if (!in) throw InputError(fmt::format("bounds file {}: cannot be read (missing or not readable)", path));
    std::ostringstream text;
    text << in.rdbuf();
    return parse_bounds(text.str(), format, path);
}

}  // namespace vssw::cli
