#include "io/palette.hpp"

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <string_view>
#include <vector>

#include <fmt/format.h>

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
    {"box2d", "#882255"},          // wine (Paul Tol's colour-blind safe "muted" set: Okabe-Ito's spares stay free)
    {"dart", "#E69F00"},           // orange
    {"mujoco", "#332288"},         // indigo (Paul Tol's colour-blind safe "muted" set; Okabe-Ito has no hue left)
};
// The palette's colour left for other names (its yellow, #F0E442, reads badly on white and is not used).
constexpr std::string_view kSpare[] = {"#999999"};

// One marker shape per engine, so that a series reads without its colour (in grey print, to a reader who does not
// tell the colours apart) and a backend keeps its marker whatever the engine list is: gnuplot's point types, a filled
// one and its open twin (the plus, cross and star have no filled form: both the same). A name the table does not
// know takes the spare shape.
struct EngineMarker {
    std::string_view engine;
    int filled, open;
};
constexpr EngineMarker kEngineMarkers[] = {
    {"analytic", 7, 6},        // circle
    {"bullet", 5, 4},          // square
    {"ode", 9, 8},             // triangle
    {"simbody", 11, 10},       // inverted triangle
    {"siconos", 13, 12},       // diamond
    {"simbody-rigid", 15, 14}, // pentagon
    {"box2d", 1, 1},           // plus
    {"dart", 3, 3},            // star
    {"mujoco", 2, 2},          // cross
};
constexpr EngineMarker kSpareMarker = {"", 7, 6};  // a circle, in the spare grey: apart from the black analytic's

// Dash types the variants of one engine's series cycle through (gnuplot's numbers).
constexpr int kAnalyticDashes[] = {1, 2, 4, 5}, kEngineDashes[] = {2, 4, 5, 3};

}  // namespace

std::string engine_colour(const std::string& engine) {
    for (const EngineColour& e : kEngineColours)
        if (e.engine == engine) return std::string(e.colour);
    std::size_t h = 0;  // a stable choice for a name: the same in every plot and every run
    for (char c : engine) h = h * 31 + static_cast<unsigned char>(c);
    return std::string(kSpare[h % (sizeof kSpare / sizeof kSpare[0])]);
}

int engine_point(const std::string& engine, bool filled) {
    EngineMarker m = kSpareMarker;
    for (const EngineMarker& e : kEngineMarkers)
        if (e.engine == engine) m = e;
    return filled ? m.filled : m.open;
}

std::string series_style(const std::string& engine, std::size_t variant) {
    const bool analytic = engine == "analytic";
    const int dash = analytic ? kAnalyticDashes[variant % std::size(kAnalyticDashes)]
                              : kEngineDashes[variant % std::size(kEngineDashes)];
    return fmt::format("lc rgb '{}' lw {} dt {} pt {} ps 0.7", engine_colour(engine), analytic ? 2 : 1.5, dash,
                       engine_point(engine, variant % 2 == 0));
}

std::vector<std::size_t> series_variants(const std::vector<std::string>& engines) {
    std::vector<std::size_t> variants;
    for (std::size_t i = 0; i < engines.size(); ++i)
        variants.push_back(static_cast<std::size_t>(
            std::count(engines.begin(), engines.begin() + static_cast<std::ptrdiff_t>(i), engines[i])));
    return variants;
}

}  // namespace vssw::study
