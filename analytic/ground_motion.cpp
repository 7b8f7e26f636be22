#include "ground_motion.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <utility>

#include "error.hpp"
#include "input_file.hpp"

namespace vssw {
namespace {

constexpr double kPi = 3.141592653589793;
// Two sample times are "evenly spaced" when each lies within this fraction of dt of its grid point: far below any
// real timing error, yet far above the rounding of times read from text (~1e-13 relative for 0.02 s over 30 s).
// It guarantees that the O(1) index guess is off by at most one interval, which operator() corrects.
constexpr double kUniformSpacingTolerance = 1e-9;
// Upper limit for reserving memory from a header's NPTS, so a corrupt header cannot trigger a huge allocation
// before the values are counted.
constexpr double kMaxReserve = 1e7;
// Lines of two numbers, the first rising on each, that make a file read with a step a time-and-acceleration table
// instead: the first numbers of ten lines of accelerations rise all the way about once in 10! = 3.6 million.
constexpr std::size_t kMinTimeColumnLines = 10;

std::string upper(std::string s) {
    for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

std::string lower(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

std::string trim(const std::string& s) {
    const char* blanks = " \t\r\n";
    const auto first = s.find_first_not_of(blanks);
    if (first == std::string::npos) return {};
    return s.substr(first, s.find_last_not_of(blanks) - first + 1);
}

// What a message may quote of a file's text: at most this many characters. A message names the file and the line; a
// short excerpt helps find a typo in a record, while a whole line of any file passed as a record (/etc/passwd, a
// process's environment) does not belong in an error message.
constexpr std::size_t kMaxExcerpt = 40;

// `text` for a message: printable ASCII kept, anything else shown as '?', cut to kMaxExcerpt characters ("...").
std::string excerpt(const std::string& text) {
    std::string out;
    for (const char c : text.substr(0, kMaxExcerpt))
        out += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
    return text.size() > kMaxExcerpt ? out + "..." : out;
}

// Splits on any of `separators`, dropping empty fields (so runs of blanks count as one separator).
std::vector<std::string> split(const std::string& s, const char* separators) {
    std::vector<std::string> out;
    std::size_t pos = 0;
    while (pos < s.size()) {
        const auto start = s.find_first_not_of(separators, pos);
        if (start == std::string::npos) break;
        auto end = s.find_first_of(separators, start);
        if (end == std::string::npos) end = s.size();
        out.push_back(s.substr(start, end - start));
        pos = end;
    }
    return out;
}

// The whole token must be a number: strtod alone would accept the "1.0" of "1.0abc". Fortran E format
// (-0.731461E-02, -.7314610E-02) is ordinary strtod input. Range is checked by the caller (isfinite).
bool parse_number(const std::string& token, double& out) {
    if (token.empty()) return false;
    const char* begin = token.c_str();
    char* end = nullptr;
    out = std::strtod(begin, &end);
    return end != begin && end == begin + token.size();
}

// A stream as lines (line i of the file is lines[i - 1]), with any '\r' of DOS line endings removed: PEER files are
// often distributed with CRLF. Its size is bounded too (a file that grows while it is read; a text given whole).
std::vector<std::string> lines_of(std::istream& in, const std::string& name) {
    std::vector<std::string> lines;
    std::string line;
    long long bytes = 0;
    while (std::getline(in, line)) {
        // A UTF-8 byte-order mark (spreadsheets and Windows editors write one) is not part of the first value.
        if (lines.empty() && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
        bytes += static_cast<long long>(line.size()) + 1;
        if (bytes > kMaxRecordBytes)
            throw InputError(fmt::format("ground-motion file '{}' has more than the {} bytes allowed (real records "
                                         "are a few MB)",
                                         name, kMaxRecordBytes));
        if (!line.empty() && line.back() == '\r') line.pop_back();
        lines.push_back(std::move(line));
    }
    return lines;
}

std::vector<std::string> read_lines(const std::string& path) {
    std::ifstream in = open_input_file(path, "ground-motion file", static_cast<std::uintmax_t>(kMaxRecordBytes));
    std::vector<std::string> lines = lines_of(in, path);
    if (in.bad()) throw InputError(fmt::format("error while reading ground-motion file '{}'", path));
    return lines;
}

std::string record_name(const std::string& path) { return std::filesystem::path(path).filename().string(); }

// Builds the record, prefixing any complaint from GroundMotion::sampled with the file name.
GroundMotion sampled_from_file(std::vector<double> times, std::vector<double> values, const std::string& path) {
    try {
        return GroundMotion::sampled(std::move(times), std::move(values), record_name(path));
    } catch (const InputError& e) {
        throw InputError(fmt::format("{}: {}", path, e.what()));
    }
}

// --- PEER AT2 -----------------------------------------------------------------------------------------------------

// Units written on line 3, e.g. "ACCELERATION TIME HISTORY IN UNITS OF G" or "... IN CM/S/S". Returns false when no
// (or more than one distinct) unit word is found.
bool units_from_at2_line(const std::string& line, AccelUnits& units) {
    bool found_g = false, found_cm = false, found_m = false;
    for (std::string word : split(upper(line), " \t")) {
        // Strip punctuation around the unit: "G.", "(CM/S/S)", "G,".
        const auto first = word.find_first_not_of(".,;:()[]");
        const auto last = word.find_last_not_of(".,;:()[]");
        if (first == std::string::npos) continue;
        word = word.substr(first, last - first + 1);
        if (word == "G") found_g = true;
        if (word == "GAL" || word == "GALS" || word == "CM/S/S" || word == "CM/S^2" || word == "CM/S2" ||
            word == "CM/SEC/SEC" || word == "CM/SEC^2" || word == "CM/SEC2")
            found_cm = true;
        if (word == "M/S/S" || word == "M/S^2" || word == "M/S2" || word == "M/SEC/SEC" || word == "M/SEC^2")
            found_m = true;
    }
    if (int(found_g) + int(found_cm) + int(found_m) != 1) return false;
    units = found_g ? AccelUnits::g : found_cm ? AccelUnits::cm_per_s2 : AccelUnits::m_per_s2;
    return true;
}

// Text of the value written after "LABEL=" (or "LABEL:") in an NGA-West2 header, or empty when the label is not
// followed by '=' (older style, numbers first).
std::string value_after_label(const std::string& upper_line, const std::string& label) {
    const auto at = upper_line.find(label);
    if (at == std::string::npos) return {};
    auto pos = upper_line.find_first_not_of(" \t", at + label.size());
    if (pos == std::string::npos || (upper_line[pos] != '=' && upper_line[pos] != ':')) return {};
    pos = upper_line.find_first_not_of(" \t", pos + 1);
    if (pos == std::string::npos) return {};
    const auto end = upper_line.find_first_of(" \t,", pos);
    std::string text = upper_line.substr(pos, end == std::string::npos ? std::string::npos : end - pos);
    // "DT=.0100SEC" without a blank before the unit.
    if (text.size() > 3 && text.compare(text.size() - 3, 3, "SEC") == 0) text.resize(text.size() - 3);
    return text;
}

struct At2Counts {
    double npts;
    double dt;
};

// Line 4: "1991    0.0100    NPTS, DT" (older) or "NPTS=  1991, DT=   .0100 SEC" (NGA-West2), any case.
At2Counts parse_at2_counts(const std::string& line, const std::string& path) {
    const std::string u = upper(line);
    const auto npts_at = u.find("NPTS");
    if (npts_at == std::string::npos)
        throw InputError(fmt::format("{}:4: header line 4 has no NPTS: '{}'", path, excerpt(trim(line))));
    const auto dt_at = u.find("DT");
    if (dt_at == std::string::npos)
        throw InputError(fmt::format("{}:4: header line 4 has no DT: '{}'", path, excerpt(trim(line))));

    std::string npts_text = value_after_label(u, "NPTS");
    std::string dt_text = value_after_label(u, "DT");
    if (npts_text.empty() || dt_text.empty()) {
        // Older style: the two numbers come before the labels, in the order of the labels.
        const auto leading = split(u.substr(0, std::min(npts_at, dt_at)), " \t,");
        if (leading.size() != 2)
            throw InputError(fmt::format("{}:4: expected NPTS and DT values in header line 4, got '{}'", path,
                                         excerpt(trim(line))));
        if (npts_text.empty()) npts_text = npts_at < dt_at ? leading[0] : leading[1];
        if (dt_text.empty()) dt_text = npts_at < dt_at ? leading[1] : leading[0];
    }

    At2Counts c{};
    if (!parse_number(npts_text, c.npts))
        throw InputError(fmt::format("{}:4: NPTS is not a number: '{}'", path, excerpt(npts_text)));
    if (!parse_number(dt_text, c.dt))
        throw InputError(fmt::format("{}:4: DT is not a number: '{}'", path, excerpt(dt_text)));
    if (!(std::isfinite(c.npts) && c.npts > 0.0 && c.npts == std::floor(c.npts)))
        throw InputError(fmt::format("{}:4: NPTS must be a positive whole number, got {}", path, excerpt(npts_text)));
    if (c.npts < 2.0)
        throw InputError(fmt::format("{}:4: NPTS must be at least 2 to define a record, got {}", path, excerpt(npts_text)));
    if (!(std::isfinite(c.dt) && c.dt > 0.0))
        throw InputError(fmt::format("{}:4: DT must be a positive finite number, got {}", path, excerpt(dt_text)));
    if (c.dt < kMinSampleStep)
        throw InputError(fmt::format("{}:4: DT must be at least {:g} s, got {}", path, kMinSampleStep, excerpt(dt_text)));
    return c;
}

GroundMotion parse_at2(const std::vector<std::string>& lines, const std::string& path,
                       const AccelUnits* units_override) {
    if (lines.empty()) throw InputError(fmt::format("{}: file is empty", path));
    if (lines.size() < 4)
        throw InputError(fmt::format("{}: truncated header: {} line(s), a PEER AT2 header has 4", path,
                                     lines.size()));

    // A velocity or displacement history (.VT2/.DT2) has the same layout: reading it as acceleration would be silent
    // nonsense, so refuse it even when the units are overridden.
    const std::string line3 = upper(lines[2]);
    if (line3.find("VELOCITY") != std::string::npos || line3.find("DISPLACEMENT") != std::string::npos)
        throw InputError(fmt::format("{}:3: not an acceleration history: '{}'", path, excerpt(trim(lines[2]))));

    AccelUnits units = AccelUnits::g;
    if (units_override != nullptr) {
        units = *units_override;
    } else if (!units_from_at2_line(lines[2], units)) {
        throw InputError(fmt::format(
            "{}:3: cannot read the acceleration units from line 3 '{}' (expected e.g. 'UNITS OF G', 'CM/S/S', "
            "'GAL' or 'M/S/S'); give the units explicitly",
            path, excerpt(trim(lines[2]))));
    }
    const double factor = to_m_per_s2(units);
    const At2Counts counts = parse_at2_counts(lines[3], path);

    std::vector<double> values;
    values.reserve(static_cast<std::size_t>(std::min(counts.npts, kMaxReserve)));
    for (std::size_t i = 4; i < lines.size(); ++i) {
        const std::size_t line_no = i + 1;
        for (const std::string& token : split(lines[i], " \t\r")) {
            double v = 0.0;
            if (!parse_number(token, v))
                throw InputError(fmt::format("{}:{}: non-numeric value '{}'", path, line_no, excerpt(token)));
            if (!std::isfinite(v) || !std::isfinite(v * factor))
                throw InputError(fmt::format("{}:{}: value '{}' is not finite", path, line_no, excerpt(token)));
            values.push_back(v * factor);
        }
    }

    const double count = static_cast<double>(values.size());
    if (count != counts.npts)
        throw InputError(fmt::format("{}: header line 4 says NPTS = {} but {} value(s) follow ({})", path,
                                     counts.npts, values.size(),
                                     count < counts.npts ? "file truncated?" : "too many values"));

    // Times i * DT, not accumulated sums, so that sample i is exactly on the grid.
    std::vector<double> times(values.size());
    for (std::size_t i = 0; i < times.size(); ++i) times[i] = static_cast<double>(i) * counts.dt;
    return sampled_from_file(std::move(times), std::move(values), path);
}

// --- two columns --------------------------------------------------------------------------------------------------

GroundMotion parse_two_column(const std::vector<std::string>& lines, const std::string& path, AccelUnits units) {
    if (lines.empty()) throw InputError(fmt::format("{}: file is empty", path));
    const double factor = to_m_per_s2(units);
    std::vector<double> times, values;
    std::size_t previous_line = 0;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::size_t line_no = i + 1;
        const std::string data = lines[i].substr(0, lines[i].find('#'));  // '#' starts a comment
        const auto fields = split(data, " \t\r,");
        if (fields.empty()) continue;  // blank or comment-only line
        if (fields.size() != 2)
            throw InputError(fmt::format("{}:{}: expected 2 numbers (time, acceleration), got {} field(s): '{}'",
                                         path, line_no, fields.size(), excerpt(trim(data))));
        double t = 0.0, a = 0.0;
        for (int k = 0; k < 2; ++k) {
            double& v = k == 0 ? t : a;
            if (!parse_number(fields[k], v))
                throw InputError(fmt::format("{}:{}: non-numeric value '{}'", path, line_no, excerpt(fields[k])));
            if (!std::isfinite(v) || (k == 1 && !std::isfinite(v * factor)))
                throw InputError(fmt::format("{}:{}: value '{}' is not finite", path, line_no, excerpt(fields[k])));
        }
        if (times.empty() && t < 0.0)
            throw InputError(fmt::format("{}:{}: the first time must be >= 0, got {}", path, line_no, excerpt(fields[0])));
        if (!times.empty() && !(t > times.back()))
            throw InputError(fmt::format("{}:{}: time {} is not after the previous time {} (line {})", path,
                                         line_no, excerpt(fields[0]), times.back(), previous_line));
        times.push_back(t);
        values.push_back(a * factor);
        previous_line = line_no;
    }
    if (times.size() < 2)
        throw InputError(
            fmt::format("{}: {} data line(s), a record needs at least 2 samples", path, times.size()));
    return sampled_from_file(std::move(times), std::move(values), path);
}

// --- one column at a step dt, and tables with a header row ----------------------------------------------------------

// Whether the line's data (before any '#') holds a comma: its fields are then separated by commas.
bool has_comma(const std::string& line) { return line.substr(0, line.find('#')).find(',') != std::string::npos; }

// The line's data (before any '#') split into fields: by commas when `by_commas`, else by blanks and tabs.
std::vector<std::string> fields_of(const std::string& line, bool by_commas) {
    const std::string data = line.substr(0, line.find('#'));
    if (!by_commas) return split(data, " \t\r");
    std::vector<std::string> fields;
    if (trim(data).empty()) return fields;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = data.find(',', start);
        fields.push_back(trim(data.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return fields;
}

// A header row names every column: none of its fields is a number. A line of numbers and words is a malformed data
// line (its reader says so), never a header that would drop it unread.
bool is_header(const std::vector<std::string>& fields) {
    double ignored = 0.0;
    return std::none_of(fields.begin(), fields.end(), [&](const std::string& f) { return parse_number(f, ignored); });
}

// A finite acceleration in m/s^2 from field `text` of line `line_no`, or InputError.
double acceleration_of(const std::string& text, double factor, const std::string& path, std::size_t line_no) {
    double a = 0.0;
    if (!parse_number(text, a)) throw InputError(fmt::format("{}:{}: non-numeric value '{}'", path, line_no, excerpt(text)));
    if (!std::isfinite(a) || !std::isfinite(a * factor))
        throw InputError(fmt::format("{}:{}: value '{}' is not finite", path, line_no, excerpt(text)));
    return a * factor;
}

std::vector<double> times_at_step(std::size_t count, double dt) {
    std::vector<double> times(count);
    for (std::size_t i = 0; i < count; ++i) times[i] = static_cast<double>(i) * dt;  // on the grid, not summed
    return times;
}

GroundMotion require_two_samples(std::vector<double> times, std::vector<double> values, const std::string& path) {
    if (times.size() < 2)
        throw InputError(fmt::format("{}: {} sample(s), a record needs at least 2", path, times.size()));
    return sampled_from_file(std::move(times), std::move(values), path);
}

// Accelerations only (no header), every number of the file in order, at the step dt.
GroundMotion parse_single_column(const std::vector<std::string>& lines, const std::string& path, double factor,
                                 double dt) {
    std::vector<double> values;
    // A file of two numbers a line whose first rises line after line is a table of time and acceleration: read with
    // a step, its times became accelerations (El Centro read as 31 g, exit 0).
    bool two_per_line = true;
    std::size_t data_lines = 0;
    double previous_first = -std::numeric_limits<double>::infinity();
    bool first_rises = true;
    auto whole_number = [](const std::string& s, bool signed_) {
        const std::size_t from = signed_ && !s.empty() && (s[0] == '-' || s[0] == '+') ? 1 : 0;
        return s.size() > from &&
               std::all_of(s.begin() + static_cast<std::ptrdiff_t>(from), s.end(),
                           [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; });
    };
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const bool by_commas = has_comma(lines[i]);
        const std::vector<std::string> fields = fields_of(lines[i], by_commas);
        for (std::size_t j = 0; j < fields.size(); ++j) {
            const std::string& field = fields[j];
            if (by_commas && j > 0) {
                // "0,0123" is a decimal comma, not the values 0 and 123: a whole number written with a leading
                // zero is what the comma's second half looks like, and no accelerogram writes its values so.
                if (field.size() > 1 && field[0] == '0' && std::isdigit(static_cast<unsigned char>(field[1])))
                    throw InputError(fmt::format("{}:{}: '{}' after a comma looks like a decimal comma; write the "
                                                 "decimals with a point",
                                                 path, i + 1, excerpt(field)));
                // "0,5" and "-1,25" likewise: two whole numbers either side of a comma are one decimal, not two
                // accelerations (whole numbers of a unit are separated by blanks instead).
                if (whole_number(fields[j - 1], true) && whole_number(field, false))
                    throw InputError(fmt::format("{}:{}: '{},{}' looks like a decimal comma; write the decimals with "
                                                 "a point (whole numbers separated by blanks, not commas)",
                                                 path, i + 1, excerpt(fields[j - 1]), excerpt(field)));
            }
            values.push_back(acceleration_of(field, factor, path, i + 1));
        }
        if (fields.empty()) continue;
        ++data_lines;
        two_per_line = two_per_line && fields.size() == 2;
        const double first = values[values.size() - fields.size()];  // read above (times a positive unit factor)
        first_rises = first_rises && first > previous_first;
        previous_first = first;
    }
    if (two_per_line && first_rises && data_lines >= kMinTimeColumnLines)
        throw InputError(fmt::format("{}: every line holds two numbers and the first rises line after line, as a time "
                                     "column does: read it as time and acceleration without the record's step (with "
                                     "a step every number is an acceleration)",
                                     path));
    std::vector<double> times = times_at_step(values.size(), dt);  // before `values` is moved from
    return require_two_samples(std::move(times), std::move(values), path);
}

std::size_t column_index(const std::vector<std::string>& header, const std::string& name, const char* flag,
                         const std::string& path, std::size_t line_no) {
    const auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end())
        throw InputError(fmt::format("{}:{}: {} '{}' is not a column of the header (columns: {})", path, line_no, flag,
                                     name, excerpt(fmt::format("{}", fmt::join(header, ", ")))));
    if (std::find(it + 1, header.end(), name) != header.end())
        throw InputError(fmt::format("{}:{}: {} '{}' names more than one column of the header (columns: {}): which is "
                                     "meant cannot be told",
                                     path, line_no, flag, name, excerpt(fmt::format("{}", fmt::join(header, ", ")))));
    return static_cast<std::size_t>(it - header.begin());
}

// A table whose first data line (line `header_at`, 0-based) names its columns.
GroundMotion parse_table(const std::vector<std::string>& lines, std::size_t header_at, const std::string& path,
                         double factor, const RecordFormat& format) {
    const bool by_commas = has_comma(lines[header_at]);
    const std::vector<std::string> header = fields_of(lines[header_at], by_commas);
    const std::size_t header_line = header_at + 1;
    // A row of names is a record's header only when a row of numbers follows it. Otherwise the file is no record, and
    // its text stays out of the message (a file such as /etc/passwd had its first line quoted as "columns").
    const bool numbers_follow = [&] {
        for (std::size_t i = header_at + 1; i < lines.size(); ++i) {
            const std::vector<std::string> fields = fields_of(lines[i], by_commas);
            if (fields.empty()) continue;
            double x = 0.0;
            return std::all_of(fields.begin(), fields.end(), [&](const std::string& f) { return parse_number(f, x); });
        }
        return false;
    }();
    if (!numbers_follow)
        throw InputError(fmt::format("{}:{}: not a ground-motion record: a line of text with no line of numbers after "
                                     "it (a record is a PEER AT2 file, lines of time and acceleration, accelerations "
                                     "with --record-dt, or a table whose header row names its columns)",
                                     path, header_line));
    if (format.dt && format.time_column)
        throw InputError(fmt::format("{}: give either the record's step or its time column '{}', not both", path,
                                     *format.time_column));
    std::size_t accel = 0;
    if (format.accel_column) accel = column_index(header, *format.accel_column, "acceleration column", path, header_line);
    else if (header.size() == 2 && !format.dt)  // the column that is not time (the second when none is named)
        accel = format.time_column
                    ? 1 - column_index(header, *format.time_column, "time column", path, header_line)
                    : 1;
    else if (header.size() != 1)
        throw InputError(fmt::format("{}:{}: name the acceleration column (columns: {})", path, header_line,
                                     excerpt(fmt::format("{}", fmt::join(header, ", ")))));
    std::optional<std::size_t> time;
    if (format.time_column) time = column_index(header, *format.time_column, "time column", path, header_line);
    else if (!format.dt && header.size() == 2) time = 1 - accel;
    else if (!format.dt)
        throw InputError(fmt::format("{}:{}: name the time column or give the record's step (columns: {})", path,
                                     header_line, excerpt(fmt::format("{}", fmt::join(header, ", ")))));
    if (time && *time == accel)
        throw InputError(fmt::format("{}: the time column and the acceleration column are both '{}'", path,
                                     excerpt(header[accel])));
    std::vector<double> times, values;
    for (std::size_t i = header_at + 1; i < lines.size(); ++i) {
        const std::vector<std::string> fields = fields_of(lines[i], by_commas);
        if (fields.empty()) continue;
        if (fields.size() != header.size())
            throw InputError(fmt::format("{}:{}: {} field(s), the header has {}", path, i + 1, fields.size(),
                                         header.size()));
        values.push_back(acceleration_of(fields[accel], factor, path, i + 1));
        if (!time) continue;
        double t = 0.0;
        if (!parse_number(fields[*time], t) || !std::isfinite(t))
            throw InputError(fmt::format("{}:{}: time '{}' is not a finite number", path, i + 1, excerpt(fields[*time])));
        if (times.empty() && t < 0.0)
            throw InputError(fmt::format("{}:{}: the first time must be >= 0, got {}", path, i + 1, excerpt(fields[*time])));
        if (!times.empty() && !(t > times.back()))
            throw InputError(fmt::format("{}:{}: time {} is not after the previous time {}", path, i + 1,
                                         excerpt(fields[*time]), times.back()));
        times.push_back(t);
    }
    if (!time) times = times_at_step(values.size(), *format.dt);
    return require_two_samples(std::move(times), std::move(values), path);
}

// read_record's choice of reader, on lines from a file or from text.
GroundMotion parse_lines(const std::vector<std::string>& lines, const std::string& path, const AccelUnits* units,
                         const RecordFormat& format) {
    if (format.dt)
        require(std::isfinite(*format.dt) && *format.dt >= kMinSampleStep, fmt::format("{}: record step", path),
                fmt::format("a finite time of at least {:g} s", kMinSampleStep), *format.dt);
    if (lines.size() >= 4 && upper(lines[3]).find("NPTS") != std::string::npos) {
        if (!format.is_default())
            throw InputError(fmt::format("{} is a PEER AT2 record, whose header gives its step: the record's step "
                                         "and column names apply to other files",
                                         path));
        return parse_at2(lines, path, units);
    }
    const double factor = to_m_per_s2(units != nullptr ? *units : AccelUnits::g);
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::vector<std::string> fields = fields_of(lines[i], has_comma(lines[i]));
        if (fields.empty()) continue;
        if (is_header(fields)) return parse_table(lines, i, path, factor, format);
        break;
    }
    if (format.time_column || format.accel_column)
        throw InputError(fmt::format("{} has no header row to name its columns (its first data line is numbers)",
                                     path));
    if (format.dt) return parse_single_column(lines, path, factor, *format.dt);
    return parse_two_column(lines, path, units != nullptr ? *units : AccelUnits::g);
}

void require_amplitude(double amplitude) {
    require(std::isfinite(amplitude), "ground-motion amplitude", "finite", amplitude);
}

void require_time(double value, const std::string& what) {
    require(std::isfinite(value) && value > 0.0, what, "a positive finite time in s", value);
}

}  // namespace

// --- units ----------------------------------------------------------------------------------------------------------

AccelUnits parse_units(const std::string& text) {
    const std::string t = lower(trim(text));
    if (t == "g") return AccelUnits::g;
    if (t == "m/s2" || t == "m/s^2") return AccelUnits::m_per_s2;
    if (t == "cm/s2" || t == "cm/s^2" || t == "gal") return AccelUnits::cm_per_s2;
    throw InputError(
        fmt::format("acceleration units must be one of g, m/s2, m/s^2, cm/s2, cm/s^2, gal; got '{}'", text));
}

double to_m_per_s2(AccelUnits units) {
    switch (units) {
        case AccelUnits::g: return kStandardGravity;
        case AccelUnits::m_per_s2: return 1.0;
        case AccelUnits::cm_per_s2: return 0.01;
    }
    throw InputError(fmt::format("unknown acceleration units code {}", static_cast<int>(units)));
}

// --- GroundMotion ---------------------------------------------------------------------------------------------------

GroundMotion GroundMotion::sampled(std::vector<double> times, std::vector<double> accel_m_s2, std::string name) {
    if (times.size() != accel_m_s2.size())
        throw InputError(fmt::format("record '{}': {} times but {} accelerations", name, times.size(),
                                     accel_m_s2.size()));
    if (times.size() < 2)
        throw InputError(fmt::format("record '{}': {} sample(s), a record needs at least 2", name, times.size()));
    for (std::size_t i = 0; i < times.size(); ++i) {
        if (!std::isfinite(times[i]))
            throw InputError(fmt::format("record '{}': time of sample {} must be finite, got {}", name, i, times[i]));
        if (!std::isfinite(accel_m_s2[i]))
            throw InputError(
                fmt::format("record '{}': acceleration of sample {} must be finite, got {}", name, i, accel_m_s2[i]));
        if (i > 0 && !(times[i] > times[i - 1]))
            throw InputError(fmt::format("record '{}': times must increase strictly, but sample {} is at {} after {}",
                                         name, i, times[i], times[i - 1]));
        if (i > 0 && times[i] - times[i - 1] < kMinSampleStep)
            throw InputError(fmt::format("record '{}': samples {} and {} are {:g} s apart, less than {:g} s", name,
                                         i - 1, i, times[i] - times[i - 1], kMinSampleStep));
    }
    if (times.front() < 0.0)
        throw InputError(fmt::format("record '{}': times must start at 0 or later, got {}", name, times.front()));

    GroundMotion m;
    const std::size_t n = times.size();
    const double t0 = times.front();
    const double dt = (times.back() - t0) / static_cast<double>(n - 1);
    bool uniform = dt > 0.0;
    for (std::size_t i = 0; uniform && i < n; ++i)
        uniform = std::abs(times[i] - (t0 + static_cast<double>(i) * dt)) <= kUniformSpacingTolerance * dt;
    m.uniform_dt_ = uniform ? dt : 0.0;
    m.duration_ = times.back();
    m.breakpoints_ = times;
    m.times_ = std::move(times);
    m.values_ = std::move(accel_m_s2);
    m.name_ = std::move(name);
    return m;
}

GroundMotion GroundMotion::analytic(std::function<double(double)> a, double duration, std::vector<double> breakpoints,
                                    AnalyticShape shape, std::string name) {
    if (!a) throw InputError(fmt::format("analytic ground motion '{}' has no function", name));
    require(std::isfinite(duration) && duration > 0.0, fmt::format("duration of ground motion '{}'", name),
            "a positive finite time in s", duration);
    require(std::isfinite(shape.peak) && shape.peak >= 0.0, fmt::format("peak of ground motion '{}'", name),
            "a finite acceleration >= 0 m/s^2", shape.peak);
    for (double b : breakpoints)
        require(std::isfinite(b) && b >= 0.0 && b <= duration, fmt::format("breakpoint of ground motion '{}'", name),
                fmt::format("within [0, {}] s", duration), b);
    breakpoints.push_back(0.0);
    breakpoints.push_back(duration);
    std::sort(breakpoints.begin(), breakpoints.end());
    breakpoints.erase(std::unique(breakpoints.begin(), breakpoints.end()), breakpoints.end());

    GroundMotion m;
    m.fn_ = std::move(a);
    m.next_extremum_ = std::move(shape.next_extremum);
    m.analytic_peak_ = shape.peak;
    m.duration_ = duration;
    m.breakpoints_ = std::move(breakpoints);
    m.name_ = std::move(name);
    return m;
}

GroundMotion GroundMotion::none() {
    GroundMotion m;
    m.is_zero_ = true;
    m.name_ = "none";
    return m;
}

// Hot path (every integrator stage): no allocation; sampled records branch on times_ instead of going through fn_.
double GroundMotion::operator()(double t) const {
    // One comparison pair covers t < 0, t > duration and NaN; a NaN time is returned as NaN, not masked as 0.
    if (!(t >= 0.0 && t <= duration_)) return std::isnan(t) ? t : 0.0;
    if (times_.empty()) return is_zero_ ? 0.0 : fn_(t);

    if (t < times_[0]) return 0.0;  // a record that starts after t = 0
    const std::size_t i = interval_of(t);
    const double w = (t - times_[i]) / (times_[i + 1] - times_[i]);
    // (1 - w) a_i + w a_{i+1} returns the samples exactly at w = 0 and w = 1.
    return (1.0 - w) * values_[i] + w * values_[i + 1];
}

std::optional<GroundMotion::LinearPiece> GroundMotion::linear_piece(double t) const {
    // No motion: every finite time (finite bounds, so that slope (x - start) is 0, not 0 times infinity).
    constexpr double kLowest = std::numeric_limits<double>::lowest(), kHighest = std::numeric_limits<double>::max();
    if (is_zero_) return LinearPiece{kLowest, kHighest, 0.0, 0.0};
    if (times_.empty() || !(t >= times_[0] && t <= duration_)) return std::nullopt;
    const std::size_t i = interval_of(t);
    const double t0 = times_[i], t1 = times_[i + 1];
    return LinearPiece{t0, t1, values_[i], (values_[i + 1] - values_[i]) / (t1 - t0)};
}

std::size_t GroundMotion::interval_of(double t) const {
    const std::size_t n = times_.size();
    std::size_t i = 0;
    if (uniform_dt_ > 0.0) {
        // The guess is within one interval of the truth (kUniformSpacingTolerance); fix it against the stored times
        // so that interpolation always uses the true bracketing samples.
        i = std::min(static_cast<std::size_t>((t - times_[0]) / uniform_dt_), n - 2);
        if (t < times_[i] && i > 0)
            --i;
        else if (t > times_[i + 1] && i + 2 < n)
            ++i;
    } else {
        const auto it = std::upper_bound(times_.begin(), times_.end(), t);  // first sample after t
        i = std::min(static_cast<std::size_t>(it - times_.begin()) - 1, n - 2);
    }
    return i;
}

bool GroundMotion::continuous_at(double t) const {
    if (is_zero_) return true;
    return !times_.empty() && t > times_.front() && t < duration_;
}

double GroundMotion::pga() const {
    if (is_zero_) return 0.0;
    if (times_.empty()) return analytic_peak_;
    double peak = 0.0;
    for (double v : values_) peak = std::max(peak, std::abs(v));
    return peak;
}

double GroundMotion::quiet_after(double level) const {
    if (is_zero_) return 0.0;
    if (times_.empty()) return duration_;
    for (std::size_t i = values_.size(); i-- > 0;)
        if (std::abs(values_[i]) > level) return i + 1 < times_.size() ? times_[i + 1] : duration_;
    return 0.0;
}

double GroundMotion::next_extremum(double t) const {
    if (is_zero_ || !times_.empty() || !next_extremum_) return std::numeric_limits<double>::infinity();
    return next_extremum_(t);
}

GroundMotion GroundMotion::scaled(double factor) const {
    require(std::isfinite(factor), fmt::format("scale factor for ground motion '{}'", name_), "finite", factor);
    GroundMotion m = *this;
    m.name_ = fmt::format("{} x {}", name_, factor);
    if (is_zero_) return m;
    if (!times_.empty()) {
        for (double& v : m.values_) {
            v *= factor;
            if (!std::isfinite(v))
                throw InputError(fmt::format("scaling ground motion '{}' by {} overflows", name_, factor));
        }
        return m;
    }
    m.fn_ = [f = fn_, factor](double t) { return factor * f(t); };
    m.analytic_peak_ = std::abs(factor) * analytic_peak_;
    return m;
}

GroundMotion GroundMotion::scaled_to_pga(double pga_m_s2) const {
    require(std::isfinite(pga_m_s2) && pga_m_s2 > 0.0, fmt::format("target PGA for ground motion '{}'", name_),
            "a positive finite acceleration in m/s^2", pga_m_s2);
    const double current = pga();
    require(current > 0.0, fmt::format("PGA of ground motion '{}' (to scale it to {} m/s^2)", name_, pga_m_s2),
            "> 0", current);
    return scaled(pga_m_s2 / current);
}

// --- records --------------------------------------------------------------------------------------------------------

GroundMotion read_peer_at2(const std::string& path, const AccelUnits* units_override) {
    return parse_at2(read_lines(path), path, units_override);
}

GroundMotion read_two_column(const std::string& path, AccelUnits units) {
    return parse_two_column(read_lines(path), path, units);
}

GroundMotion read_record(const std::string& path, const AccelUnits* units, const RecordFormat& format) {
    return parse_lines(read_lines(path), path, units, format);
}

GroundMotion parse_record(const std::string& text, const std::string& name, const AccelUnits* units,
                          const RecordFormat& format) {
    std::istringstream in(text);
    return parse_lines(lines_of(in, name), name, units, format);
}

// --- synthetic inputs -----------------------------------------------------------------------------------------------

namespace {

constexpr double kNoMore = std::numeric_limits<double>::infinity();
// A harmonic's cycles: 1e6 is 600 s at 0.6 ms (1.7 kHz), beyond any ground motion.
constexpr double kMaxHarmonicCycles = 1e6;

// The extrema of a sinusoid of period T at first + k T/2 (k = 0, 1, ...) before `end`: the first after t.
std::function<double(double)> sinusoid_extrema(double period, double first, double end) {
    return [half = 0.5 * period, first, end](double t) {
        double next = first + std::max(0.0, std::floor((t - first) / half) + 1.0) * half;
        while (next <= t) next += half;  // rounding of the division
        return next < end ? next : kNoMore;
    };
}

// The first of a few known extrema (ascending) after t.
std::function<double(double)> listed_extrema(std::vector<double> times) {
    return [times = std::move(times)](double t) {
        const auto it = std::upper_bound(times.begin(), times.end(), t);
        return it == times.end() ? kNoMore : *it;
    };
}

}  // namespace

GroundMotion constant_motion(double amplitude, double duration) {
    require_amplitude(amplitude);
    require_time(duration, "constant motion duration");
    return GroundMotion::analytic([amplitude](double) { return amplitude; }, duration, {}, {std::abs(amplitude), {}},
                                  fmt::format("constant {} m/s^2 for {} s", amplitude, duration));
}

GroundMotion sine_pulse(double amplitude, double period) {
    require_amplitude(amplitude);
    require_time(period, "sine pulse period T_p");
    const double omega = 2.0 * kPi / period;
    return GroundMotion::analytic([amplitude, omega](double t) { return amplitude * std::sin(omega * t); }, period,
                                  {}, {std::abs(amplitude), sinusoid_extrema(period, 0.25 * period, period)},
                                  fmt::format("sine pulse a_p={} m/s^2 T_p={} s", amplitude, period));
}

GroundMotion cosine_pulse(double amplitude, double period) {
    require_amplitude(amplitude);
    require_time(period, "cosine pulse period T_p");
    const double omega = 2.0 * kPi / period;
    // Jumps from 0 to a_p at t = 0 and from a_p back to 0 after T_p: both are breakpoints (added by analytic()).
    return GroundMotion::analytic([amplitude, omega](double t) { return amplitude * std::cos(omega * t); }, period,
                                  {}, {std::abs(amplitude), sinusoid_extrema(period, 0.5 * period, period)},
                                  fmt::format("cosine pulse a_p={} m/s^2 T_p={} s", amplitude, period));
}

GroundMotion ricker_wavelet(double amplitude, double period) {
    require_amplitude(amplitude);
    require_time(period, "Ricker wavelet period T_p");
    const double centre = 1.5 * period;
    const double pf2 = kPi * kPi / (period * period);  // pi^2 f^2 with f = 1/T_p
    // Smooth inside; its tiny values at 0 and 3 T_p (about -1e-8 a_p) make the ends kinks, which analytic() adds.
    return GroundMotion::analytic(
        [amplitude, centre, pf2](double t) {
            const double x = pf2 * (t - centre) * (t - centre);
            return amplitude * (1.0 - 2.0 * x) * std::exp(-x);
        },
        // Extrema where d/dx [(1 - 2x) e^-x] = 0 (x = 1.5, the side lobes) and at the centre (x = 0, the peak a_p).
        3.0 * period, {},
        {std::abs(amplitude), listed_extrema({centre - std::sqrt(1.5) * period / kPi, centre,
                                              centre + std::sqrt(1.5) * period / kPi})},
        fmt::format("Ricker wavelet a_p={} m/s^2 T_p={} s", amplitude, period));
}

GroundMotion harmonic(double amplitude, double period, double duration) {
    require_amplitude(amplitude);
    require_time(period, "harmonic period T");
    require_time(duration, "harmonic duration");
    // At rest the model looks at every extremum (two a cycle): a bound on the cycles keeps a run finite (1e8 cycles of
    // a 1e-8 s period over 600 s was hours of looks) and each half period far above the times' rounding.
    require(duration / period <= kMaxHarmonicCycles, "harmonic cycles (duration / period T)",
            fmt::format("at most {:g}: a longer or faster harmonic than any shaking", kMaxHarmonicCycles),
            duration / period);
    const double omega = 2.0 * kPi / period;
    // Shorter than a quarter period, it ends before its first peak.
    const double peak =
        duration >= 0.25 * period ? std::abs(amplitude) : std::abs(amplitude * std::sin(omega * duration));
    return GroundMotion::analytic([amplitude, omega](double t) { return amplitude * std::sin(omega * t); },
                                  duration, {}, {peak, sinusoid_extrema(period, 0.25 * period, duration)},
                                  fmt::format("harmonic a_p={} m/s^2 T={} s for {} s", amplitude, period, duration));
}

}  // namespace vssw
