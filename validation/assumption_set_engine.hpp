#pragma once
// The analytic model under an assumption set other than the report's reference, behind the Engine interface, so
// that the validation suite measures it exactly as it measures an engine: the same cases, the same metric code, the
// same rows against the reference. Its numbers are what the other set's assumptions change (e.g. the paper's Eq. 3
// kinematics, Eq. 19 impact and bilateral roller against the mechanism the engines build), a finding about those
// assumptions: the report shows them in a row of their own with no verdict (validation/suite.hpp,
// SuiteResults::other_set).
#include <string>
#include <vector>

#include "analytic/assumption_sets.hpp"
#include "multibody/host/analytic_engine.hpp"

namespace vssw::validation {

// The engine id of the analytic model under a set in the suite's results: "paper-model", "mechanism-model".
std::string assumption_set_engine_id(AssumptionSet set);
// What a report calls it: "analytic, paper's assumptions".
std::string assumption_set_engine_label(AssumptionSet set);

class AssumptionSetEngine final : public multibody::Engine {
public:
    explicit AssumptionSetEngine(AssumptionSet set) : set_(set) {}
    AssumptionSet set() const { return set_; }
    std::string name() const override { return assumption_set_engine_id(set_); }
    std::string display_name() const override { return assumption_set_engine_label(set_); }
    std::string version() const override { return model_.version() + ", set " + to_string(set_); }
    // The analytic backend's defaults with the set's assumptions (multibody::analytic_settings).
    multibody::EngineSettings default_settings() const override;
    std::vector<multibody::SettingDescription> setting_descriptions() const override {
        return model_.setting_descriptions();
    }
    multibody::Trajectory simulate(const multibody::WallScene& scene, const multibody::Excitation& excitation,
                                   const multibody::EngineSettings& settings) const override {
        return model_.simulate(scene, excitation, settings);
    }
    void check_settings(const multibody::EngineSettings& settings) const override { model_.check_settings(settings); }
    bool dt_is_a_reporting_interval() const override { return true; }
    double cost_per_simulated_second() const override { return model_.cost_per_simulated_second(); }

private:
    AssumptionSet set_;
    multibody::AnalyticEngine model_;
};

}  // namespace vssw::validation
