#pragma once
// Where the shipped data (records, Table 1) and the shipped studies (the validation suites) are found, so that an
// installed `vssw` does not need its source tree.
#include <string>

namespace vssw {

// In order: the environment variable VSSW_DATA_DIR when set and not empty; the installed layout beside the running
// program (<prefix>/bin/vssw -> <prefix>/share/vssw/data, when that folder holds table1.csv); the source tree's
// data/ fixed at build time, while it exists (a build directory's programs and tests read what is being edited, not
// an older installed copy); the same folder under the install prefix configured at build time (the installed Python
// module, whose program is python3, once the source tree is gone).
std::string shipped_data_dir();
// The same search for the studies folder (validation-default.toml): VSSW_STUDIES_DIR, <prefix>/share/vssw/studies
// beside the program, the source tree's studies/, the configured prefix's.
std::string shipped_studies_dir();

}  // namespace vssw
