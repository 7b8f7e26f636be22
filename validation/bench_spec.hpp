#pragma once
// An engine's work-precision sweep as its folder states it: the BENCH lines of multibody/<engine>/engine.cmake
// (cmake/engines.cmake), carried into the generated vssw_engine_facts.hpp as one text.
#include <string>
#include <string_view>
#include <vector>

#include "multibody/engine.hpp"
#include "validation/work_precision.hpp"

namespace vssw::validation {

// A setting's value in a label: 1e-04, 2.5e-04 (one decimal only when it is needed).
std::string sci(double v);

// The settings a sweep text names. Groups are separated by '|', each "LABEL: AXIS V V ..., AXIS V ...": every
// combination of its axes' values (the first axis outermost), each applied to `defaults` with EngineSettings::set
// ("dt", "iterations" or a knob), labelled by LABEL with each {NAME} replaced by that setting's value (sci(), or a
// whole number for iterations). A group without axes is the defaults under its label. Empty text: no settings.
// A text that does not read so is a fault of the build's facts: std::logic_error naming it.
std::vector<BenchSetting> expand_bench_spec(const multibody::EngineSettings& defaults, std::string_view spec);

// The sweep text of the backend `name` in this build's facts; "" when it states none.
std::string_view bench_spec_of(const std::string& name);

}  // namespace vssw::validation
