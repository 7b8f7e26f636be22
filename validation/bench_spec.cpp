#include "validation/bench_spec.hpp"

#include <cstdlib>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "vssw_engine_facts.hpp"  // each engine's BENCH text (generated: cmake/engines.cmake)

namespace vssw::validation {
namespace {

struct Axis {
    std::string name;
    std::vector<double> values;
};

std::string_view trimmed(std::string_view s) {
    while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
    while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
    return s;
}

std::vector<std::string_view> split(std::string_view s, char separator) {
    std::vector<std::string_view> parts;
    for (std::size_t at = s.find(separator); at != std::string_view::npos; at = s.find(separator)) {
        parts.push_back(s.substr(0, at));
        s.remove_prefix(at + 1);
    }
    parts.push_back(s);
    return parts;
}

[[noreturn]] void refuse(std::string_view spec, std::string_view why) {
    throw std::logic_error(fmt::format("the bench sweep '{}' of an engine.cmake: {}", spec, why));
}

Axis read_axis(std::string_view group, std::string_view text) {
    Axis axis;
    for (std::string_view word : split(trimmed(text), ' ')) {
        if (word.empty()) continue;
        if (axis.name.empty()) {
            axis.name = std::string(word);
            continue;
        }
        const std::string number(word);
        char* end = nullptr;
        axis.values.push_back(std::strtod(number.c_str(), &end));
        if (end != number.c_str() + number.size()) refuse(group, fmt::format("'{}' is not a number", word));
    }
    if (axis.values.empty()) refuse(group, fmt::format("the axis '{}' has no values", axis.name));
    return axis;
}

// The label with each {NAME} replaced by that setting's value in `s`.
std::string label_of(std::string_view group, std::string_view label, const multibody::EngineSettings& s) {
    std::string out;
    for (std::size_t open = label.find('{'); open != std::string_view::npos; open = label.find('{')) {
        const std::size_t close = label.find('}', open);
        if (close == std::string_view::npos) refuse(group, "a '{' without its '}'");
        out += label.substr(0, open);
        const std::string name(label.substr(open + 1, close - open - 1));
        if (name == "dt") out += sci(s.dt);
        else if (name == "iterations") out += std::to_string(s.iterations);
        else if (const auto knob = s.knobs.find(name); knob != s.knobs.end()) out += sci(knob->second);
        else refuse(group, fmt::format("the label names {{{}}}, which no axis or default sets", name));
        label.remove_prefix(close + 1);
    }
    return out + std::string(label);
}

// Every combination of axes[from...] applied to `s`, the first axis outermost.
void combine(std::string_view group, std::string_view label, const std::vector<Axis>& axes, std::size_t from,
             multibody::EngineSettings s, std::vector<BenchSetting>& out) {
    if (from == axes.size()) {
        out.push_back({label_of(group, label, s), s});
        return;
    }
    for (double value : axes[from].values) {
        s.set(axes[from].name, value);
        combine(group, label, axes, from + 1, s, out);
    }
}

}  // namespace

std::string sci(double v) {
    const std::string whole = fmt::format("{:.0e}", v);
    return std::stod(whole) == v ? whole : fmt::format("{:.1e}", v);
}

std::vector<BenchSetting> expand_bench_spec(const multibody::EngineSettings& defaults, std::string_view spec) {
    std::vector<BenchSetting> sweep;
    if (trimmed(spec).empty()) return sweep;
    for (std::string_view group : split(spec, '|')) {
        const std::size_t colon = group.find(':');
        if (colon == std::string_view::npos) refuse(group, "a group without 'LABEL:'");
        std::vector<Axis> axes;
        for (std::string_view text : split(group.substr(colon + 1), ','))
            if (!trimmed(text).empty()) axes.push_back(read_axis(group, text));
        combine(group, trimmed(group.substr(0, colon)), axes, 0, defaults, sweep);
    }
    return sweep;
}

std::string_view bench_spec_of(const std::string& name) {
    for (const EngineFacts& e : kEngineFacts)
        if (name == e.name) return e.bench;
    return "";
}

}  // namespace vssw::validation
