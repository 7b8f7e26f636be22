#pragma once
// Numbers as people read them in vssw's tables and sentences (JSON and CSV carry full precision).
#include <string>

namespace vssw::study {

// 6 significant digits.
std::string num(double value);
std::string yes_no(bool value);
// A relative error or change in percent: "+0.02 %", "-13.2 %", "+3.1e-04 %", "0 %"; "n/a" when not finite.
std::string percent(double rel_error);

}  // namespace vssw::study
