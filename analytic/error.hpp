#pragma once
// Bad input is reported by throwing InputError with a message that names the offending value; the program
// prints it on one line and exits with code 2. Nothing in the analytic core crashes or returns a silent NaN.
#include <stdexcept>
#include <string>

namespace vssw {

struct InputError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Throws InputError("<what> must be <rule>, got <value>") unless ok.
void require(bool ok, const std::string& what, const std::string& rule, double value);

}  // namespace vssw
