#pragma once
// The commit this program was built from: "" outside a git checkout, "+changes" after it when the work tree differed
// from it. Written at every build into build/generated/vssw_commit.hpp (cli/CMakeLists.txt), which only
// build_commit.cpp includes: a new stamp (the first edit after a commit) recompiles that one small file, not every
// command that names the commit nor the Python module.
namespace vssw::cli {

const char* build_commit();

}  // namespace vssw::cli
