#include "io/palette.hpp"

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "vssw_engine_facts.hpp"  // each engine's colour and marker (generated: cmake/engines.cmake)

namespace vssw::io {
namespace {

// Each engine's colour and marker are facts of its folder (multibody/<engine>/engine.cmake, generated into
// vssw_engine_facts.hpp): Okabe-Ito, assigned once, black for the reference and the strongest hues for the four
// default engines, then Paul Tol's colour-blind safe "muted" set where Okabe-Ito has no hue left.

// The palette's colour left for other names (its yellow, #F0E442, reads badly on white and is not used).
constexpr std::string_view kSpare[] = {"#999999"};

// One marker shape per engine, so that a series reads without its colour (in grey print, to a reader who does not
// tell the colours apart) and a backend keeps its marker whatever the engine list is: gnuplot's point types, a filled
// one and its open twin (the plus, cross and star have no filled form: both the same). A name the table does not
// know takes the spare shape.
struct EngineMarker {
    int filled, open;
};
constexpr EngineMarker kSpareMarker = {7, 6};  // a circle, in the spare grey: apart from the black analytic's

// Dash types the variants of one engine's series cycle through (gnuplot's numbers).
constexpr int kAnalyticDashes[] = {1, 2, 4, 5}, kEngineDashes[] = {2, 4, 5, 3};

}  // namespace

std::string engine_colour(const std::string& engine) {
    for (const EngineFacts& e : kEngineFacts)
        if (engine == e.name) return e.colour;
    std::size_t h = 0;  // a stable choice for a name: the same in every plot and every run
    for (char c : engine) h = h * 31 + static_cast<unsigned char>(c);
    return std::string(kSpare[h % (sizeof kSpare / sizeof kSpare[0])]);
}

int engine_point(const std::string& engine, bool filled) {
    EngineMarker m = kSpareMarker;
    for (const EngineFacts& e : kEngineFacts)
        if (engine == e.name) m = {e.marker_filled, e.marker_open};
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

}  // namespace vssw::io
