#include "study/palette.hpp"

#include <cstddef>
#include <string_view>

namespace vssw::study {
namespace {

struct EngineColour {
    std::string_view engine, colour;
};
// Okabe-Ito, assigned once: black for the reference, the strongest hues for the four default engines.
constexpr EngineColour kEngineColours[] = {
    {"analytic", "#000000"},       // black
    {"bullet", "#0072B2"},         // blue
    {"ode", "#D55E00"},            // vermillion
    {"simbody", "#009E73"},        // bluish green
    {"siconos", "#CC79A7"},        // reddish purple
    {"simbody-rigid", "#56B4E9"},  // sky blue
};
// The palette's colours left for other names (its yellow, #F0E442, reads badly on white and is not used).
constexpr std::string_view kSpare[] = {"#E69F00", "#999999"};

}  // namespace

std::string engine_colour(const std::string& engine) {
    for (const EngineColour& e : kEngineColours)
        if (e.engine == engine) return std::string(e.colour);
    std::size_t h = 0;  // a stable choice for a name: the same in every plot and every run
    for (char c : engine) h = h * 31 + static_cast<unsigned char>(c);
    return std::string(kSpare[h % (sizeof kSpare / sizeof kSpare[0])]);
}

}  // namespace vssw::study
