#pragma once
// Where the shipped data (records, Table 1) are found, so that an installed `vssw` does not need its source tree.
#include <string>

namespace vssw {

// In order: the environment variable VSSW_DATA_DIR when set and not empty; the installed layout beside the running
// program (<prefix>/bin/vssw -> <prefix>/share/vssw/data, when that folder holds table1.csv); the same folder under
// the install prefix configured at build time (for the installed Python module, whose program is python3); the
// source tree's data/ fixed at build time (a build directory's programs and tests).
std::string shipped_data_dir();

}  // namespace vssw
