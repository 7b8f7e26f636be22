#pragma once
// One colour per engine in every plot vssw draws (the report's, a study's, a bench's): the Okabe-Ito palette, whose
// eight colours stay apart for the common forms of colour blindness (Okabe & Ito 2008, "Color Universal Design").
// The analytic model is black; a name the table does not know takes one of the palette's spare colours, the same one
// for the same name in every plot. Each engine has its marker too (engine_point), the same in every plot whatever
// the other engines are: a series reads by its shape where the colours do not tell it.
#include <cstddef>
#include <string>
#include <vector>

namespace vssw::io {

// "#rrggbb" for gnuplot's `lc rgb`.
std::string engine_colour(const std::string& engine);

// gnuplot's point type of an engine's marker (`pt`): its shape is the engine's in every plot; `filled` false gives
// its open twin (the same for the plus, cross and star, which have none).
int engine_point(const std::string& engine, bool filled = true);

// The line and point style of a series: its engine's colour and marker, solid for the analytic model, dashed
// for an engine; `variant` (0, 1, ...: the series' place among those of the same engine) changes the dash and
// alternates the marker between filled and open (never its shape).
std::string series_style(const std::string& engine, std::size_t variant);
// The variant of each series of these engines (one name per series): 0 for an engine's first, 1 for its second ...
std::vector<std::size_t> series_variants(const std::vector<std::string>& engines);

}  // namespace vssw::io
