#include "io/csv.hpp"

#include <cmath>

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
    std::string field;
    bool quoted = false, in_quotes = false;
    for (int c = in.get(); c != std::char_traits<char>::eof(); c = in.get()) {
        const char ch = static_cast<char>(c);
        if (in_quotes) {
            if (ch == '"') {
                if (in.peek() == '"') {
                    field += '"';
                    in.get();
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
            break;
        } else if (ch != '\r') {
            field += ch;
        }
    }
    if (in_quotes) throw InputError("CSV: a quoted field is not closed before the end of the file");
    fields.push_back(field);
    return true;
}

}  // namespace vssw::io
