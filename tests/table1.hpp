#pragma once
// Table 1 of the paper for the tests: the shipped data/table1.csv, read once (analytic/specimens.hpp), so that a test
// names a specimen by its number instead of typing its dimensions again.
#include <string>
#include <vector>

#include "analytic/specimens.hpp"

namespace vssw::testing {

inline const std::vector<Specimen>& table1() {
    static const std::vector<Specimen> table = read_table1(default_table1_path());
    return table;
}

inline const Specimen& table1(int number) { return table1_specimen(table1(), number); }

}  // namespace vssw::testing
