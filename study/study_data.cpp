#include "study/study_data.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <set>
#include <tuple>
#include <unordered_map>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "analytic/input_file.hpp"
#include "io/csv.hpp"
#include "study/outputs.hpp"
#include "study/runner.hpp"
#include "study/spec.hpp"
#include "io/text.hpp"
#include "multibody/engine.hpp"

namespace vssw::study {
namespace fs = std::filesystem;
namespace {

// Columns holding numbers that name things rather than measure them: a categorical axis, not a numeric one.
const std::set<std::string> kIdColumns = {"engine", "settings", "specimen"};

// The units of the parameter columns, for axis labels.
const std::map<std::string, std::string> kParameterUnits = {
    {"height", "m"},   {"thickness", "m"},   {"density", "kg/m^3"}, {"g", "m/s^2"},    {"alpha", "rad"},
    {"R", "m"},        {"alpha1", "rad"},    {"alpha2", "rad"},     {"R1", "m"},       {"theta0", "alpha1"},
    {"pga", "g"},      {"amplitude", "g"},   {"pulse_period", "s"}, {"duration", "s"}, {"max_pga", "g"}};

// A whole field read as a number; NaN when it is not one.
double number_of(const std::string& text) {
    if (text.empty()) return std::nan("");
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    return *end == '\0' ? v : std::nan("");
}

// Significant digits that make two numbers one level: a derived column (R of a wall given by alpha and R) carries the
// last bits of its computation (3.0000000000000004 beside 3); twelve digits hold every level a study file can sensibly
// give apart.
constexpr int kLevelDigits = 12;

// A level's text: a number in its shortest form at kLevelDigits, a word as it is.
std::string canonical_level(const std::string& text) {
    const double v = number_of(text);
    return std::isfinite(v) ? fmt::format("{:.{}g}", v, kLevelDigits) : text;
}

// Interns the texts of one raw column and, for a parameter column, their canonical levels.
class Interner {
public:
    Interner(RawColumn& raw, ColumnLevels* column) : raw_(raw), column_(column) {
        if (!column_) return;
        column_->texts = {""};
        column_->values = {std::nan("")};
        index_[""] = kEmptyLevel;
    }
    std::uint32_t id(const std::string& field) {
        // A column repeats a few texts over many rows: each distinct one is kept, and made canonical, once.
        if (const auto seen = raw_index_.find(field); seen != raw_index_.end()) return seen->second;
        const auto id = static_cast<std::uint32_t>(raw_.texts.size());
        raw_.texts.push_back(field);
        if (column_) raw_.level.push_back(canonical_id(field));
        raw_index_.emplace(field, id);
        return id;
    }

private:
    std::uint32_t canonical_id(const std::string& field) {
        const std::string text = canonical_level(field);
        const auto [it, inserted] = index_.try_emplace(text, static_cast<std::uint32_t>(column_->texts.size()));
        if (inserted) {
            column_->texts.push_back(text);
            column_->values.push_back(number_of(text));
            column_->order.push_back(it->second);
        }
        return it->second;
    }

    RawColumn& raw_;
    ColumnLevels* column_;
    std::unordered_map<std::string, std::uint32_t> index_;      // by canonical text
    std::unordered_map<std::string, std::uint32_t> raw_index_;  // by the text as the file gives it
};

std::size_t header_index(const std::vector<std::string>& header, const std::string& name) {
    const auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end()) throw InputError(fmt::format("no column '{}'", name));
    return static_cast<std::size_t>(it - header.begin());
}

void read_metrics(StudyData& d) {
    for (const io::Json& m : d.manifest.at("metrics"))
        d.metrics.push_back({m.at("name").get<std::string>(), m.at("unit").get<std::string>(),
                             m.value("description", std::string()), false, false});
}

std::vector<std::string> metric_names(const io::Json& manifest) {
    std::vector<std::string> names;
    for (const io::Json& m : manifest.at("metrics")) names.push_back(m.at("name").get<std::string>());
    return names;
}

// The assumption levels in the order of the manifest's runs (the file's order), ahead of any the runs do not name.
void order_assumptions(StudyData& d) {
    for (ColumnLevels& c : d.columns) {
        if (!c.assumption) continue;
        std::vector<std::uint32_t> order;
        for (const io::Json& run : d.manifest.at("runs")) {
            if (!run.contains(c.key)) continue;
            const std::string text = canonical_level(run.at(c.key).get<std::string>());
            for (std::uint32_t id = 1; id < c.texts.size(); ++id)
                if (c.texts[id] == text && std::find(order.begin(), order.end(), id) == order.end())
                    order.push_back(id);
        }
        for (std::uint32_t id : c.order)
            if (std::find(order.begin(), order.end(), id) == order.end()) order.push_back(id);
        c.order = order;
    }
}

void classify_columns(StudyData& d) {
    for (const std::string& key : kAssumptionKeys) d.assumption_columns.push_back(d.column(key));
    std::set<std::string> varied;
    for (const io::Json& v : d.manifest.at("varied")) varied.insert(v.get<std::string>());
    for (ColumnLevels& c : d.columns) {
        c.assumption = std::find(kAssumptionKeys.begin(), kAssumptionKeys.end(), c.key) != kAssumptionKeys.end();
        c.physical = std::find(kPhysicalAssumptionKeys.begin(), kPhysicalAssumptionKeys.end(), c.key) !=
                     kPhysicalAssumptionKeys.end();
        c.varied = varied.count(c.key) > 0;
        const auto is_number = [&](std::uint32_t id) { return std::isfinite(c.values[id]); };
        c.numeric = !kIdColumns.count(c.key) && !c.order.empty() &&
                    std::all_of(c.order.begin(), c.order.end(), is_number);
    }
}

void read_series(StudyData& d) {
    for (const io::Json& run : d.manifest.at("runs")) {
        Series s;
        s.engine = run.at("engine").get<std::string>();
        s.settings = run.value("settings", std::string());
        s.set = run.value("set", std::string());  // "" in a folder written before the sets had names
        for (const std::string& key : kAssumptionKeys)
            s.assumptions.push_back(run.contains(key) ? canonical_level(run.at(key).get<std::string>())
                                                      : std::string());
        s.label = d.series_label(s);
        d.series.push_back(std::move(s));
    }
}

// results.csv's header and records into the builder (InputError naming the file).
StudyDataBuilder read_rows(const fs::path& path, std::vector<std::string> metrics) {
    std::ifstream in = open_input_file(path, "the study's results", kMaxResultsBytes);
    try {
        std::vector<std::string> header, fields;
        if (!io::read_csv_record(in, header) || header.empty() || header.front() != "case_id")
            throw InputError("no header line starting with case_id");
        StudyDataBuilder rows(std::move(header), std::move(metrics));
        while (io::read_csv_record(in, fields)) {
            if (fields.size() == 1 && fields[0].empty()) continue;  // a blank line
            rows.add(fields);
        }
        return rows;
    } catch (const InputError& e) {
        throw InputError(fmt::format("{}: {}", path.string(), e.what()));
    }
}

void classify_metrics(StudyData& d) {
    std::vector<bool> only_0_1(d.metrics.size(), true);
    for (const StudyRow& r : d.rows) {
        if (!std::isfinite(r.value)) continue;
        d.metrics[r.metric].any_value = true;
        if (r.value != 0.0 && r.value != 1.0) only_0_1[r.metric] = false;
    }
    for (std::size_t m = 0; m < d.metrics.size(); ++m) d.metrics[m].binary = d.metrics[m].any_value && only_0_1[m];
}

}  // namespace

bool is_failed(const std::string& status) { return status.rfind("failed", 0) == 0; }

std::string failure_reason(const std::string& status) {
    const auto colon = status.find(": ");
    return colon == std::string::npos ? status : status.substr(colon + 2);
}

std::size_t StudyData::column(const std::string& key) const {
    for (std::size_t c = 0; c < columns.size(); ++c)
        if (columns[c].key == key) return c;
    return std::string::npos;
}

std::vector<std::size_t> StudyData::varied() const {
    std::vector<std::size_t> out;
    for (std::size_t c = 0; c < columns.size(); ++c)
        if (columns[c].varied) out.push_back(c);
    return out;
}

bool StudyData::in_series(const StudyRow& row, const Series& s, const std::vector<std::size_t>& ignored) const {
    if (text(row, 0) != s.engine || text(row, columns.size() - 1) != s.settings) return false;
    for (std::size_t i = 0; i < kAssumptionKeys.size(); ++i) {
        const std::size_t c = assumption_columns[i];
        if (c == std::string::npos || row.levels[c] == kEmptyLevel) continue;
        if (std::find(ignored.begin(), ignored.end(), c) != ignored.end()) continue;
        if (text(row, c) != s.assumptions[i]) return false;
    }
    return true;
}

std::string StudyData::series_label(const Series& s, const std::vector<std::size_t>& ignored) const {
    std::string label = multibody::engine_display_name(s.engine);
    for (std::size_t i = 0; i < kAssumptionKeys.size() && s.analytic(); ++i) {
        const std::size_t c = assumption_columns[i];
        if (c == std::string::npos || !columns[c].varied) continue;
        if (std::find(ignored.begin(), ignored.end(), c) != ignored.end()) continue;
        label += fmt::format(" {}={}", kAssumptionKeys[i], s.assumptions[i]);
    }
    return s.settings.empty() ? label : label + " " + s.settings;
}

// The columns kept as the file gives them, each with its interner.
struct StudyDataBuilder::Interners {
    std::vector<Interner> raw;
    std::unordered_map<std::string, std::uint32_t> metric, status, warning;
};

StudyDataBuilder::StudyDataBuilder(std::vector<std::string> header, std::vector<std::string> metrics)
    : metric_names_(std::move(metrics)), interners_(std::make_shared<Interners>()) {
    d_.header = std::move(header);
    const std::vector<std::string>& h = d_.header;
    case_id_ = header_index(h, "case_id");
    first_ = header_index(h, "engine");
    const std::size_t last = header_index(h, "settings");
    metric_ = header_index(h, "metric");
    value_ = header_index(h, "value");
    status_ = header_index(h, "status");
    warnings_ = header_index(h, "warnings");
    if (last < first_) throw InputError("the column 'settings' comes before 'engine'");
    d_.columns.resize(last - first_ + 1);
    for (std::size_t c = 0; c < d_.columns.size(); ++c) d_.columns[c].key = h[first_ + c];
    for (std::size_t i = 0; i < h.size(); ++i) {
        if (i == case_id_ || i == metric_ || i == value_ || i == status_ || i == warnings_) continue;
        RawColumn raw;
        raw.field = i;
        if (i >= first_ && i <= last) raw.level_column = i - first_;
        d_.raw_columns.push_back(std::move(raw));
    }
    for (RawColumn& raw : d_.raw_columns)
        interners_->raw.emplace_back(raw, raw.level_column == std::string::npos ? nullptr
                                                                                 : &d_.columns[raw.level_column]);
    for (std::size_t m = 0; m < metric_names_.size(); ++m)
        interners_->metric[metric_names_[m]] = static_cast<std::uint32_t>(m);
}

void StudyDataBuilder::add(const std::vector<std::string>& fields, bool same_columns) {
    if (fields.size() != d_.header.size())
        throw InputError(fmt::format("a row of {} fields, the header has {}", fields.size(), d_.header.size()));
    StudyRow row;
    char* end = nullptr;
    row.case_id = static_cast<int>(std::strtol(fields[case_id_].c_str(), &end, 10));
    if (fields[case_id_].empty() || *end != '\0')
        throw InputError(fmt::format("case_id '{}' is not a number", fields[case_id_]));
    const auto m = interners_->metric.find(fields[metric_]);
    if (m == interners_->metric.end())
        throw InputError(fmt::format("metric '{}' is not one of the manifest's", fields[metric_]));
    row.metric = m->second;
    row.value = std::nan("");  // an empty value: none
    if (const std::string& value = fields[value_]; !value.empty()) {
        row.value = std::strtod(value.c_str(), &end);
        if (*end != '\0') throw InputError(fmt::format("value '{}' is not a number", value));
    }
    row.levels.resize(d_.columns.size());
    row.raw.resize(d_.raw_columns.size());
    for (std::size_t k = 0; k < d_.raw_columns.size(); ++k) {
        const RawColumn& raw = d_.raw_columns[k];
        const bool parameter = raw.level_column != std::string::npos;
        row.raw[k] = same_columns && parameter ? last_raw_[k] : interners_->raw[k].id(fields[raw.field]);
        if (parameter) row.levels[raw.level_column] = raw.level[row.raw[k]];
    }
    const std::string& status = fields[status_];
    const auto [st, added] = interners_->status.try_emplace(status, static_cast<std::uint32_t>(d_.statuses.size()));
    if (added) d_.statuses.push_back(status);
    row.status = st->second;
    if (is_failed(status)) {
        ++d_.failed_rows;
        ++d_.failure_reasons[failure_reason(status)];
    }
    if (const std::string& warning = fields[warnings_]; !warning.empty()) {
        ++d_.warned_rows;
        warned_tasks_.insert({row.case_id, row.levels});
        const auto [w, new_warning] =
            interners_->warning.try_emplace(warning, static_cast<std::uint32_t>(d_.warnings.size()));
        if (new_warning) d_.warnings.push_back(warning);
        row.warning = w->second;
    }
    last_raw_ = row.raw;
    d_.rows.push_back(std::move(row));
}

StudyData StudyDataBuilder::finish(io::Json manifest) {
    StudyData d = std::move(d_);
    d.manifest = std::move(manifest);
    d.warned_tasks = static_cast<long>(warned_tasks_.size());
    try {
        const io::Json& study = d.manifest.at("study");
        d.name = study.at("name").get<std::string>();
        d.description = study.value("description", std::string());
        d.kind = study.at("kind").get<std::string>();
        read_metrics(d);
        if (const std::vector<std::string> named = metric_names(d.manifest); named != metric_names_) {
            throw InputError(fmt::format("its metrics [{}] are not those of the rows [{}]", fmt::join(named, ", "),
                                         fmt::join(metric_names_, ", ")));
        }
        classify_columns(d);
        order_assumptions(d);
        read_series(d);
    } catch (const io::Json::exception& e) {
        throw InputError(e.what());
    }
    classify_metrics(d);
    return d;
}

StudyData read_study_data(const fs::path& dir) {
    io::Json manifest = read_manifest(dir);
    const auto not_a_manifest = [&](const std::exception& e) {
        return InputError(fmt::format("'{}' is not a study manifest: {}", (dir / kManifestFile).string(), e.what()));
    };
    std::vector<std::string> metrics;
    try {
        metrics = metric_names(manifest);
    } catch (const io::Json::exception& e) {
        throw not_a_manifest(e);
    }
    StudyDataBuilder rows = read_rows(dir / kResultsCsv, std::move(metrics));
    try {
        return rows.finish(std::move(manifest));
    } catch (const InputError& e) {
        throw not_a_manifest(e);
    }
}

std::string parameter_label(const std::string& key) {
    const auto it = kParameterUnits.find(key);
    return it == kParameterUnits.end() ? key : fmt::format("{} [{}]", key, it->second);
}

std::string metric_label(const MetricMeta& metric) {
    return metric.unit.empty() ? metric.name : fmt::format("{} [{}]", metric.name, metric.unit);
}

}  // namespace vssw::study
