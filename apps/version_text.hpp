#pragma once
// `vssw --version`: the program's version and commit, and each backend compiled in with its library's version.
#include <string>

namespace vssw::cli {

// "vssw 0.1.0 (commit 2389e4a)", then one line per backend ("  bullet  Bullet 3.24 (double precision)"), then the
// backends this build left out, if any.
std::string version_text();

}  // namespace vssw::cli
