// Fuzz harness of the study-file reader of `vssw study` (study/spec.hpp): every input is parsed as TOML and as JSON
// (parse_config, what read_study_file does after reading the file) and checked as a study (study_from_json).
//
// The entry point is study_from_json, the smallest that parses and validates a whole study file without running
// anything: it checks every key, type, list, engine, metric and part. The checks made later, when the grid is built
// (study/grid.hpp: the walls' ranges, the records read from disk, each engine's knobs by name, the grid's size),
// need the engines and the file system and are left to the property test of the program
// (tests/cli/test_cli_properties.py), which runs `vssw study` on random files.
//
// A normal outcome is a StudySpec or vssw::InputError, the only error the reader documents for bad files. A finding is
// anything else: another exception type (a toml++ or nlohmann exception that got through, e.g. a type_error from a
// get<> on the wrong type; reported here, then abort), a crash or sanitizer report, a hang, or a study that breaks the
// reader's promises (checked below: a name, at least one part, engine and metric, every list non-empty with each value
// once, every number finite).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <optional>
#include <set>
#include <string>
#include <typeinfo>
#include <variant>
#include <vector>

#include "analytic/error.hpp"
#include "io/config_file.hpp"
#include "multibody/host/engine_names.hpp"
#include "study/metric_catalog.hpp"
#include "study/spec.hpp"

// Every backend the reader knows, as in a build with all of them (multibody/host/registry.cpp's list): the harness links
// no engine (registry.cpp would pull in every adapter and its library), and with all names available the reader's
// paths for each engine's settings are reachable from any build. An engine missing from a real build is refused by
// the same check with a shorter list.
namespace vssw::multibody {
std::vector<std::string> available_engines() {
    return {"analytic", "bullet", "ode", "simbody", "simbody-rigid", "siconos"};
}
// A name is known as written (the registry's other spellings are tested with it, tests/test_cli.cpp).
std::optional<std::string> canonical_engine(const std::string& name) {
    for (const std::string& known : available_engines())
        if (name == known) return name;
    return std::nullopt;
}
// No suggestion for a name that is none of them (the registry's own is tested with it, tests/test_cli.cpp).
std::string engine_name_hint(const std::string&) { return ""; }
}  // namespace vssw::multibody

namespace {

using vssw::study::Axis;
using vssw::study::Level;

[[noreturn]] void finding(const char* format, const char* what) {
    std::fprintf(stderr, "fuzz_study_file: FINDING (%s): %s\n", format, what);
    std::abort();
}

void check_axis(const Axis& a, const char* format) {
    if (a.key.empty()) finding(format, "an axis without a key");
    if (a.levels.empty()) finding(format, "an axis without levels");
    for (std::size_t i = 0; i < a.levels.size(); ++i) {
        if (const double* x = std::get_if<double>(&a.levels[i]); x && !std::isfinite(*x))
            finding(format, "a non-finite level");
        for (std::size_t j = 0; j < i; ++j)
            if (a.levels[i] == a.levels[j]) finding(format, "a level listed twice");
    }
}

void check_engines(const std::vector<vssw::study::EngineSpec>& engines, const char* format) {
    if (engines.empty()) finding(format, "no engine");
    std::set<std::string> names;
    for (const auto& e : engines) {
        if (!names.insert(e.name).second) finding(format, "an engine named twice");
        std::set<std::string> keys;
        for (const Axis& a : e.settings) {
            check_axis(a, format);
            if (!keys.insert(a.key).second) finding(format, "an engine setting given twice");
        }
    }
}

// The metric's entry; a name the catalogue does not know is a finding here (the reader must have refused it), not the
// InputError metric_info throws, which parse() would take for a normal refusal.
const vssw::compare::MetricInfo& known_metric(const std::string& name, const char* format) {
    for (const auto& m : vssw::study::metric_catalog())
        if (name == m.name) return m;
    finding(format, "a metric the catalogue does not know");
}

void check_study(const vssw::study::StudySpec& s, const char* format) {
    if (s.name.empty()) finding(format, "a study without a name");
    if (s.parts.empty()) finding(format, "a study without a part");
    if (s.metrics.empty()) finding(format, "a study without a metric");
    if (s.assumptions.size() != vssw::study::kAssumptionKeys.size()) finding(format, "assumptions not all defaulted");
    for (const Axis& a : s.assumptions) check_axis(a, format);
    check_engines(s.engines, format);
    std::set<std::string> metrics;
    for (const std::string& m : s.metrics) {
        if (!metrics.insert(m).second) finding(format, "a metric named twice");
        (void)known_metric(m, format);
    }
    for (const auto& p : s.parts) {
        if (p.wall.empty()) finding(format, "a part without a wall");
        if (p.metrics.empty()) finding(format, "a part that measures nothing");
        for (const std::string& m : p.metrics)
            if (!vssw::study::kind_measures(p.kind, known_metric(m, format)))
                finding(format, "a part measuring a metric its excitation cannot give");
        for (const Axis& a : p.wall) check_axis(a, format);
        for (const Axis& a : p.excitation) check_axis(a, format);
        check_engines(p.engines, format);
    }
}

void parse(const std::string& text, const char* format) {
    const std::string name = std::string("fuzz-input.") + format;
    bool parsed = false;
    try {
        const nlohmann::json doc = vssw::io::parse_config(text, format, name, "study file");
        parsed = true;
        check_study(vssw::study::study_from_json(doc, name, "."), format);
    } catch (const vssw::InputError&) {
        // The documented refusal of a bad file: a normal outcome.
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fuzz_study_file: FINDING (%s, %s): exception %s: %s\n", format,
                     parsed ? "study_from_json" : "parse_config", typeid(e).name(), e.what());
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
