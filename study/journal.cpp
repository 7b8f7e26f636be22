#include "study/journal.hpp"

#include <cstdlib>
#include <limits>
#include <sstream>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "analytic/input_file.hpp"
#include "io/csv.hpp"

namespace vssw::study {
namespace {

constexpr const char* kMagic = "#vssw-study-journal";
constexpr const char* kDone = "#done";
constexpr const char* kIda = "#ida";

std::string header(const std::string& identity, Shard shard) {
    return fmt::format("{},{},{}/{}", kMagic, identity, shard.k, shard.n);
}

long parse_long(const std::string& text, const std::filesystem::path& path) {
    char* end = nullptr;
    const long v = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0') throw InputError(fmt::format("journal {}: '{}' is not a whole number", path.string(), text));
    return v;
}

// A journal line's fields: split at its commas when it holds no quote or carriage return (every line of numbers and
// plain statuses), else read as a CSV record.
void split_record(const std::string& line, std::vector<std::string>& f) {
    if (line.find_first_of("\"\r") != std::string::npos) {
        std::istringstream record(line);
        io::read_csv_record(record, f);
        return;
    }
    f.clear();
    std::size_t start = 0;
    for (;;) {
        const std::size_t comma = line.find(',', start);
        f.emplace_back(line, start, comma == std::string::npos ? std::string::npos : comma - start);
        if (comma == std::string::npos) return;
        start = comma + 1;
    }
}

// Reads the journal's whole tasks (their rows in file order) and the byte offset just past the last whole task.
std::vector<ResultRow> read_whole_tasks(const std::filesystem::path& path, const std::string* identity,
                                        const Shard* shard, std::set<TaskKey>* done, std::streamoff* end_of_whole,
                                        std::vector<IdaRow>* ida = nullptr) {
    std::ifstream in = open_input_file(path, "the study journal", kMaxResultsBytes);
    std::string first;
    std::getline(in, first);
    if (first.rfind(kMagic, 0) != 0) throw InputError(fmt::format("{} is not a vssw study journal", path.string()));
    if (identity && shard && first != header(*identity, *shard))
        throw InputError(fmt::format("journal {} belongs to another study or shard ({}; this is {})", path.string(),
                                     first, header(*identity, *shard)));
    std::vector<ResultRow> rows, pending;
    std::vector<IdaRow> pending_ida;
    std::set<TaskKey> seen;
    if (in.eof()) throw InputError(fmt::format("journal {}: its first line is cut short", path.string()));
    // Offsets counted from the lines read (each and its newline), not asked of the stream per task (a seek each).
    std::streamoff read = static_cast<std::streamoff>(first.size()) + 1, whole = read;
    std::vector<std::string> f;
    std::string line;
    for (;;) {
        if (!std::getline(in, line)) break;
        if (in.eof()) break;  // a last line without its newline was being written: not whole
        read += static_cast<std::streamoff>(line.size()) + 1;
        split_record(line, f);
        if (!f.empty() && f[0] == kDone) {
            if (f.size() != 3) throw InputError(fmt::format("journal {}: a malformed closing line '{}'", path.string(), line));
            const TaskKey key{static_cast<int>(parse_long(f[1], path)), static_cast<std::size_t>(parse_long(f[2], path))};
            for (ResultRow& r : pending)
                if (r.case_id != key.first || r.run != key.second)
                    throw InputError(fmt::format("journal {}: rows of another task before '{}'", path.string(), line));
            if (seen.insert(key).second) {
                rows.insert(rows.end(), std::make_move_iterator(pending.begin()), std::make_move_iterator(pending.end()));
                if (ida) ida->insert(ida->end(), pending_ida.begin(), pending_ida.end());
            }
            pending.clear();
            pending_ida.clear();
            if (done) done->insert(key);
            whole = read;
            continue;
        }
        if (!f.empty() && f[0] == kIda) {
            if (f.size() != 6) throw InputError(fmt::format("journal {}: a malformed IDA line '{}'", path.string(), line));
            IdaRow p;
            p.case_id = static_cast<int>(parse_long(f[1], path));
            p.run = static_cast<std::size_t>(parse_long(f[2], path));
            p.point = {std::strtod(f[3].c_str(), nullptr), std::strtod(f[4].c_str(), nullptr), f[5] == "1"};
            pending_ida.push_back(p);
            continue;
        }
        if (f.size() != 6) throw InputError(fmt::format("journal {}: a malformed row '{}'", path.string(), line));
        ResultRow r;
        r.case_id = static_cast<int>(parse_long(f[0], path));
        r.run = static_cast<std::size_t>(parse_long(f[1], path));
        r.metric = static_cast<std::size_t>(parse_long(f[2], path));
        r.value = f[3].empty() ? std::numeric_limits<double>::quiet_NaN() : std::strtod(f[3].c_str(), nullptr);
        r.status = f[4];
        r.warnings = f[5];
        pending.push_back(std::move(r));
    }
    if (end_of_whole) *end_of_whole = whole;
    return rows;
}

}  // namespace

std::string journal_text(int case_id, std::size_t run, const std::vector<Measurement>& rows,
                         const std::vector<IdaPoint>& ida) {
    std::string text;
    for (const Measurement& m : rows)
        text += fmt::format("{},{},{},{},{},{}\n", case_id, run, m.metric, io::csv_number(m.value), io::csv_field(m.status),
                            io::csv_field(m.warnings));
    for (const IdaPoint& p : ida)
        text += fmt::format("{},{},{},{},{},{}\n", kIda, case_id, run, io::csv_number(p.scale), io::csv_number(p.peak),
                            p.overturned ? 1 : 0);
    text += fmt::format("{},{},{}\n", kDone, case_id, run);
    return text;
}

Journal::Journal(std::filesystem::path path, const std::string& identity, Shard shard) : path_(std::move(path)) {
    out_.open(path_, std::ios::binary | std::ios::trunc);
    if (!out_) throw InputError(fmt::format("cannot write the study journal '{}'", path_.string()));
    out_ << header(identity, shard) << '\n' << std::flush;
}

Journal::Journal(std::filesystem::path path, const std::string& identity, Shard shard, std::set<TaskKey>& done)
    : path_(std::move(path)) {
    std::streamoff whole = 0;
    (void)read_whole_tasks(path_, &identity, &shard, &done, &whole);
    std::error_code ec;
    std::filesystem::resize_file(path_, static_cast<std::uintmax_t>(whole), ec);  // drop a half-written task
    if (ec) throw InputError(fmt::format("cannot continue the study journal '{}': {}", path_.string(), ec.message()));
    out_.open(path_, std::ios::binary | std::ios::app);
    if (!out_) throw InputError(fmt::format("cannot write the study journal '{}'", path_.string()));
}

void Journal::append_text(const std::string& text) {
    const std::lock_guard<std::mutex> lock(mutex_);
    out_ << text << std::flush;
    if (!out_) throw InputError(fmt::format("error while writing the study journal '{}'", path_.string()));
}

std::vector<ResultRow> read_journal(const std::filesystem::path& path, std::vector<IdaRow>* ida) {
    return read_whole_tasks(path, nullptr, nullptr, nullptr, nullptr, ida);
}

void check_journal(const std::filesystem::path& path, const std::string& identity, Shard shard) {
    (void)read_whole_tasks(path, &identity, &shard, nullptr, nullptr);
}

}  // namespace vssw::study
