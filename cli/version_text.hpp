#pragma once
// `vssw --version`: the program's version and commit, each backend of this build with its library's version, and
// where each plugin was found.
#include <string>

namespace vssw::cli {

// "vssw X.Y.Z (commit 2389e4a)" (X.Y.Z: project() in CMakeLists.txt), then one line per backend ("  bullet  Bullet
// 3.24 (double precision)"; for an engine whose plugin cannot be opened, why), then the backends this build left out,
// if any, then each plugin's path (the MPI module's too, found but not opened).
std::string version_text();

}  // namespace vssw::cli
