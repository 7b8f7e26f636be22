#include "io/csv.hpp"

#include <cmath>
#include <istream>
#include <streambuf>

#include <fmt/format.h>

#include "analytic/error.hpp"

namespace vssw::io {

std::string csv_field(const std::string& text) {
    if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) {
        if (c == '"') quoted += '"';
        quoted += c;
    }
    return quoted + '"';
}

std::string csv_number(double value) { return std::isfinite(value) ? fmt::format("{:.17g}", value) : ""; }

bool read_csv_record(std::istream& in, std::vector<std::string>& fields) {
    fields.clear();
    if (in.peek() == std::char_traits<char>::eof()) return false;
    // Byte by byte from the stream's buffer: the stream's own get() builds a sentry for every byte, which made reading
    // a study's results back cost more than writing them. The stream's state ends as get() would leave it.
    std::streambuf& buffer = *in.rdbuf();
    constexpr int kEnd = std::char_traits<char>::eof();
    std::string field;
    bool quoted = false, in_quotes = false, ended = true;
    for (int c = buffer.sbumpc(); c != kEnd; c = buffer.sbumpc()) {
        const char ch = static_cast<char>(c);
        if (in_quotes) {
            if (ch == '"') {
                if (buffer.sgetc() == '"') {
                    field += '"';
                    buffer.sbumpc();
                } else {
                    in_quotes = false;
                }
            } else {
                field += ch;
            }
            continue;
        }
        if (ch == '"' && field.empty() && !quoted) {
            in_quotes = quoted = true;
        } else if (ch == ',') {
            fields.push_back(field);
            field.clear();
            quoted = false;
        } else if (ch == '\n') {
            ended = false;
            break;
        } else if (ch != '\r') {
            field += ch;
        }
    }
    if (ended) in.setstate(std::ios::eofbit | std::ios::failbit);  // as get() leaves a stream it found at its end
    if (in_quotes) throw InputError("CSV: a quoted field is not closed before the end of the file");
    fields.push_back(field);
    return true;
}

}  // namespace vssw::io
