#include "study/study_plots.hpp"

namespace vssw::study {

const char* const kValueSection = "Each metric against each varied parameter";
const char* const kTornadoSection = "What the analytic model's assumptions change (tornado charts)";
const char* const kPhysicalTornadoSection = "What the paper's physical assumptions cost (tornado charts)";
const char* const kRockingSection = "Rocking curves (the paper's Fig. 10/11)";
const char* const kMapSection = "Overturning maps";

StudyPlots study_plot_scripts(const StudyData& d, const std::vector<Effect>& effects) {
    StudyPlots out;
    add_value_plots(d, out);
    add_tornado_plots(d, effects, out);
    add_rocking_curves(d, out);
    add_overturning_maps(d, out);
    return out;
}

}  // namespace vssw::study
