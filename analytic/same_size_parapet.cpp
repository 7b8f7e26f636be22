#include "analytic/same_size_parapet.hpp"

#include "analytic/error.hpp"
#include "analytic/wall.hpp"

namespace vssw {

std::optional<ParapetGeometry> parapet_with_n_and_corners(const ParapetGeometry& sharp, double eccentricity,
                                                          double corner_radius) {
    // with_eccentricity alone refuses only an e/b outside [-1, 1] on sharp corners, which the VSSW was refused for.
    const ParapetGeometry off_centre = with_eccentricity(sharp, eccentricity);
    try {
        return with_corner_radius(off_centre, corner_radius);
    } catch (const InputError&) {
        return std::nullopt;
    }
}

}  // namespace vssw
