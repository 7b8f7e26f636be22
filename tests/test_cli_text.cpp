// Text from inputs as the program handles it: a path or name that is not UTF-8 refused before anything runs, name
// templates bounded when the study file is read, and every message with an input's control characters escaped.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "io/text.hpp"
#include "tests/cli_runner.hpp"
#include "tests/study_fixtures.hpp"

namespace {

using vssw::testing::run_cli;
using vssw::testing::TempDir;
using vssw::testing::write_file;

const std::vector<std::string> kWallArgs = {"--height", "4", "--thickness", "0.4", "--hinge", "0.7"};

std::vector<std::string> with_wall(std::vector<std::string> args) {
    args.insert(args.end(), kWallArgs.begin(), kWallArgs.end());
    return args;
}

const char* const kStudy = "name = \"u\"\nmetrics = [\"threshold_closed_form_g\"]\nengines = [\"analytic\"]\n"
                           "[wall]\nheight = 4.0\nthickness = 0.4\nhinge = [0.6, 0.7]\n"
                           "[excitation]\nkind = \"closed-form\"\ntheta0 = 0.5\n";

// A byte a terminal acts on: C0 (a line's own final '\n' aside), DEL, or C1 (UTF-8 C2 80 to C2 9F).
std::string raw_control_in(const std::string& message) {
    for (std::size_t i = 0; i < message.size(); ++i) {
        const auto c = static_cast<unsigned char>(message[i]);
        const bool last_newline = c == '\n' && i + 1 == message.size();
        if ((c < 0x20 && !last_newline) || c == 0x7f) return "byte " + std::to_string(c) + " at " + std::to_string(i);
        if (c == 0xC2 && i + 1 < message.size() && static_cast<unsigned char>(message[i + 1]) < 0xA0)
            return "a C1 character at " + std::to_string(i);
    }
    return "";
}

TEST(Text, PrintableEscapesControlsAndBytesThatAreNotUtf8) {
    EXPECT_EQ(vssw::io::printable("a\x1b[2J\n\t\x7f" "b"), "a\\x1b[2J\\n\\t\\x7fb");
    EXPECT_EQ(vssw::io::printable("s\xff.toml"), "s\\xff.toml");
    EXPECT_EQ(vssw::io::printable("\xC2\x9B" "31m"), "\\u009b31m");  // C1 CSI
    // Direction marks (U+202E right-to-left override, U+2066 left-to-right isolate, U+200F right-to-left mark) would
    // reorder the line on a terminal: shown as their code points. U+2010 (a hyphen, beside them) stays itself.
    EXPECT_EQ(vssw::io::printable("run\xE2\x80\xAE" "lmth.exe \xE2\x81\xA6x\xE2\x80\x8F \xE2\x80\x90"),
              "run\\u202elmth.exe \\u2066x\\u200f \xE2\x80\x90");
    EXPECT_EQ(vssw::io::printable("M\xC3\xBCller \xE5\x9C\xB0"), "M\xC3\xBCller \xE5\x9C\xB0");  // letters stay
    EXPECT_EQ(vssw::io::printable("\xC0\xAF \xED\xA0\x80 \xF4\x90\x80\x80 \xE5\x9C"),  // overlong, surrogate, > U+10FFFF, cut
              "\\xc0\\xaf \\xed\\xa0\\x80 \\xf4\\x90\\x80\\x80 \\xe5\\x9c");
    EXPECT_FALSE(vssw::io::not_utf8("M\xC3\xBCller \xF0\x9F\x8C\x8D"));
    EXPECT_EQ(vssw::io::not_utf8("ab\xff").value_or(""), "'ab\\xff' is not UTF-8 (the byte \\xff at offset 2)");
}

// A file stem is at most kMaxFileStem bytes; a longer name is cut and tagged with a hash of the whole, so that two
// names alike up to the cut still get two files, and a name within the limit is as it was.
TEST(Text, ALongNamesFileStemIsCutAndStaysUnique) {
    const std::string a = std::string(300, 'a') + "/x", b = std::string(300, 'a') + "/y";
    EXPECT_EQ(vssw::io::file_stem(a).size(), vssw::io::kMaxFileStem);
    EXPECT_NE(vssw::io::file_stem(a), vssw::io::file_stem(b));
    EXPECT_EQ(vssw::io::file_stem(a), vssw::io::file_stem(a));  // the same name, the same file
    const std::string at_limit(vssw::io::kMaxFileStem, 'c');
    EXPECT_EQ(vssw::io::file_stem(at_limit), at_limit);
    EXPECT_EQ(vssw::io::file_stem(at_limit + "d").size(), vssw::io::kMaxFileStem);
}

// Every path and name on the command line: a byte that is not UTF-8 is exit 2 naming it, before any folder or run
// (it used to fail only when the JSON was written, after the run, leaving a journal no --resume could finish).
TEST(Text, AWordThatIsNotUtf8IsRefusedBeforeAnything) {
    const TempDir dir;
    const std::string bad = "\xff";
    const std::string study = write_file(dir / ("s" + bad + ".toml"), kStudy).string();
    const std::string good = write_file(dir / "s.toml", kStudy).string();
    const std::string out = (dir / "out").string();
    struct Case {
        std::vector<std::string> args;
        std::string names;
    };
    const std::vector<Case> cases = {
        {{"study", study, "--out", out, "--no-plots"}, "the argument '"},
        {{"study", good, "--out", out + bad, "--json", "--no-plots"}, "the value of --out, '"},
        {{"study", good, "--out=" + out + bad, "--json"}, "the value of --out, '"},
        {{"motions", "generate", "--count", "1", "--seed", "1", "--out", out + bad, "--json"}, "the value of --out"},
        {{"motions", "describe", "--json", (dir / ("r" + bad + ".at2")).string()}, "the argument '"},
        {with_wall({"history", "--record", (dir / ("r" + bad + ".at2")).string(), "--pga", "0.3", "--json"}),
         "the value of --record"},
    };
    for (const Case& c : cases) {
        const auto r = run_cli(c.args);
        EXPECT_EQ(r.code, 2) << r.err;
        EXPECT_NE(r.err.find(c.names), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("\\xff"), std::string::npos) << r.err;
        EXPECT_EQ(raw_control_in(r.err) + (r.err.find(bad) == std::string::npos ? "" : "a raw 0xff"), "") << r.err;
        EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
        for (const auto& entry : std::filesystem::directory_iterator(dir.path))
            EXPECT_NE(entry.path().filename().string().substr(0, 3), "out") << entry.path();
    }
}

// A width or precision above the bound in a name template is refused when the file is read, naming the key and the
// value (a 240-byte study wrote 763 MB); so is a name that renders longer than the bound.
TEST(Text, NameTemplatesAreBounded) {
    const TempDir dir;
    const std::string out = (dir / "out").string();
    const auto study_with = [&](const std::string& key, const std::string& tmpl) {
        return write_file(dir / "t.toml", "name = \"t\"\nmetrics = [\"threshold_closed_form_g\"]\nengines = [\"analytic\"]\n"
                                          "[[part]]\n" + key + " = \"" + tmpl + "\"\n"
                                          "[part.wall]\nheight = [4.0, 4.5]\nthickness = 0.4\nhinge = 0.7\n"
                                          "[part.excitation]\nkind = \"closed-form\"\ntheta0 = 0.5\n")
            .string();
    };
    struct Case {
        std::string key, tmpl, expected;
    };
    const std::vector<Case> refused = {
        {"wall_name", "{height:>100000000}", "wall_name: \"{height:>100000000}\": the field '{height:>100000000}' asks "
                                             "for a width or precision of 100000000, more than 100"},
        {"wall_label", "h{height:.1000000000f}", "wall_label"},
        {"record_name", "{height:*<101}", "of 101, more than 100"},
        {"wall_name", "{height:0>00000000000000000000000000000000000000000101}", "more than 100"},
        {"wall_name", "w" + std::string(200, 'x') + "{height}", "bytes, more than 200"},
        {"wall_name", "{height:>99}{height:>99}{height:>9}", "bytes, more than 200"},
    };
    for (const Case& c : refused) {
        const auto r = run_cli({"study", study_with(c.key, c.tmpl), "--out", out, "--no-plots"});
        EXPECT_EQ(r.code, 2) << c.tmpl << ": " << r.err;
        EXPECT_NE(r.err.find(c.expected), std::string::npos) << r.err;
        EXPECT_FALSE(std::filesystem::exists(out)) << c.tmpl;
    }
    // Within the bounds: a padded, zero-filled or precise name (fill digits are no width).
    for (const char* tmpl : {"{height:0>100}", "w{height:9>8.3f}", "{height:.100f}"}) {
        const auto r = run_cli({"study", study_with("wall_name", tmpl), "--out", out, "--no-plots"});
        EXPECT_EQ(r.code, 0) << tmpl << ": " << r.err;
    }
}

// An escape sequence in an engine name, a study key, a record file name or a bounds file's case id reaches the
// message escaped: it could otherwise set the terminal's title or clear its screen.
TEST(Text, MessagesShowControlCharactersEscaped) {
    const TempDir dir;
    const std::string esc = "\x1b]0;PWNED\x07\x1b[2J\xC2\x9B" "31m";
    const std::string study = write_file(dir / "esc.toml", "name=\"x\"\nmetrics=[\"period\"]\n[wall]\nheight=4.0\n"
                                                           "thickness=0.4\nhinge=0.7\n\"bad\\u001b[2J\"=1\n"
                                                           "[excitation]\nkind=\"free\"\ntheta0=0.5\n")
                                  .string();
    const std::string bounds = write_file(dir / "b.toml", "suite = \"default\"\n[[analytic]]\ncase = \"fig6\\u001b[2J\"\n"
                                                          "metric = \"threshold_g\"\nreference = 0.2857\nmax_drift = 0.0002\n")
                                   .string();
    const std::vector<std::vector<std::string>> commands = {
        with_wall({"compare", "--engine", "ode" + esc}),
        {"study", study, "--out", (dir / "e").string()},
        with_wall({"history", "--record", (dir / ("r" + esc + ".at2")).string(), "--pga", "0.3"}),
        {"check", "--bounds", bounds},
    };
    for (const auto& args : commands) {
        const auto r = run_cli(args);
        EXPECT_EQ(r.code, 2) << r.err;
        EXPECT_EQ(raw_control_in(r.err), "") << r.err;
        EXPECT_NE(r.err.find("\\x1b"), std::string::npos) << r.err;
        EXPECT_EQ(r.err.rfind("vssw: error: ", 0), 0u) << r.err;
    }
}

}  // namespace
