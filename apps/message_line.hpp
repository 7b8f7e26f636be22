#pragma once
// The program's lines on stderr, "vssw: KIND: TEXT": one line, whatever the text holds, and nothing in it that a
// terminal would act on. A message echoes its inputs (a file or engine name, a study key, a record's case id), and
// an escape sequence there could set the window's title or clear the screen: shown escaped instead (io/text.hpp).
#include <ostream>
#include <string>

#include "io/text.hpp"

namespace vssw::cli {

inline void print_message_line(std::ostream& err, const char* kind, std::string text) {
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == ' ')) text.pop_back();
    err << "vssw: " << kind << ": " << study::printable(text) << '\n';
}

}  // namespace vssw::cli
