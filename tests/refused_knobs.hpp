#pragma once
// Each knob value outside its documented range is refused by check_settings with an InputError naming the knob (the
// adapters' "bad settings are refused by name" tests, one list of values per engine).
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "analytic/error.hpp"
#include "multibody/engine.hpp"

namespace vssw::testing {

inline void expect_knobs_refused_by_name(const multibody::Engine& engine,
                                         const std::vector<std::pair<std::string, double>>& bad_values) {
    for (const auto& [knob, value] : bad_values) {
        multibody::EngineSettings s = engine.default_settings();
        s.knobs[knob] = value;
        try {
            engine.check_settings(s);
            ADD_FAILURE() << engine.name() << ": " << knob << " = " << value << " was accepted";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(knob), std::string::npos) << e.what();
        }
    }
}

}  // namespace vssw::testing
