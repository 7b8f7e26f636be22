#pragma once
// One colour per engine in every plot vssw draws (the report's, a study's, a bench's): the Okabe-Ito palette, whose
// eight colours stay apart for the common forms of colour blindness (Okabe & Ito 2008, "Color Universal Design").
// The analytic model is black; a name the table does not know takes one of the palette's spare colours, the same one
// for the same name in every plot.
#include <string>

namespace vssw::study {

// "#rrggbb" for gnuplot's `lc rgb`.
std::string engine_colour(const std::string& engine);

}  // namespace vssw::study
