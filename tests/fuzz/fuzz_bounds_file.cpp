// Fuzz harness of the bounds-file reader of `vssw check` (validation/bounds_file.hpp, parse_bounds = read_bounds_file
// on text): every input is read as TOML and as JSON.
//
// A normal outcome is a set of bounds or vssw::InputError, the only error the reader documents for bad files
// (syntax errors of toml++ and nlohmann::json are turned into it). A finding is anything else: another exception
// type (a toml++ or nlohmann exception that got through; reported here, then abort), a crash or sanitizer report, a
// hang, or bounds that break the reader's promises (checked below: finite numbers, non-negative drift, min <= max,
// at least one bound).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <typeinfo>

#include "analytic/error.hpp"
#include "validation/bounds_file.hpp"

namespace {

[[noreturn]] void finding(const char* format, const char* what) {
    std::fprintf(stderr, "fuzz_bounds_file: FINDING (%s): %s\n", format, what);
    std::abort();
}

void check_bounds(const vssw::validation::Bounds& b, const char* format) {
    if (b.analytic.empty() && b.engines.empty() && b.stress.empty() && b.earthquake.empty())
        finding(format, "bounds without an entry");
    for (const auto& q : b.earthquake) {
        if (q.engine.empty() || q.engine == "analytic" || q.study.empty()) finding(format, "earthquake bound incomplete");
        if (q.measure != "overturning_agreement" && q.measure != "fragility_median_ratio" &&
            q.measure != "peak_ratio_median" && q.measure != "inside_band")
            finding(format, "earthquake bound with an unknown measure");
        if (std::isnan(q.min) || std::isnan(q.max) || q.min > q.max || (std::isinf(q.min) && std::isinf(q.max)))
            finding(format, "earthquake bound with a bad interval");
    }
    for (const auto& st : b.stress) {
        if (st.case_ids.empty() || st.allowed.empty()) finding(format, "stress bound without cases or verdicts");
        for (const auto& v : st.allowed)
            if (v != "ok" && v != "refused" && v != "failed") finding(format, "stress bound with an unknown verdict");
    }
    for (const auto& a : b.analytic) {
        if (a.case_id.empty() || a.metric.empty()) finding(format, "analytic bound with an empty case or metric");
        if (!std::isfinite(a.reference) || !std::isfinite(a.max_drift) || a.max_drift < 0.0)
            finding(format, "analytic bound with a non-finite reference or a bad drift");
    }
    for (const auto& e : b.engines) {
        if (e.engine.empty() || e.metric.empty() || e.case_ids.empty()) finding(format, "engine bound incomplete");
        if (!std::isfinite(e.min_error) || !std::isfinite(e.max_error) || e.min_error > e.max_error)
            finding(format, "engine bound with a bad error interval");
    }
}

void parse(const std::string& text, const char* format) {
    try {
        check_bounds(vssw::validation::parse_bounds(text, format, "fuzz-input"), format);
    } catch (const vssw::InputError&) {
        // The documented refusal of a bad file: a normal outcome.
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fuzz_bounds_file: FINDING (%s): exception %s: %s\n", format, typeid(e).name(),
                     e.what());
        std::abort();
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    parse(text, "toml");
    parse(text, "json");
    return 0;
}
