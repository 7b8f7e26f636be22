#pragma once
// The program's lines on stderr, "vssw: KIND: TEXT": one line, whatever the text holds, and nothing in it that a
// terminal would act on. A message echoes its inputs (a file or engine name, a study key, a record's case id), and
// an escape sequence there could set the window's title or clear the screen: shown escaped instead (io/text.hpp).
#include <ostream>
#include <string>

#include "io/text.hpp"

namespace vssw::cli {

// The text of a message as the program shows it (also the Python module's exceptions): its trailing line break
// dropped, then control characters and bytes that are not UTF-8 escaped.
inline std::string message_text(std::string text) {
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == ' ')) text.pop_back();
    return io::printable(text);
}

inline void print_message_line(std::ostream& err, const char* kind, const std::string& text) {
    err << "vssw: " << kind << ": " << message_text(text) << '\n';
}

}  // namespace vssw::cli
