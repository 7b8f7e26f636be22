// Fuzz harness of the ground-motion record reader (analytic/ground_motion.hpp, parse_record = read_record on text):
// PEER AT2 in both header styles and two-column text, chosen by content as for a file; and each input again as
// accelerations alone at a step and as a table with named columns (RecordFormat).
//
// A normal outcome is a record or vssw::InputError (the documented refusal). A finding is anything else: another
// exception type (reported here, then abort), a crash or sanitizer report, a hang, or a record that breaks the
// GroundMotion contract (checked below: the reader promised finite, strictly increasing samples, and the
// interpolation must pass through them).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <typeinfo>

#include "analytic/error.hpp"
#include "analytic/ground_motion.hpp"

namespace {

// The interpolant between two samples a, b is (1 - w) a + w b: within [min, max] up to a few roundings of the
// larger magnitude. 1e-12 is far above those (~1e-16) and far below any wrong bracket (a whole sample off).
constexpr double kInterpolationTolerance = 1e-12;

[[noreturn]] void finding(const char* what, std::size_t sample) {
    std::fprintf(stderr, "fuzz_ground_motion: FINDING: %s (sample %zu)\n", what, sample);
    std::abort();
}

void check_record(const vssw::GroundMotion& m) {
    const auto& t = m.sample_times();
    const auto& a = m.sample_values();
    if (t.size() < 2 || t.size() != a.size()) finding("a record with fewer than 2 samples or unequal lengths", 0);
    if (!(m.duration() == t.back())) finding("duration is not the last sample time", t.size() - 1);
    if (!std::isfinite(m.pga())) finding("non-finite PGA", 0);
    for (std::size_t i = 0; i < t.size(); ++i) {
        if (!std::isfinite(t[i]) || !std::isfinite(a[i]) || t[i] < 0.0) finding("non-finite or negative sample", i);
        if (i > 0 && !(t[i] > t[i - 1])) finding("sample times not strictly increasing", i);
        const double at_sample = m(t[i]);
        if (std::abs(at_sample - a[i]) > kInterpolationTolerance * std::abs(a[i]))
            finding("the record does not pass through its sample", i);
        if (i == 0) continue;
        // Midpoint: between the two bracketing samples (a wrong bracket extrapolates from other samples).
        const double mid = t[i - 1] + 0.5 * (t[i] - t[i - 1]);
        const double v = m(mid);
        const double lo = std::min(a[i - 1], a[i]), hi = std::max(a[i - 1], a[i]);
        const double slack = kInterpolationTolerance * std::max(std::abs(lo), std::abs(hi));
        if (!(v >= lo - slack && v <= hi + slack)) finding("interpolation outside its bracketing samples", i);
    }
    if (m(-1.0) != 0.0 || m(t.back() * 2.0 + 1.0) != 0.0) finding("non-zero outside the record", 0);
}

void parse(const std::string& text, const vssw::AccelUnits* units, const vssw::RecordFormat& format = {}) {
    try {
        check_record(vssw::parse_record(text, "fuzz-input", units, format));
    } catch (const vssw::InputError&) {
        // The documented refusal of a bad file: a normal outcome.
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fuzz_ground_motion: FINDING: exception %s: %s\n", typeid(e).name(), e.what());
        std::abort();
    }
    // Anything not derived from std::exception escapes and terminates: a finding too.
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    parse(text, nullptr);  // units from the AT2 header, g for two columns
    // Explicit units: the override path of the AT2 reader (it skips the header's unit word) and the cm/s2 factor.
    const vssw::AccelUnits cm = vssw::AccelUnits::cm_per_s2;
    parse(text, &cm);
    // The other formats (RecordFormat): accelerations alone at a step, and a table with named columns, with a step.
    vssw::RecordFormat step;
    step.dt = 0.01;
    parse(text, nullptr, step);
    vssw::RecordFormat named;
    named.time_column = "t";
    named.accel_column = "a";
    parse(text, nullptr, named);
    vssw::RecordFormat named_at_step;
    named_at_step.dt = 0.02;
    named_at_step.accel_column = "a";
    parse(text, nullptr, named_at_step);
    return 0;
}
