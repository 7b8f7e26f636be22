#pragma once
// Reading a bounds file for `vssw check`: TOML (.toml) or JSON (.json), one schema (docs/guide/check.md):
//
//   suite = "default"                    # optional; where the case ids come from
//   [[analytic]]                         # the analytic core against a stored value
//   case = "fig6-vssw"
//   metric = "threshold_g"
//   reference = 0.0974
//   max_drift = 1e-6                     # relative
//   [[engine]]                           # an engine against the analytic model
//   engine = "ode"
//   cases = ["fig6-vssw", "fig6-pw"]
//   metric = "period"
//   max_error = 0.005                    # |rel_error| <= max_error, or
//   # error = [-0.14, -0.12]             # min <= rel_error <= max (a known, explained offset)
//   [[stress]]                           # verdicts of `vssw stress --quick` (docs/guide/stress.md)
//   cases = ["hinge-0.05", "xi-50"]
//   engines = ["ode"]                    # optional: every backend compiled in
//   allowed = ["ok"]                     # of ok, refused, failed
//
// Every problem (missing file, syntax, unknown key, wrong type, NaN, negative bound, empty file) is an InputError
// naming the file and the entry.
#include <string>

#include "validation/bounds.hpp"

namespace vssw::validation {

Bounds read_bounds_file(const std::string& path);
// The same from text (format "toml" or "json"); `name` is used in messages.
Bounds parse_bounds(const std::string& text, const std::string& format, const std::string& name);

}  // namespace vssw::validation
