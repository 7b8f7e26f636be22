#pragma once
// How large a name from a study or suite file's templates (wall_name, wall_label, record_name, record_label) may get.
// fmt honours a width or precision up to 2^31 and allocates it: "{height:>100000000}" made a 240-byte study write
// 763 MB, and a larger one ended in std::bad_alloc. Both bounds are checked when the file is read.
#include <cstddef>
#include <optional>
#include <string>

namespace vssw::study {

// [characters] the widest padding or the most digits a field of a name may ask for: a name is a table cell and a
// legend entry, for which 100 is already more than a line.
inline constexpr long kMaxTemplateWidth = 100;
// [bytes] the longest name a template may render to: a long sentence; 10,000 cases of it are 2 MB of results.csv.
inline constexpr std::size_t kMaxNameBytes = 200;

// Why the template asks for more than kMaxTemplateWidth in one of its fields ("{key:format}"): the field and the
// number, or nothing when every field is within the bound.
std::optional<std::string> template_too_wide(const std::string& tmpl);

}  // namespace vssw::study
