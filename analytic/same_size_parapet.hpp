#pragma once
// The parapet a VSSW's threshold is compared with (Eq. 12 over Eq. 17, `vssw wall` and a study's
// threshold_ratio_to_parapet): one block of the wall's whole size, N at the wall's e/b, its corners at the wall's r/b.
#include <optional>

#include "analytic/geometry.hpp"

namespace vssw {

// `sharp` (the parapet of the wall's size, xi, density and g, sharp corners, N at the centre) with N at e/b =
// eccentricity and its corners rounded to r/b = corner_radius; nullopt when that parapet cannot stand (N outside its
// rounded pivot's flat: with_corner_radius refuses it, although the VSSW, whose upper block changes N's lever, took
// the same e/b and r/b).
std::optional<ParapetGeometry> parapet_with_n_and_corners(const ParapetGeometry& sharp, double eccentricity,
                                                          double corner_radius);

}  // namespace vssw
