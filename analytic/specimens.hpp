#pragma once
// Table 1 of the paper (the ABK 1981 specimens) as data: data/table1.csv, read by the validation suite, the tests and
// the benchmarks, so that no specimen is typed twice (data/SOURCES.md says where the numbers come from).
#include <string>
#include <vector>

#include "analytic/wall.hpp"

namespace vssw {

struct Specimen {
    int number;             // as in Table 1 (4 and 12 have no data)
    double height;          // full height 2h [m]
    double thickness;       // full thickness 2b [m]
    double hinge_ratio;     // h1/h, as printed
    std::string note;       // the table's footnote, if any
};

// The shipped table: shipped_data_dir() + "/table1.csv" (analytic/data_dir.hpp).
std::string default_table1_path();

// Reads a Table 1 file: the header `number,height_m,thickness_m,hinge_ratio,note`, then one specimen a line, five
// comma-separated fields (the note may be empty and holds no comma); blank lines are skipped, CRLF is accepted. The
// number is a whole number >= 1 given once, height and thickness positive finite numbers, the hinge ratio in (0, 1).
// Throws InputError naming the file and the line (and the value) of anything else, or a file with no specimen.
std::vector<Specimen> read_table1(const std::string& path);

// The specimen with that number; InputError naming it and the numbers there are otherwise.
const Specimen& table1_specimen(const std::vector<Specimen>& table, int number);

// The specimen's wall at overburden ratio xi, default density and gravity.
VsswGeometry make_vssw(const Specimen& specimen, double xi = 0.0);

}  // namespace vssw
