#pragma once
// Human-readable output: a titled list of quantities printed as aligned columns (name, value, unit, note).
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "io/text.hpp"

namespace vssw::cli {

// A number for people: 6 significant digits (JSON and CSV carry full precision); yes or no.
// A number, or `none` when the quantity does not exist.
std::string num_or(const std::optional<double>& value, const std::string& none);

class Table {
public:
    explicit Table(std::string title) : title_(std::move(title)) {}
    // A quantity: its value is right-aligned with the other values.
    Table& add(std::string name, std::string value, std::string unit = "", std::string note = "");
    // A description (a file name, a model): printed after the name, left-aligned, not widening the value column.
    Table& text(std::string name, std::string text);
    void print(std::ostream& out) const;

private:
    struct Row {
        std::string name, value, unit, note;
        bool is_text;
    };
    std::string title_;
    std::vector<Row> rows_;
};

}  // namespace vssw::cli
