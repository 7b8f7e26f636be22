#pragma once
// Numbers and names as people read them in vssw's tables and sentences (JSON and CSV carry full precision), and names
// as file names.
#include <string>

namespace vssw::study {

// 6 significant digits.
std::string num(double value);
std::string yes_no(bool value);
// A relative error or change in percent: "+0.02 %", "-13.2 %", "+3.1e-04 %", "0 %"; "n/a" when not finite.
std::string percent(double rel_error);
// The text with its line breaks as spaces: for one-line messages, CSV statuses and Markdown list items.
std::string one_line(std::string text);
// Case ids and other names as file names: '/' becomes '_' and anything outside [A-Za-z0-9._-] becomes '-'.
std::string file_stem(const std::string& case_id);

}  // namespace vssw::study
