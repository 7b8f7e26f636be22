#pragma once
// Ends the program with exit 0 after printing `text` on standard output, thrown by an option's callback while the
// command line is parsed (`vssw --version`, `vssw compare --list-settings`): CLI11 runs the options' callbacks before
// it checks the required ones, so these print without a wall being described, as --help does.
#include <stdexcept>
#include <string>

namespace vssw::cli {

struct EarlyOutput : std::runtime_error {
    explicit EarlyOutput(std::string output) : std::runtime_error("early output"), text(std::move(output)) {}
    std::string text;
};

}  // namespace vssw::cli
