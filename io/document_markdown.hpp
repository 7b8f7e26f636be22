#pragma once
// A document (io/document.hpp) as GitHub-flavoured Markdown: tables, plots as image links to plots/*.svg.
#include <iosfwd>

#include "io/document.hpp"

namespace vssw::io {

void write_markdown(std::ostream& out, const Document& doc);

}  // namespace vssw::io
