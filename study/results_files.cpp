#include "study/results_files.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <ostream>
#include <set>
#include <string>

#include <fmt/format.h>

#include "analytic/assumption_sets.hpp"
#include "analytic/error.hpp"
#include "analytic/input_file.hpp"
#include "io/csv.hpp"
#include "io/json.hpp"
#include "study/metric_catalog.hpp"

namespace vssw::study {
namespace {

using Json = nlohmann::ordered_json;

// Columns whose values are numbers in results.json (the rest are words; empty is null in both).
const std::set<std::string> kNumericColumns = {
    "case_id", "height", "thickness", "hinge",  "xi",     "density",  "g",        "theta0",   "scale",
    "pga",     "amplitude", "pulse_period", "alpha", "R", "alpha1", "alpha2", "R1", "specimen", "duration",
    "tolerance", "max_pga", "step", "overburden_eccentricity", "friction", "hinge_friction", "value", "corner_radius",
    "diaphragm_period", "diaphragm_damping"};

}  // namespace

std::vector<std::string> results_header(const Grid& grid) {
    std::vector<std::string> h = {"case_id", "engine"};
    h.insert(h.end(), grid.columns().begin(), grid.columns().end());
    for (const char* c : {"metric", "value", "unit", "status", "warnings"}) h.push_back(c);
    return h;
}

void write_results_csv(std::ostream& out, const Grid& grid, const std::vector<ResultRow>& rows) {
    const std::vector<std::string> header = results_header(grid);
    for (std::size_t i = 0; i < header.size(); ++i) out << (i ? "," : "") << header[i];
    out << '\n';
    const StudySpec& spec = grid.spec();
    std::vector<std::string> units;  // each metric's unit as a CSV field, looked up once
    for (const std::string& m : spec.metrics) units.push_back(io::csv_field(metric_info(m).unit));
    int cached_id = 0;
    std::size_t cached_run = 0;
    CaseSpec c;
    std::string case_fields;  // the row's start, the same for every metric of one case and run (rows come so sorted)
    std::string line;
    for (const ResultRow& r : rows) {
        if (r.case_id != cached_id) c = grid.make_case(r.case_id);
        const RunSpec& run = grid.runs().at(r.run);
        if (r.case_id != cached_id || r.run != cached_run || case_fields.empty()) {
            case_fields = fmt::format("{},{}", r.case_id, io::csv_field(run.engine));
            for (const std::string& v : grid.column_values(c, run)) (case_fields += ',') += io::csv_field(v);
            cached_id = r.case_id;
            cached_run = r.run;
        }
        const std::string& metric = spec.metrics.at(r.metric);
        const std::string& unit = units.at(r.metric);
        line = case_fields;
        // Shortest exact form: a value reads back to the same double, and a tidy file stays short.
        ((line += ',') += metric) += ',';
        if (std::isfinite(r.value)) fmt::format_to(std::back_inserter(line), "{}", r.value);
        (line += ',') += unit;
        (line += ',') += io::csv_field(r.status);
        (line += ',') += io::csv_field(r.warnings);
        line += '\n';
        out << line;
    }
}

Json manifest_json(const Grid& grid, const StudyMeta& meta) {
    const StudySpec& spec = grid.spec();
    Json engines = Json::array();
    for (const EngineVersion& e : meta.engines) engines.push_back({{"name", e.name}, {"version", e.version}});
    Json runs = Json::array();
    for (const RunSpec& r : grid.runs()) {
        Json j = {{"engine", r.engine}, {"settings", r.settings_text}};
        if (r.engine == "analytic") {
            j["set"] = set_name(Assumptions{r.kinematics, r.impact, r.roller});  // paper, mechanism or custom
            for (std::size_t i = 0; i < spec.assumptions.size(); ++i)
                j[spec.assumptions[i].key] = to_text(r.assumptions[i]);
        }
        runs.push_back(j);
    }
    Json metrics = Json::array();
    for (const std::string& m : spec.metrics) {
        const compare::MetricInfo& info = metric_info(m);
        metrics.push_back({{"name", m}, {"unit", info.unit}, {"description", info.description}});
    }
    Json j;
    j["vssw"] = {{"commit", meta.commit}, {"study_format", kStudyFormat}};
    j["study"] = {{"name", spec.name},
                  {"description", spec.description},
                  {"file", spec.path},
                  {"base_dir", spec.base_dir},
                  {"identity", grid.identity()},
                  {"kind", spec.kind_text()},
                  {"as_read", spec.as_read}};
    j["shard"] = {{"k", meta.shard.k}, {"n", meta.shard.n}};
    j["date"] = meta.date;
    j["engines"] = engines;
    j["columns"] = results_header(grid);
    j["varied"] = grid.varied_parameters();
    j["metrics"] = metrics;
    // This shard's cases: `vssw study merge` sums them over the shards.
    j["cases"] = {{"in_grid", grid.product_size()}, {"total", grid.case_ids().size()}, {"run", grid.shard_case_ids(meta.shard.k, meta.shard.n).size()}};
    j["runs"] = runs;
    j["skipped_runs"] = grid.skipped_runs();
    j["tasks"] = {{"run", meta.tasks_run}, {"resumed", meta.tasks_resumed}};
    if (meta.result_rows >= 0) j["results"] = {{"rows", meta.result_rows}, {"fnv1a64", meta.results_hash}};
    j["wall_time_s"] = meta.wall_time_s;
    j["threads"] = meta.threads;
    j["processes"] = meta.processes;
    j["run_budget_s"] = meta.run_budget_s ? nlohmann::ordered_json(*meta.run_budget_s) : nlohmann::ordered_json(nullptr);
    return j;
}

std::size_t ResultsTable::column(const std::string& name) const {
    const auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end()) throw InputError(fmt::format("results.csv has no column '{}'", name));
    return static_cast<std::size_t>(it - header.begin());
}

ResultsTable read_results_csv(const std::filesystem::path& path) {
    std::ifstream in = open_input_file(path, "the study's results", kMaxResultsBytes);
    ResultsTable t;
    try {
        if (!io::read_csv_record(in, t.header) || t.header.empty() || t.header.front() != "case_id")
            throw InputError("no header line starting with case_id");
        std::vector<std::string> fields;
        while (io::read_csv_record(in, fields)) {
            if (fields.size() == 1 && fields[0].empty()) continue;  // a blank line
            if (fields.size() != t.header.size())
                throw InputError(fmt::format("row {} has {} fields, the header {}", t.rows.size() + 2, fields.size(),
                                             t.header.size()));
            t.rows.push_back(fields);
        }
    } catch (const InputError& e) {
        throw InputError(fmt::format("{}: {}", path.string(), e.what()));
    }
    return t;
}

std::string file_fnv1a(const std::filesystem::path& path) {
    std::ifstream in = open_input_file(path, "the study's results", kMaxResultsBytes);
    std::uint64_t h = 14695981039346656037ull;  // FNV-1a 64's offset basis and prime, as grid.cpp's identity
    char buf[1 << 16];
    while (in) {
        in.read(buf, sizeof buf);
        for (std::streamsize i = 0; i < in.gcount(); ++i) {
            h ^= static_cast<unsigned char>(buf[i]);
            h *= 1099511628211ull;
        }
    }
    return fmt::format("{:016x}", h);
}

namespace {

// The text dump_json gives the JSON string `text`: the text quoted as it is when no byte of it needs escaping or a
// check (the common case: numbers, names), else dump_json's own (escapes, bytes that are not UTF-8).
void append_json_string(std::string& out, const std::string& text) {
    const bool plain = std::all_of(text.begin(), text.end(), [](char c) {
        const auto byte = static_cast<unsigned char>(c);
        return byte >= 0x20 && byte < 0x7f && c != '"' && c != '\\';
    });
    if (!plain) {
        out += io::dump_json(Json(text));
        return;
    }
    out += '"';
    out += text;
    out += '"';
}

// The text dump_json gives the JSON number `x`: nlohmann's own shortest round-trip form ("0.5", "1.0", "1e-05"), or
// null for NaN and infinities, as its serializer writes them.
void append_json_number(std::string& out, double x) {
    if (!std::isfinite(x)) {
        out += "null";
        return;
    }
    std::array<char, 64> digits{};  // the serializer's own buffer size
    const char* end = nlohmann::detail::to_chars(digits.data(), digits.data() + digits.size(), x);
    out.append(digits.data(), static_cast<std::size_t>(end - digits.data()));
}

// One row of results.csv as the line dump_json gives the object {header[i]: field} (keys in the header's order, no
// spaces): an empty field null, a number in a numeric column a number (case_id and specimen whole), anything else a
// string. Written as text, not built as a Json object and dumped, which cost a quarter of a closed-form study's time.
void append_json_row(std::string& out, const std::vector<std::string>& keys, const std::vector<char>& numeric,
                     const std::vector<char>& whole, const std::vector<std::string>& fields) {
    out += '{';
    for (std::size_t i = 0; i < keys.size(); ++i) {
        if (i > 0) out += ',';
        out += keys[i];
        out += ':';
        const std::string& v = fields[i];
        char* end = nullptr;
        const double x = std::strtod(v.c_str(), &end);
        const bool number = !v.empty() && *end == '\0';  // a word in a numeric column (hinge "eq15") stays a word
        if (v.empty()) out += "null";
        else if (!number || !numeric[i]) append_json_string(out, v);
        else if (whole[i]) out += std::to_string(static_cast<long>(x));
        else append_json_number(out, x);
    }
    out += '}';
}

}  // namespace

void write_results_json(std::ostream& out, const Json& manifest, const std::filesystem::path& csv) {
    // Streamed: the manifest's keys, then "rows" one object at a time, so that a large study needs no large JSON
    // value in memory.
    std::string head = io::dump_json(manifest, 2);
    head.pop_back();  // the closing brace
    while (!head.empty() && (head.back() == '\n' || head.back() == ' ')) head.pop_back();
    out << head << ",\n  \"rows\": [";
    std::ifstream in(csv, std::ios::binary);
    if (!in) throw InputError(fmt::format("cannot read '{}'", csv.string()));
    std::vector<std::string> header, fields;
    io::read_csv_record(in, header);
    // Each column's key as JSON text and its kind, once. A key twice in the header would be one key of the object:
    // results.csv has none (results_header), and such a file is refused rather than written otherwise.
    std::vector<std::string> keys(header.size());
    std::vector<char> numeric(header.size()), whole(header.size());
    for (std::size_t i = 0; i < header.size(); ++i) {
        if (std::count(header.begin(), header.end(), header[i]) > 1)
            throw InputError(fmt::format("'{}': the column '{}' is named twice", csv.string(), header[i]));
        append_json_string(keys[i], header[i]);
        numeric[i] = kNumericColumns.count(header[i]) > 0;
        whole[i] = header[i] == "case_id" || header[i] == "specimen";
    }
    bool first = true;
    std::string line;
    while (io::read_csv_record(in, fields)) {
        if (fields.size() != header.size()) continue;
        line.assign(first ? "\n    " : ",\n    ");
        append_json_row(line, keys, numeric, whole, fields);
        out << line;
        first = false;
    }
    out << (first ? "]\n}\n" : "\n  ]\n}\n");
}


}  // namespace vssw::study
