#pragma once
// The validation suite (validation::Suite: what `vssw report` and `vssw check` run) from a study file whose parts name
// their walls and records (study/spec.hpp, "[[part]]"). The shipped suites are such files, studies/validation-
// default.toml and validation-full.toml: Table 1 is data, the walls and cases are data, and a user can copy a suite and
// change it. Case ids follow validation/suite.hpp's conventions from the names: threshold "<wall>", free
// "<wall>/r<theta0>", record "<wall>/<record>", and a free part whose engines' dt varies is a step study,
// "<wall>/r<theta0>/dt<dt>/<engine>" (one case per engine and step).
#include <string>

#include "validation/suite.hpp"
#include "study/grid.hpp"

namespace vssw::validation {

// The suite of a study's grid. InputError naming the file when a part of it cannot be a suite's: a part without a
// wall_name (or, under a record, a record_name), a kind the suite does not run (pulse, scale-to-collapse,
// closed-form), a wall name given to two different walls, a case id given twice.
Suite suite_from_study(const study::Grid& grid, const std::string& suite_name);

// The shipped suite file of a name ("default", "full": studies/validation-<name>.toml), or the path given.
std::string suite_file(const std::string& name_or_path);

// The suite of a name or a file; its records are read from `data_dir` by file name when it is not empty (the
// report's --data), else from where the file says. InputError on a name that is neither a shipped suite nor a file.
Suite read_suite(const std::string& name_or_path, const std::string& data_dir);

}  // namespace vssw::validation
