#include "cli/build_commit.hpp"

#include "vssw_commit.hpp"  // VSSW_GIT_COMMIT, written at build time (cli/CMakeLists.txt)

namespace vssw::cli {

const char* build_commit() { return VSSW_GIT_COMMIT; }

}  // namespace vssw::cli
