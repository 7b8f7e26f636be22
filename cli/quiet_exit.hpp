#pragma once
// Ends a command with an exit code and nothing more printed: for MPI processes other than rank 0, whose reason is
// printed once by rank 0 (or by the process itself, before it throws this).
#include <stdexcept>

namespace vssw::cli {

struct QuietExit : std::runtime_error {
    explicit QuietExit(int exit_code) : std::runtime_error("quiet exit"), code(exit_code) {}
    int code;
};

}  // namespace vssw::cli
