#include "validation/bounds_file.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "analytic/error.hpp"
#include "io/config_file.hpp"
#include "io/json.hpp"

namespace vssw::validation {
namespace {

using nlohmann::json;

constexpr const char* kWhat = "bounds file";  // in messages: "bounds file <path>: ..."

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
            throw InputError(fmt::format("{}: '{}' must be a non-empty string, got {}", where_, key, io::dump_json(v)));
        return v.get<std::string>();
    }
    double number(const char* key) const { return finite(required(key), key); }
    double non_negative(const char* key) const {
        const double x = number(key);
        if (x < 0.0) throw InputError(fmt::format("{}: '{}' must be >= 0, got {}", where_, key, x));
        return x;
    }
    // A non-empty list of names; `what` says what they name in messages ("case ids", "engine names", "verdicts").
    std::vector<std::string> texts(const char* key, const char* what = "case ids") const {
        const json& v = required(key);
        if (!v.is_array() || v.empty())
            throw InputError(
                fmt::format("{}: '{}' must be a non-empty list of {}, got {}", where_, key, what, io::dump_json(v)));
        std::vector<std::string> out;
        for (const json& x : v) {
            if (!x.is_string() || x.get<std::string>().empty())
                throw InputError(
                    fmt::format("{}: '{}' holds {}, not one of the {} it lists", where_, key, io::dump_json(x), what));
            out.push_back(x.get<std::string>());
        }
        return out;
    }
    std::pair<double, double> range(const char* key) const {
        const json& v = required(key);
        if (!v.is_array() || v.size() != 2)
            throw InputError(fmt::format("{}: '{}' must be [min, max], got {}", where_, key, io::dump_json(v)));
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
            throw InputError(fmt::format("{}: '{}' must be a finite number, got {}", where_, key, io::dump_json(v)));
        return v.get<double>();
    }

    const json& entry_;
    std::string where_;
};

// An [[earthquake]] entry: study (default "default"), engine, measure, and min, max or both.
EarthquakeBound earthquake_bound(const EntryReader& r) {
    static const std::vector<std::string> kMeasures = {"overturning_agreement", "fragility_median_ratio",
                                                       "peak_ratio_median", "inside_band"};
    EarthquakeBound b{r.has("study") ? r.text("study") : "default", r.text("engine"), r.text("measure"),
                               r.has("min") ? r.number("min") : -HUGE_VAL, r.has("max") ? r.number("max") : HUGE_VAL};
    if (b.engine == "analytic") throw InputError(r.where() + ": engine 'analytic' is the reference");
    if (std::find(kMeasures.begin(), kMeasures.end(), b.measure) == kMeasures.end())
        throw InputError(fmt::format("{}: measure '{}' is not one of {}", r.where(), b.measure, fmt::join(kMeasures, ", ")));
    if (!r.has("min") && !r.has("max")) throw InputError(r.where() + ": give 'min', 'max' or both");
    if (b.min > b.max) throw InputError(fmt::format("{}: min {} is above max {}", r.where(), b.min, b.max));
    return b;
}

const json& list_of_tables(const json& doc, const char* key, const std::string& name) {
    static const json kEmpty = json::array();
    if (!doc.contains(key)) return kEmpty;
    const json& v = doc.at(key);
    if (!v.is_array())
        throw InputError(fmt::format("bounds file {}: '{}' must be a list of tables ([[{}]] in TOML)", name, key, key));
    return v;
}

Bounds to_bounds(const json& doc, const std::string& name) {
    if (!doc.is_object()) throw InputError(fmt::format("bounds file {}: the top level must be a table", name));
    for (const auto& item : doc.items())
        if (item.key() != "suite" && item.key() != "analytic" && item.key() != "engine" && item.key() != "stress" &&
            item.key() != "earthquake")
            throw InputError(fmt::format(
                "bounds file {}: unknown key '{}' (known: suite, analytic, engine, stress, earthquake)", name,
                item.key()));
    Bounds bounds;
    if (doc.contains("suite")) {
        if (!doc["suite"].is_string())
            throw InputError(fmt::format("bounds file {}: 'suite' must be a string, got {}", name, io::dump_json(doc["suite"])));
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
        EngineBound b{r.text("engine"), r.texts("cases"), r.text("metric"), 0.0, 0.0};
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
    i = 0;
    for (const json& entry : list_of_tables(doc, "stress", name)) {
        const EntryReader r(entry, fmt::format("bounds file {}: stress bound #{}", name, ++i),
                            {"cases", "engines", "allowed"});
        StressBound b{r.texts("cases"),
                               r.has("engines") ? r.texts("engines", "engine names") : std::vector<std::string>{},
                               r.texts("allowed", "verdicts")};
        for (const std::string& v : b.allowed)
            if (v != "ok" && v != "refused" && v != "failed")
                throw InputError(fmt::format("{}: 'allowed' holds '{}', not a verdict (ok, refused, failed)", r.where(), v));
        bounds.stress.push_back(b);
    }
    i = 0;
    for (const json& entry : list_of_tables(doc, "earthquake", name))
        bounds.earthquake.push_back(
            earthquake_bound(EntryReader(entry, fmt::format("bounds file {}: earthquake bound #{}", name, ++i),
                                         {"study", "engine", "measure", "min", "max"})));
    if (bounds.analytic.empty() && bounds.engines.empty() && bounds.stress.empty() && bounds.earthquake.empty())
        throw InputError(fmt::format(
            "bounds file {}: no bounds ([[analytic]], [[engine]], [[stress]] or [[earthquake]] entries)", name));
    return bounds;
}

}  // namespace

Bounds parse_bounds(const std::string& text, const std::string& format, const std::string& name) {
    return to_bounds(io::parse_config(text, format, name, kWhat), name);
}

Bounds read_bounds_file(const std::string& path) {
    return to_bounds(io::read_config_file(path, kWhat), path);
}

}  // namespace vssw::validation
