#pragma once
// A document (io/document.hpp) as one self-contained page: inline CSS, each plot's SVG read from plots_dir and
// embedded in the page, its ids prefixed so that several plots can share one page.
#include <filesystem>
#include <iosfwd>
#include <string>

#include "io/document.hpp"

namespace vssw::io {

void write_html(std::ostream& out, const Document& doc, const std::filesystem::path& plots_dir);
// Text for HTML: & < > " escaped.
std::string html_escape(const std::string& text);

}  // namespace vssw::io
