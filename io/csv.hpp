#pragma once
// CSV as vssw writes and reads it (RFC 4180): a field is quoted, with its quotes doubled, when it holds a comma, a
// quote or a line break; numbers are written in full and empty when they are not finite.
#include <istream>
#include <string>
#include <vector>

namespace vssw::io {

std::string csv_field(const std::string& text);
// A number with 17 significant digits (it reads back to the same double); empty for NaN or infinity.
std::string csv_number(double value);
// The fields of one record read from `in` (a quoted field may span lines); false at the end of the input.
// InputError on an unterminated quote.
bool read_csv_record(std::istream& in, std::vector<std::string>& fields);

}  // namespace vssw::io
