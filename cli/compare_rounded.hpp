#pragma once
// `vssw compare --corner-radius`: each engine's threshold and period on the rounded wall, the closed form of Eq. (12r)
// / (17r) beside the thresholds, and the engines' spread (compare/rounded_corners.hpp), as a table or JSON.
#include <iosfwd>

#include "cli/wall_options.hpp"
#include "compare/rounded_corners.hpp"
#include "io/json.hpp"

namespace vssw::cli {

// theta0 in the JSON is the release as typed (--theta0, a fraction of alpha), as plain compare writes it.
io::Json to_json(const compare::RoundedCornerComparison& c, const WallOptions& wall, WallKind kind, double release);
void print_rounded_corners(std::ostream& out, const compare::RoundedCornerComparison& c, const WallOptions& wall,
                           WallKind kind);

}  // namespace vssw::cli
