#include "cli/table.hpp"

#include <algorithm>
#include <ostream>

#include <fmt/format.h>

namespace vssw::cli {

std::string num_or(const std::optional<double>& value, const std::string& none) { return value ? io::num(*value) : none; }

Table& Table::add(std::string name, std::string value, std::string unit, std::string note) {
    rows_.push_back({std::move(name), std::move(value), std::move(unit), std::move(note), false});
    return *this;
}

Table& Table::text(std::string name, std::string text) {
    rows_.push_back({std::move(name), std::move(text), "", "", true});
    return *this;
}

void Table::print(std::ostream& out) const {
    std::size_t name_w = 0, value_w = 0, unit_w = 0;
    for (const Row& r : rows_) {
        name_w = std::max(name_w, r.name.size());
        if (r.is_text) continue;
        value_w = std::max(value_w, r.value.size());
        unit_w = std::max(unit_w, r.unit.size());
    }
    out << title_ << '\n';
    for (const Row& r : rows_) {
        std::string line = r.is_text ? fmt::format("  {:<{}}  {}", r.name, name_w, r.value)
                                     : fmt::format("  {:<{}}  {:>{}}  {:<{}}  {}", r.name, name_w, r.value, value_w,
                                                   r.unit, unit_w, r.note);
        line.erase(line.find_last_not_of(' ') + 1);  // no trailing blanks when unit or note is empty
        out << line << '\n';
    }
}

}  // namespace vssw::cli
