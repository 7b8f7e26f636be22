#include "analytic/specimens.hpp"

#include "analytic/data_dir.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "analytic/input_file.hpp"

namespace vssw {
namespace {

constexpr const char* kHeader = "number,height_m,thickness_m,hinge_ratio,note";
constexpr std::size_t kFields = 5;
// Largest specimen number read: far above Table 1's 18, and well inside int (the conversion stays defined).
constexpr double kMaxNumber = 1e6;

std::vector<std::string> split_fields(const std::string& line) {
    std::vector<std::string> fields(1);
    for (char c : line) {
        if (c == ',') fields.emplace_back();
        else fields.back() += c;
    }
    return fields;
}

// The whole field as a number (no blanks, no trailing text), else InputError naming the place, column and text.
double number_field(const std::string& where, const char* column, const std::string& text) {
    const char* begin = text.c_str();
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(begin, &end);
    if (text.empty() || end != begin + text.size() || errno == ERANGE || !std::isfinite(value))
        throw InputError(fmt::format("{}: {} is not a finite number: '{}'", where, column, text));
    return value;
}

Specimen parse_specimen(const std::string& where, const std::string& line) {
    const std::vector<std::string> f = split_fields(line);
    if (f.size() != kFields)
        throw InputError(fmt::format("{}: {} field{}, expected {} ({}): '{}'", where, f.size(),
                                     f.size() == 1 ? "" : "s", kFields, kHeader, line));
    Specimen s;
    const double number = number_field(where, "number", f[0]);
    if (number < 1.0 || number != std::floor(number) || number > kMaxNumber)
        throw InputError(fmt::format("{}: number must be a whole number from 1 to {:g}, got '{}'", where, kMaxNumber,
                                     f[0]));
    s.number = static_cast<int>(number);
    s.height = number_field(where, "height_m", f[1]);
    s.thickness = number_field(where, "thickness_m", f[2]);
    s.hinge_ratio = number_field(where, "hinge_ratio", f[3]);
    if (s.height <= 0.0) throw InputError(fmt::format("{}: height_m must be positive, got '{}'", where, f[1]));
    if (s.thickness <= 0.0) throw InputError(fmt::format("{}: thickness_m must be positive, got '{}'", where, f[2]));
    if (s.hinge_ratio <= 0.0 || s.hinge_ratio >= 1.0)
        throw InputError(fmt::format("{}: hinge_ratio must be in (0, 1), got '{}'", where, f[3]));
    s.note = f[4];
    return s;
}

}  // namespace

std::string default_table1_path() { return shipped_data_dir() + "/table1.csv"; }

std::vector<Specimen> read_table1(const std::string& path) {
    std::ifstream in = open_input_file(path, "the Table 1 file", kMaxTextFileBytes);
    std::vector<Specimen> table;
    std::vector<int> lines;  // where each specimen was given, for a repeated number's message
    std::string line;
    int n = 0;
    bool header = false;
    while (std::getline(in, line)) {
        ++n;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.find_first_not_of(" \t") == std::string::npos) continue;
        const std::string where = fmt::format("{}:{}", path, n);
        if (!header) {
            if (line != kHeader)
                throw InputError(fmt::format("{}: the header must be '{}', got '{}'", where, kHeader, line));
            header = true;
            continue;
        }
        Specimen s = parse_specimen(where, line);
        const auto same =
            std::find_if(table.begin(), table.end(), [&](const Specimen& t) { return t.number == s.number; });
        if (same != table.end())
            throw InputError(fmt::format("{}: specimen {} is given twice (also on line {})", where, s.number,
                                         lines[static_cast<std::size_t>(same - table.begin())]));
        table.push_back(std::move(s));
        lines.push_back(n);
    }
    if (in.bad()) throw InputError(fmt::format("error while reading the Table 1 file '{}'", path));
    if (table.empty()) throw InputError(fmt::format("{}: no specimen (a header line, then one specimen a line)", path));
    return table;
}

const Specimen& table1_specimen(const std::vector<Specimen>& table, int number) {
    for (const Specimen& s : table)
        if (s.number == number) return s;
    std::vector<int> numbers;
    for (const Specimen& s : table) numbers.push_back(s.number);
    throw InputError(fmt::format("Table 1 has no specimen {} (it has {})", number, fmt::join(numbers, ", ")));
}

VsswGeometry make_vssw(const Specimen& specimen, double xi) {
    return make_vssw(specimen.height, specimen.thickness, specimen.hinge_ratio, xi);
}

}  // namespace vssw
