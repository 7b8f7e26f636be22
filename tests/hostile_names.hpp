#pragma once
// Names written to run commands if any of them reached gnuplot or a shell as code rather than as text, for the tests
// that put them into a study or a suite and draw its plots: what gnuplot must show as it is, and how to find a
// command that ran anyway (the marker files it leaves).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <system_error>
#include <vector>

namespace vssw::testing {

// Every command in the hostile names creates a file whose name starts with this.
inline const std::string kMarker = "VSSW_MARK";

// A record file name (no '/'): backquotes and $(...) (command substitution: gnuplot runs backquotes inside double
// quotes, a shell both), quotes of both kinds, a line break followed by "!touch" (a new gnuplot command that runs a
// shell), an @macro (gnuplot substitutes one outside quotes), a tab, a backslash, and non-ASCII text.
inline const std::string kHostileFileName = "r`touch VSSW_MARK_1`$(touch VSSW_MARK_2) 'q' \"dq\"\n!touch VSSW_MARK_3\n"
                                            "@m\t\\ M\xC3\xBCller \xCE\xB5 \xE5\x9C\xB0\xE9\x9C\x87.AT2";
// A name that may hold '/': the same, with markup that a page would run if it were not escaped.
inline const std::string kHostileName = "w`touch VSSW_MARK_4`$(touch VSSW_MARK_5) 'q' \"dq\"\n!touch VSSW_MARK_6\n"
                                        "@m <script>alert(1)</script> M\xC3\xBCller \xCE\xB5 \xE5\x9C\xB0\xE9\x9C\x87";

// A name made of Markdown and HTML that a renderer would make live if it were not escaped for every renderer: a tag
// with a handler, a javascript: link, an autolink, emphasis, a code span and entities (tests/markdown_scan.py).
inline const std::string kMarkupName = "w1\"><img src=x onerror=alert(2)> [click](javascript:alert(10)) "
                                       "<javascript:alert(3)> *em* _u_ `code` &lt;b&gt; \\<i>";

// The text (UTF-8) as a TOML basic string in ASCII, as study files are: non-ASCII characters as \\uXXXX escapes.
inline std::string toml_string(const std::string& text) {
    std::string s = "\"";
    for (std::size_t i = 0; i < text.size(); ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c == '"' || c == '\\') {
            s += std::string("\\") + text[i];
        } else if (c == '\n') {
            s += "\\n";
        } else if (c == '\t') {
            s += "\\t";
        } else if (c < 0x80) {
            s += text[i];
        } else {
            // A lead byte 110xxxxx, 1110xxxx or 11110xxx and its continuation bytes 10xxxxxx.
            const int extra = c >= 0xF0 ? 3 : c >= 0xE0 ? 2 : 1;
            unsigned long code = c & (0x3Fu >> extra);
            for (int k = 0; k < extra; ++k) code = (code << 6) | (static_cast<unsigned char>(text[++i]) & 0x3Fu);
            char buf[16];
            std::snprintf(buf, sizeof buf, code > 0xFFFF ? "\\U%08lX" : "\\u%04lX", code);
            s += buf;
        }
    }
    return s + '"';
}

// The text (UTF-8) as a JSON string: quotes, backslashes and control characters escaped.
inline std::string json_string(const std::string& text) {
    std::string s = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') s += std::string("\\") + c;
        else if (static_cast<unsigned char>(c) < 0x20) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(c));
            s += buf;
        } else s += c;
    }
    return s + '"';
}

// The text as gnuplot's SVG holds it: control characters as spaces (io/gnuplot.hpp), then '&' and '<' as XML
// escapes them (gnuplot leaves '>' and the quotes as they are).
inline std::string svg_text(const std::string& text) {
    std::string s;
    for (char c : text) {
        if (static_cast<unsigned char>(c) < 0x20 || c == '\x7f') s += ' ';
        else if (c == '&') s += "&amp;";
        else if (c == '<') s += "&lt;";
        else s += c;
    }
    return s;
}

// The hover texts of a plot's SVG as vssw writes it (a native tooltip per point: `<g><title>TEXT</title>`,
// io/gnuplot.hpp), the document's own <title> left out; as the SVG holds them, XML-escaped.
inline std::vector<std::string> hover_titles(const std::string& svg) {
    std::vector<std::string> titles;
    const std::regex title("<g><title>([^<]*)</title>");
    for (auto it = std::sregex_iterator(svg.begin(), svg.end(), title); it != std::sregex_iterator(); ++it)
        titles.push_back((*it)[1]);
    return titles;
}

// What the Markdown page at `page` makes live when MkDocs renders it, and each of `texts` that it does not show as
// text (tests/markdown_scan.py, Python-Markdown), one per line; "" when it shows them all as text and runs nothing.
inline std::string markdown_problems(const std::filesystem::path& page, const std::vector<std::string>& texts) {
    const std::filesystem::path list = page.string() + ".texts.json";
    {
        std::ofstream out(list);
        out << '[';
        for (std::size_t i = 0; i < texts.size(); ++i) out << (i ? ", " : "") << json_string(texts[i]);
        out << ']';
    }
    // Only paths reach the shell (the names go through the file); the script is in tests/ beside data/.
    const std::filesystem::path script = std::filesystem::path(VSSW_DATA_DIR).parent_path() / "tests" / "markdown_scan.py";
    const std::string command = "/usr/bin/python3 '" + script.string() + "' '" + page.string() + "' '" + list.string() + "' 2>&1";
    std::string report;
    if (FILE* p = popen(command.c_str(), "r")) {
        char buf[4096];
        while (std::fgets(buf, sizeof buf, p) != nullptr) report += buf;
        if (pclose(p) != 0 && report.empty()) report = "markdown_scan.py failed";
    }
    return report;
}

// The marker files under dir and in the current folder: each is a command that ran.
inline std::vector<std::string> markers_made(const std::filesystem::path& dir) {
    std::vector<std::string> found;
    std::error_code ec;
    for (auto it = std::filesystem::recursive_directory_iterator(dir, ec);
         !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec))
        if (it->path().filename().string().rfind(kMarker, 0) == 0) found.push_back(it->path().string());
    for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::current_path(), ec))
        if (entry.path().filename().string().rfind(kMarker, 0) == 0) found.push_back(entry.path().string());
    return found;
}

}  // namespace vssw::testing
