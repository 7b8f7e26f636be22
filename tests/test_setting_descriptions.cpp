// Each backend's Engine::setting_descriptions(), what `vssw compare --list-settings` prints: every knob it describes
// is one the backend accepts and no other is; every default it states as a number is the value in use (setting it
// explicitly leaves the run unchanged to the last bit), so the listing cannot drift from the code.
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "analytic/error.hpp"
#include "analytic/wall.hpp"
#include "multibody/engine.hpp"

namespace {

using vssw::InputError;
using vssw::multibody::Engine;
using vssw::multibody::EngineSettings;
using vssw::multibody::Excitation;
using vssw::multibody::SettingDescription;
using vssw::multibody::WallScene;

// The default as a number, when it is one ("0.2", "1e-10", "inf"); words ("Eq. (19)", "none") are not.
std::optional<double> numeric(const std::string& text) {
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size()) return std::nullopt;
    return value;
}

// The Fig. 6 VSSW released at half its angle, to just past its first impact (0.42 s): flight, landing and rocking
// back, so that a knob of the flight, of the contacts or of the impact each shows.
std::vector<double> theta1_of_free_vibration(const Engine& engine, const EngineSettings& settings) {
    Excitation ex;
    const WallScene scene = WallScene::of(vssw::make_vssw(4.0, 0.4, 0.7));
    ex.theta0 = 0.5 * scene.alpha();
    ex.t_end = 0.6;
    ex.stop_at_rest = false;
    std::vector<double> theta1;
    for (const auto& s : engine.simulate(scene, ex, settings).samples) theta1.push_back(s.theta1);
    return theta1;
}

class SettingDescriptions : public ::testing::TestWithParam<std::string> {
protected:
    std::unique_ptr<Engine> engine_ = vssw::multibody::make_engine(GetParam());
};

TEST_P(SettingDescriptions, EveryKnobDescribedIsAcceptedAndNoOtherIs) {
    const std::vector<SettingDescription> described = engine_->setting_descriptions();
    ASSERT_FALSE(described.empty());
    EXPECT_EQ(described.at(0).name, "dt");
    EXPECT_EQ(described.at(1).name, "iterations");
    for (const SettingDescription& d : described) {
        SCOPED_TRACE(d.name);
        EXPECT_FALSE(d.meaning.empty());
        EXPECT_FALSE(d.default_value.empty());
        if (!vssw::multibody::is_knob(d.name)) continue;
        EngineSettings s = engine_->default_settings();
        s.knobs[d.name] = numeric(d.default_value).value_or(0.0);
        EXPECT_NO_THROW(engine_->check_settings(s));
    }
    EngineSettings unknown = engine_->default_settings();
    unknown.knobs["no_such_setting"] = 1.0;
    try {
        engine_->check_settings(unknown);
        ADD_FAILURE() << "an undescribed setting was accepted";
    } catch (const InputError& e) {
        for (const SettingDescription& d : described) {
            if (vssw::multibody::is_knob(d.name)) {
                EXPECT_NE(std::string(e.what()).find(d.name), std::string::npos) << e.what();
            }
        }
    }
}

TEST_P(SettingDescriptions, EveryNumericDefaultIsTheDefaultInUse) {
    const EngineSettings defaults = engine_->default_settings();
    const std::vector<double> reference = theta1_of_free_vibration(*engine_, defaults);
    ASSERT_GT(reference.size(), 100u);
    for (const SettingDescription& d : engine_->setting_descriptions()) {
        SCOPED_TRACE(d.name + " = " + d.default_value);
        const std::optional<double> value = numeric(d.default_value);
        if (d.name == "dt") {
            ASSERT_TRUE(value.has_value());
            EXPECT_EQ(*value, defaults.dt);
            continue;
        }
        if (!value) continue;  // words: "none", "Eq. (19)"
        EngineSettings s = defaults;
        if (d.name == "iterations") s.iterations = static_cast<int>(*value);
        else s.knobs[d.name] = *value;
        EXPECT_EQ(theta1_of_free_vibration(*engine_, s), reference);
    }
}

std::string engine_name(const ::testing::TestParamInfo<std::string>& info) {
    std::string name = info.param;
    for (char& c : name)
        if (c == '-') c = '_';
    return name;
}

INSTANTIATE_TEST_SUITE_P(Engines, SettingDescriptions, ::testing::ValuesIn(vssw::multibody::available_engines()),
                         engine_name);

}  // namespace
