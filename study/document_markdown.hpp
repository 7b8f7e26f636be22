#pragma once
// A document (study/document.hpp) as GitHub-flavoured Markdown: tables, plots as image links to plots/*.svg.
#include <iosfwd>

#include "study/document.hpp"

namespace vssw::study {

void write_markdown(std::ostream& out, const Document& doc);

}  // namespace vssw::study
