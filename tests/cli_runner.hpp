#pragma once
// The `vssw` program run in-process for the CLI tests (cli/cli.hpp): exit code, stdout and stderr as strings.
#include <sstream>
#include <string>
#include <vector>

#include "cli/cli.hpp"

namespace vssw::testing {

struct CliResult {
    int code;
    std::string out, err;
};

inline CliResult run_cli(const std::vector<std::string>& args) {
    std::vector<const char*> argv = {"vssw"};
    for (const std::string& a : args) argv.push_back(a.c_str());
    std::ostringstream out, err;
    const int code = vssw::cli::run(static_cast<int>(argv.size()), argv.data(), out, err);
    return {code, out.str(), err.str()};
}

}  // namespace vssw::testing
