#pragma once
// Numbers and names as people read them in vssw's tables and sentences (JSON and CSV carry full precision), and names
// as file names.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace vssw::io {

// 6 significant digits.
std::string num(double value);
std::string yes_no(bool value);
// A relative error or change in percent: "+0.02 %", "-13.2 %", "+3.1e-04 %", "0 %"; "n/a" when not finite.
std::string percent(double rel_error);
// The text with its line breaks as spaces: for one-line messages, CSV statuses and Markdown list items.
std::string one_line(std::string text);
// The longest stem file_stem() gives [bytes]: a file name holds 255 (NAME_MAX), and the stems get a prefix and an
// extension of their own ("trace_" ... "_zoom.svg", "rocking_" ... ".dat"), well under the 55 left.
constexpr std::size_t kMaxFileStem = 200;
// Case ids and other names as file names: '/' becomes '_' and anything outside [A-Za-z0-9._-] becomes '-'; a name
// longer than kMaxFileStem is cut and ends in a hash of the whole name ("-" and 16 hex digits), so it stays unique.
std::string file_stem(const std::string& case_id);
// The text as a terminal may show it, for every message that can echo an input: control characters (C0, DEL and
// C1, ESC among them, which start a terminal's escape sequences) and the direction marks that reorder a line (U+202E
// and its kin) as escapes ("\n", "\t", "\x1b", "\u009b", "\u202e"), and a byte that is not part of a UTF-8
// character as "\xff". Everything else, non-ASCII letters included, as it is.
std::string printable(std::string_view text);
// When the text is not UTF-8 (RFC 3629; a file name may hold any byte): the text quoted as printable() shows it and
// its first bad byte, "'s\xff.toml' is not UTF-8 (the byte \xff at offset 1)", for a message that refuses it.
std::optional<std::string> not_utf8(std::string_view text);

}  // namespace vssw::io
