#include "io/gnuplot.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string_view>
#include <system_error>
#include <utility>

#include <fmt/format.h>

#include "analytic/child_fork.hpp"
#include "analytic/error.hpp"
#include "io/atomic_file.hpp"
#include "io/document_html.hpp"  // html_escape

namespace vssw::io {
namespace fs = std::filesystem;
namespace {

// Exit status of a program that could not be started (the shell's convention).
constexpr int kNotFound = 127;

// Runs `program script` in dir with stdin from /dev/null and stdout/stderr into log. The exit status; kNotFound when
// the program could not be started; -1 when fork failed.
int run_program(const std::string& program, const std::string& script, const fs::path& dir, const fs::path& log) {
    const pid_t pid = fork_child();  // flushed, and gnuplot dies with this process (child_fork.hpp)
    if (pid < 0) return -1;
    if (pid == 0) {
        // The log first: a relative log path names a file from here, not from dir (opened after the chdir, the log
        // of `--out relative/folder` was never made and gnuplot's warnings reached the user's terminal).
        const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd >= 0) {
            dup2(fd, 1);
            dup2(fd, 2);
        }
        if (chdir(dir.c_str()) != 0) _exit(kNotFound - 1);
        const int in = open("/dev/null", O_RDONLY);
        if (in >= 0) dup2(in, 0);
        execlp(program.c_str(), program.c_str(), script.c_str(), static_cast<char*>(nullptr));
        _exit(kNotFound);
    }
    const int status = wait_child(pid);
    if (status < 0) return -1;
    if (WIFEXITED(status)) return WEXITSTATUS(status);
    return 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

// Through a temporary file renamed on success (atomic_file.hpp); false when it cannot be written.
bool write_text(const fs::path& path, const std::string& text) {
    try {
        write_file(path, [&](std::ostream& out) { out << text; });
        return true;
    } catch (const InputError&) {
        return false;
    }
}

// Newline, CR, tab, the other C0 codes and DEL: what gnuplot text and comments turn into spaces.
bool is_control(char c) { return static_cast<unsigned char>(c) < 0x20 || c == '\x7f'; }

// Every plot's font (gnuplot.hpp, gp_font): a size the report's and a study's pages show at about 11 px, their text's.
constexpr const char* kPlotFont = "sans,11";

// gnuplot 5.4's SVG terminal writes a hypertext point as HEAD TEXT TAIL then the marker and "</g>".
constexpr std::string_view kHoverHead = "<g onmousemove=\"gnuplot_svg.showHypertext(evt,'";
constexpr std::string_view kHoverTail = "')\" onmouseout=\"gnuplot_svg.hideHypertext()\"><title> </title>";

// gnuplot's escaping of a hypertext undone (it writes & and < as entities, the rest as it is).
std::string xml_unescape(std::string_view s) {
    std::string out;
    for (std::size_t i = 0; i < s.size(); ++i) {
        bool matched = false;
        for (const auto& [entity, c] : {std::pair<std::string_view, char>{"&lt;", '<'}, {"&gt;", '>'}, {"&amp;", '&'},
                                        {"&quot;", '"'}, {"&apos;", '\''}})
            if (s.substr(i, entity.size()) == entity) {
                out += c;
                i += entity.size() - 1;
                matched = true;
                break;
            }
        if (!matched) out += s[i];
    }
    return out;
}

// The SVG gnuplot wrote with native tooltips (svg_native_tooltips); false when it cannot be read or written again.
bool add_tooltips(const fs::path& svg, const std::string& title) {
    std::ifstream in(svg, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in) return false;
    return write_text(svg, svg_native_tooltips(text.str(), title));
}

}  // namespace

std::string gp_string(const std::string& text) {
    std::string s = "'";
    for (char c : text) {
        if (is_control(c)) s += ' ';
        else if (c == '\'') s += "''";
        else s += c;
    }
    return s + '\'';
}

std::string gp_comment(const std::string& text) {
    std::string s = text;
    for (char& c : s)
        if (is_control(c)) c = ' ';
    if (!s.empty() && s.back() == '\\') s += ' ';
    return s;
}

std::string gp_data_string(const std::string& text) {
    std::string s = "\"";
    for (char c : text) {
        if (is_control(c)) s += ' ';
        else if (c == '"') s += '\'';
        else if (c == '\\') s += '/';
        else s += c;
    }
    return s + '"';
}

bool gp_safe_name(const std::string& name) {
    if (name.empty() || name[0] == '.' || name[0] == '-') return false;
    return std::all_of(name.begin(), name.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_';
    });
}

std::string gp_number(double v, bool positive_only) {
    if (!std::isfinite(v) || (positive_only && v <= 0.0)) return "?";
    return fmt::format("{:.10g}", v);
}

std::string gp_font() { return "font " + gp_string(kPlotFont); }

std::string gp_preamble(const std::string& drawn_by, const std::string& name, int width, int height) {
    return fmt::format(
        "# Drawn by `{2}`; re-draw with: gnuplot {3}\n"
        "set encoding utf8\n"
        "set terminal svg size {0},{1} noenhanced {5} background rgb 'white'\n"
        "set output {4}\n"
        "set datafile missing '?'\n"
        "set grid lc rgb '#dddddd'\n"
        "set key below center horizontal Left reverse box lc rgb '#cccccc' samplen 2 spacing 1.1\n",
        width, height, gp_comment(drawn_by), gp_comment(name + ".gp"), gp_string(name + ".svg"), gp_font());
}

std::string gp_xlabel(const std::string& text, bool key_below) {
    return "set xlabel " + gp_string(text) + (key_below ? ".\"\\n\"\n" : "\n");
}

std::string gp_hover_layer(const std::string& source, const std::string& style) {
    return source + " with labels hypertext point " + style + " notitle";
}

std::string gp_hover_text(const std::string& series, const std::string& where, double value, const std::string& unit) {
    const std::string shown = std::isfinite(value) ? fmt::format("{:.4g}{}", value, unit.empty() ? "" : " " + unit)
                                                   : std::string("no value");
    return gp_data_string(fmt::format("{}, {}: {}", series, where, shown));
}

std::string svg_native_tooltips(const std::string& svg, const std::string& title) {
    std::string out;
    out.reserve(svg.size());
    std::size_t at = 0;
    for (;;) {
        const std::size_t head = svg.find(kHoverHead, at);
        const std::size_t tail = head == std::string::npos ? head : svg.find(kHoverTail, head + kHoverHead.size());
        if (tail == std::string::npos) break;
        const std::string_view text(svg.data() + head + kHoverHead.size(), tail - head - kHoverHead.size());
        out.append(svg, at, head - at);
        out += "<g><title>" + html_escape(xml_unescape(text)) + "</title>";
        at = tail + kHoverTail.size();
    }
    out.append(svg, at, std::string::npos);
    // gnuplot's group titles: `<g id="gnuplot_plot_3" ><title>gnuplot_plot_3</title>`, a tooltip naming nothing.
    for (std::size_t g = out.find("<title>gnuplot_plot_"); g != std::string::npos;
         g = out.find("<title>gnuplot_plot_", g)) {
        const std::size_t end = out.find("</title>", g);
        if (end == std::string::npos) break;
        out.erase(g, end + std::string_view("</title>").size() - g);
    }
    const std::string gnuplot_title = "<title>Gnuplot</title>";
    if (const std::size_t t = out.find(gnuplot_title); t != std::string::npos)
        out.replace(t, gnuplot_title.size(), "<title>" + html_escape(title) + "</title>");
    return out;
}

PlotResult draw_plots(const std::vector<PlotScript>& scripts, const fs::path& plots_dir, const std::string& program) {
    PlotResult result;
    std::error_code ec;
    fs::create_directories(plots_dir, ec);
    if (ec) {
        result.note = fmt::format("cannot create {}: {}", plots_dir.string(), ec.message());
        return result;
    }
    // A program named with a '/' is a path: make it absolute, gnuplot runs in plots_dir.
    std::string run = program;
    if (run.find('/') != std::string::npos) run = fs::absolute(run, ec).string();

    bool gnuplot_missing = false;
    std::vector<std::string> failed;
    for (const PlotScript& s : scripts) {
        Plot plot = s.plot;
        if (!gp_safe_name(plot.name)) {
            // Not a file stem: it would be written into the script unquoted; file_stem makes one (io/text.hpp).
            failed.push_back(fmt::format("'{}' (not a plain file name)", gp_comment(plot.name)));
            continue;
        }
        const fs::path svg = plots_dir / (plot.name + ".svg"), log = plots_dir / (plot.name + ".log");
        if (!write_text(plots_dir / (plot.name + ".gp"), s.gp) ||
            !write_text(plots_dir / (plot.name + ".dat"), s.dat)) {
            failed.push_back(plot.name + " (cannot write its script or data)");
            continue;
        }
        fs::remove(svg, ec);  // a stale SVG from an earlier run must not pass for this one
        if (!gnuplot_missing) {
            const int status = run_program(run, plot.name + ".gp", plots_dir, log);
            if (status == kNotFound) gnuplot_missing = true;
            const bool drawn = status == 0 && fs::exists(svg, ec) && fs::file_size(svg, ec) > 0;
            // gnuplot's SVG kept as it drew it when it cannot be rewritten (its hover texts then need its script).
            plot.made = drawn;
            if (drawn && !add_tooltips(svg, plot.title))
                failed.push_back(fmt::format("{} (drawn, but {}.svg could not be read back to add its hover texts)",
                                             plot.name, plot.name));
            if (plot.made) {
                fs::remove(log, ec);
            } else {
                fs::remove(svg, ec);  // a failed run may leave a truncated SVG
                if (!gnuplot_missing)
                    failed.push_back(fmt::format("{} (gnuplot exit {}, see {}.log)", plot.name, status, plot.name));
            }
        }
        result.plots.push_back(plot);
    }
    if (gnuplot_missing) {
        for (const PlotScript& s : scripts) fs::remove(plots_dir / (s.plot.name + ".log"), ec);
        result.note = fmt::format("gnuplot ('{}') could not be run: no plots were drawn (their scripts and data are "
                                  "in plots/; install gnuplot, Debian package gnuplot-nox, and run them)",
                                  program);
    } else if (!failed.empty()) {
        result.note = fmt::format("{} plot{} failed: {}", failed.size(), failed.size() == 1 ? "" : "s",
                                  fmt::join(failed, "; "));
    }
    result.all_made = !gnuplot_missing && failed.empty();
    return result;
}

std::vector<DocBlock> plot_blocks(const PlotResult& plots) {
    std::vector<std::string> sections;
    for (const Plot& p : plots.plots)
        if (p.made && std::find(sections.begin(), sections.end(), p.section) == sections.end())
            sections.push_back(p.section);
    std::vector<DocBlock> blocks;
    for (const std::string& section : sections) {
        blocks.push_back(heading(3, section));
        for (const Plot& p : plots.plots)
            if (p.made && p.section == section) blocks.push_back(plot(p.title, p.name));
    }
    return blocks;
}

}  // namespace vssw::io
