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
#include <string_view>

#include <fmt/format.h>

#include "analytic/assumption_sets.hpp"
#include "analytic/error.hpp"
#include "analytic/input_file.hpp"
#include "io/csv.hpp"
#include "io/fnv1a.hpp"
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

std::string write_results_csv(std::ostream& out, const Grid& grid, const std::vector<ResultRow>& rows,
                              StudyDataBuilder* data) {
    const std::vector<std::string> header = results_header(grid);
    io::Fnv1a hash;
    std::string line;
    for (std::size_t i = 0; i < header.size(); ++i) (line += (i ? "," : "")) += header[i];
    line += '\n';
    out << line;
    hash.add(line);
    const StudySpec& spec = grid.spec();
    std::vector<std::string> units, unit_fields;  // each metric's unit, and as a CSV field, looked up once
    for (const std::string& m : spec.metrics) {
        units.push_back(metric_info(m).unit);
        unit_fields.push_back(io::csv_field(units.back()));
    }
    // The row's fields: the case's and run's (case_id to settings) are the same for every metric of one case and run
    // (rows come so sorted), and so is their start of the line.
    std::vector<std::string> fields(header.size());
    const std::size_t metric_field = header.size() - 5;
    int cached_id = 0;
    std::size_t cached_run = 0;
    CaseSpec c;
    std::string case_fields;
    for (const ResultRow& r : rows) {
        if (r.case_id != cached_id) c = grid.make_case(r.case_id);
        const RunSpec& run = grid.runs().at(r.run);
        const bool same_case = r.case_id == cached_id && r.run == cached_run && !case_fields.empty();
        if (!same_case) {
            fields[0] = std::to_string(r.case_id);
            fields[1] = run.engine;
            std::vector<std::string> values = grid.column_values(c, run);
            std::move(values.begin(), values.end(), fields.begin() + 2);
            case_fields = fields[0];
            for (std::size_t i = 1; i < metric_field; ++i) (case_fields += ',') += io::csv_field(fields[i]);
            cached_id = r.case_id;
            cached_run = r.run;
        }
        fields[metric_field] = spec.metrics.at(r.metric);
        fields[metric_field + 1].clear();
        // Shortest exact form: a value reads back to the same double, and a tidy file stays short.
        if (std::isfinite(r.value)) fmt::format_to(std::back_inserter(fields[metric_field + 1]), "{}", r.value);
        fields[metric_field + 2] = units.at(r.metric);
        fields[metric_field + 3] = r.status;
        fields[metric_field + 4] = r.warnings;
        line = case_fields;
        ((line += ',') += fields[metric_field]) += ',';
        line += fields[metric_field + 1];
        (line += ',') += unit_fields.at(r.metric);
        (line += ',') += io::csv_field(r.status);
        (line += ',') += io::csv_field(r.warnings);
        line += '\n';
        out << line;
        hash.add(line);
        if (data) data->add(fields, same_case);
    }
    return hash.hex();
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
    io::Fnv1a hash;
    char buf[1 << 16];
    while (in) {
        in.read(buf, sizeof buf);
        hash.add(std::string_view(buf, static_cast<std::size_t>(in.gcount())));
    }
    return hash.hex();
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

// A field of results.csv as dump_json gives it in its row's object: an empty field null, a number in a numeric column a
// number (case_id and specimen whole), anything else a string.
void append_json_field(std::string& out, const std::string& v, bool numeric, bool whole) {
    char* end = nullptr;
    const double x = std::strtod(v.c_str(), &end);
    const bool number = !v.empty() && *end == '\0';  // a word in a numeric column (hinge "eq15") stays a word
    if (v.empty()) out += "null";
    else if (!number || !numeric) append_json_string(out, v);
    else if (whole) out += std::to_string(static_cast<long>(x));
    else append_json_number(out, x);
}

// Where a row's field comes from in StudyData: its own members, or a raw column's texts.
enum class FieldSource { case_id, metric, value, status, warnings, raw };

}  // namespace

void write_results_json(std::ostream& out, const StudyData& data) {
    // Streamed: the manifest's keys, then "rows" one object at a time, so that a large study needs no large JSON
    // value in memory.
    std::string head = io::dump_json(data.manifest, 2);
    head.pop_back();  // the closing brace
    while (!head.empty() && (head.back() == '\n' || head.back() == ' ')) head.pop_back();
    out << head << ",\n  \"rows\": [";
    // Each row is the line dump_json gives the object {header[i]: field} (keys in the header's order, no spaces),
    // written as text rather than built as a Json object and dumped (a quarter of a closed-form study's time once).
    // Each distinct field ("key":value) is made once: the rows repeat a few texts. A key twice in the header would be
    // one key of the object: results.csv has none (results_header), and such a file is refused rather than written
    // otherwise.
    const std::vector<std::string>& header = data.header;
    const auto fragment = [&](std::size_t i, const std::string& text) {
        std::string f;
        append_json_string(f, header[i]);
        f += ':';
        append_json_field(f, text, kNumericColumns.count(header[i]) > 0, header[i] == "case_id" || header[i] == "specimen");
        return f;
    };
    std::vector<FieldSource> source(header.size(), FieldSource::raw);
    std::vector<std::size_t> raw_of(header.size());
    std::vector<std::string> keys(header.size());  // "key": for the fields written per row
    const std::vector<std::pair<const char*, FieldSource>> own = {{"case_id", FieldSource::case_id},
                                                                  {"metric", FieldSource::metric},
                                                                  {"value", FieldSource::value},
                                                                  {"status", FieldSource::status},
                                                                  {"warnings", FieldSource::warnings}};
    for (std::size_t i = 0; i < header.size(); ++i) {
        if (std::count(header.begin(), header.end(), header[i]) > 1)
            throw InputError(fmt::format("results.csv: the column '{}' is named twice", header[i]));
        for (const auto& [name, from] : own)
            if (header[i] == name) source[i] = from;
        append_json_string(keys[i], header[i]);
        keys[i] += ':';
    }
    std::vector<std::vector<std::string>> raw(data.raw_columns.size());
    for (std::size_t k = 0; k < data.raw_columns.size(); ++k) {
        raw_of[data.raw_columns[k].field] = k;
        for (const std::string& text : data.raw_columns[k].texts) raw[k].push_back(fragment(data.raw_columns[k].field, text));
    }
    const auto texts_of = [&](FieldSource from, const std::vector<std::string>& texts) {
        std::vector<std::string> made;
        const auto i = static_cast<std::size_t>(std::find(source.begin(), source.end(), from) - source.begin());
        for (const std::string& t : texts) made.push_back(fragment(i, t));
        return made;
    };
    std::vector<std::string> metric_names;
    for (const MetricMeta& m : data.metrics) metric_names.push_back(m.name);
    const std::vector<std::string> metrics = texts_of(FieldSource::metric, metric_names);
    const std::vector<std::string> statuses = texts_of(FieldSource::status, data.statuses);
    const std::vector<std::string> warnings = texts_of(FieldSource::warnings, data.warnings);
    std::string line;
    for (std::size_t r = 0; r < data.rows.size(); ++r) {
        const StudyRow& row = data.rows[r];
        line.assign(r ? ",\n    {" : "\n    {");
        for (std::size_t i = 0; i < header.size(); ++i) {
            if (i > 0) line += ',';
            switch (source[i]) {
                case FieldSource::case_id: (line += keys[i]) += std::to_string(row.case_id); break;
                case FieldSource::metric: line += metrics[row.metric]; break;
                case FieldSource::value: line += keys[i]; append_json_number(line, row.value); break;
                case FieldSource::status: line += statuses[row.status]; break;
                case FieldSource::warnings: line += warnings[row.warning]; break;
                case FieldSource::raw: line += raw[raw_of[i]][row.raw[raw_of[i]]]; break;
            }
        }
        line += '}';
        out << line;
    }
    out << (data.rows.empty() ? "]\n}\n" : "\n  ]\n}\n");
}

}  // namespace vssw::study
