#include "cli/stress_output.hpp"

#include <algorithm>
#include <ostream>

#include <fmt/format.h>

#include "stress/case.hpp"
#include "io/csv.hpp"

namespace vssw::cli {
namespace {

// "ok", "refused", "failed (timed_out)": the short form of a cell.
std::string cell(const stress::CaseResult& c) {
    if (c.verdict != stress::Verdict::failed) return stress::to_string(c.verdict);
    return fmt::format("failed ({})", stress::to_string(c.failure));
}

std::vector<std::string> case_names(const StressReport& r) {
    std::vector<std::string> names;
    for (const auto& c : r.cases)
        if (std::find(names.begin(), names.end(), c.name) == names.end()) names.push_back(c.name);
    return names;
}

const stress::CaseResult* find(const StressReport& r, const std::string& name, const std::string& engine) {
    for (const auto& c : r.cases)
        if (c.name == name && c.engine == engine) return &c;
    return nullptr;
}

std::string step_text(const std::optional<double>& dt) { return dt ? fmt::format("{:.3g} ms", *dt * 1e3) : "-"; }

}  // namespace

io::Json stress_json(const StressReport& r) {
    io::Json doc;
    doc["quick"] = r.quick;
    doc["time_limit_s"] = r.time_limit_s;
    doc["engines"] = r.engines;
    io::Json cases = io::Json::array();
    size_t unsafe = 0;
    for (const auto& c : r.cases) {
        io::Json j;
        j["name"] = c.name;
        j["engine"] = c.engine;
        j["verdict"] = stress::to_string(c.verdict);
        j["failure"] = stress::to_string(c.failure);
        j["reason"] = c.reason;
        j["time_s"] = c.time_s;
        cases.push_back(j);
        if (stress::is_unsafe(c)) ++unsafe;
    }
    doc["cases"] = cases;
    doc["unsafe"] = unsafe;
    io::Json steps = io::Json::array();
    for (const auto& s : r.stable_steps) {
        io::Json j;
        j["engine"] = s.engine;
        j["wall"] = s.wall;
        j["default_dt"] = s.default_dt;
        j["reference_dt"] = s.reference_dt;
        j["reference_period"] = io::finite_or_null(s.reference_period);
        j["reference_restitution"] = io::finite_or_null(s.reference_restitution);
        j["largest_stable_dt"] = io::or_null(s.largest_stable_dt);
        j["first_unstable_dt"] = io::or_null(s.first_unstable_dt);
        j["unstable_reason"] = s.unstable_reason;
        j["probes"] = s.probes;
        j["time_s"] = s.time_s;
        steps.push_back(j);
    }
    doc["stable_steps"] = steps;
    io::Json list = io::Json::array();
    for (const auto& c : stress::all_cases())
        list.push_back(io::Json{{"name", c.name}, {"quick", c.quick}, {"what", c.what}});
    doc["case_list"] = list;
    doc["wall_time_s"] = r.wall_time_s;
    return doc;
}

void write_stress_csv(std::ostream& out, const StressReport& r) {
    out << "name,engine,verdict,failure,reason,time_s\n";
    for (const auto& c : r.cases)
        out << fmt::format("{},{},{},{},{},{:.3f}\n", io::csv_field(c.name), c.engine, stress::to_string(c.verdict),
                           stress::to_string(c.failure), io::csv_field(c.reason), c.time_s);
}

void write_stress_table(std::ostream& out, const StressReport& r) {
    std::vector<std::vector<std::string>> rows;
    std::vector<std::string> head = {"case"};
    head.insert(head.end(), r.engines.begin(), r.engines.end());
    rows.push_back(head);
    for (const std::string& name : case_names(r)) {
        std::vector<std::string> row = {name};
        for (const std::string& e : r.engines) {
            const auto* c = find(r, name, e);
            row.push_back(c ? cell(*c) : "-");
        }
        rows.push_back(row);
    }
    std::vector<size_t> width(head.size(), 0);
    for (const auto& row : rows)
        for (size_t i = 0; i < row.size(); ++i) width[i] = std::max(width[i], row[i].size());
    for (const auto& row : rows) {
        std::string line;
        for (size_t i = 0; i < row.size(); ++i) line += fmt::format("{:<{}}  ", row[i], width[i]);
        while (!line.empty() && line.back() == ' ') line.pop_back();
        out << line << '\n';
    }
}

void write_stress_md(std::ostream& out, const StressReport& r) {
    out << fmt::format("# vssw stress{}\n\nTime limit {:.0f} s per case and backend; {:.1f} s in all.\n\n",
                       r.quick ? " --quick" : "", r.time_limit_s, r.wall_time_s);
    out << "| case |";
    for (const auto& e : r.engines) out << ' ' << e << " |";
    out << "\n|---|";
    for (size_t i = 0; i < r.engines.size(); ++i) out << "---|";
    out << '\n';
    for (const std::string& name : case_names(r)) {
        out << "| " << name << " |";
        for (const auto& e : r.engines) {
            const auto* c = find(r, name, e);
            out << ' ' << (c ? cell(*c) : "-") << " |";
        }
        out << '\n';
    }
    out << "\n## Reasons\n\n";
    for (const auto& c : r.cases)
        out << fmt::format("- {} / {}: {} ({:.2f} s){}\n", c.name, c.engine, cell(c), c.time_s,
                           c.reason.empty() ? "" : " - " + c.reason);
    if (!r.stable_steps.empty()) {
        out << "\n## Largest stable step (Fig. 6 walls, free vibration from 0.5 alpha1)\n\n"
               "| engine | wall | default | largest stable | first unstable | why unstable |\n|---|---|---|---|---|---|\n";
        for (const auto& s : r.stable_steps)
            out << fmt::format("| {} | {} | {} | {} | {} | {} |\n", s.engine, s.wall, step_text(s.default_dt),
                               step_text(s.largest_stable_dt), step_text(s.first_unstable_dt), s.unstable_reason);
    }
}

}  // namespace vssw::cli
