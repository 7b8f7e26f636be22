#pragma once
// report.md: the document as GitHub-flavoured Markdown (tables, plots as image links to plots/*.svg).
#include <iosfwd>

#include "apps/report_suite_document.hpp"

namespace vssw::cli {

void write_markdown(std::ostream& out, const Document& doc);

}  // namespace vssw::cli
