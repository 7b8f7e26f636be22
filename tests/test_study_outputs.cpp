// A study's plots and prose (study/outputs.hpp) on hand-written results: a tiny study file gives the grid and the
// manifest (study::manifest_json), and results.csv is written with values chosen so that every effect, ranking and
// agreement is known exactly. What is checked: the ranking of the sensitivities and the numbers in their sentences,
// the tornado data, the engines' closest assumption set, the panels summarised past kMaxPanels, the rocking curves'
// overturned points and the overturning map's data, the plots named when gnuplot is there, a missing gnuplot as a
// warning and no failure, and a merged study written exactly as a single run.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "analytic/error.hpp"
#include "multibody/engine.hpp"
#include "study/study_document.hpp"
#include "study/effects.hpp"
#include "io/gnuplot.hpp"
#include "study/grid.hpp"
#include "study/journal.hpp"
#include "study/merge.hpp"
#include "study/outputs.hpp"
#include "study/plot_lines.hpp"
#include "study/results_files.hpp"
#include "study/runner.hpp"
#include "study/spec.hpp"
#include "study/study_data.hpp"
#include "study/study_prose.hpp"
#include "io/text.hpp"
#include "tests/hostile_names.hpp"
#include "tests/temp_files.hpp"

namespace {

namespace fs = std::filesystem;
namespace st = vssw::study;

// The .dat files hold numbers with 10 significant digits (io/gnuplot.cpp, gp_number).
constexpr double kDatDigits = 1e-9;
// Effects computed from hand-written doubles: the division and the median's mean of two middle values cost a few ulps.
constexpr double kEffectRoundOff = 1e-12;

using vssw::testing::contains;
using vssw::testing::TempDir;
std::string read(const fs::path& p) { return vssw::testing::read_file(p); }

bool gnuplot_available() { return std::system("gnuplot --version >/dev/null 2>&1") == 0; }

// The first engine built besides the analytic model ("" when there is none).
std::string an_engine() {
    for (const std::string& e : vssw::multibody::available_engines())
        if (e != "analytic" && e != "simbody-rigid") return e;
    return "";
}

std::string text_of(const st::RunSpec& run, std::size_t assumption) { return st::to_text(run.assumptions[assumption]); }

using ValueOf = std::function<double(const st::CaseSpec&, const st::RunSpec&, const std::string& metric)>;

// A study folder as `vssw study` leaves it (results.csv, manifest.json) for the grid's cases of one shard, every
// value from `value`.
void write_study(const fs::path& dir, const st::Grid& grid, const ValueOf& value, st::Shard shard = {}) {
    fs::create_directories(dir);
    std::vector<st::ResultRow> rows;
    long tasks = 0;
    for (const int id : grid.shard_case_ids(shard.k, shard.n)) {
        const st::CaseSpec c = grid.make_case(id);
        for (std::size_t r = 0; r < grid.runs().size(); ++r) {
            if (!grid.run_applies(grid.runs()[r], c)) continue;
            ++tasks;
            for (std::size_t m = 0; m < grid.spec().metrics.size(); ++m)
                rows.push_back({id, r, m, value(c, grid.runs()[r], grid.spec().metrics[m]), "ok", ""});
        }
    }
    std::ofstream(dir / st::kResultsCsv) << [&] {
        std::ostringstream out;
        st::write_results_csv(out, grid, rows);
        return out.str();
    }();
    st::StudyMeta meta;
    meta.commit = "abc1234";
    meta.date = "2025-01-01T00:00:00Z";
    meta.shard = shard;
    meta.wall_time_s = 1.5;
    meta.tasks_run = tasks;
    for (const st::EngineSpec& e : grid.spec().engines) meta.engines.push_back({e.name, e.name + " (test)"});
    std::ofstream(dir / st::kManifestFile) << st::manifest_json(grid, meta).dump(2) << '\n';
}

st::StudySpec spec_of(const fs::path& dir, const std::string& toml) {
    const fs::path file = dir / "study.toml";
    std::ofstream(file) << toml;
    return st::read_study_file(file.string());
}

// The tiny study: two hinges, both kinematics, both impact laws (the bilateral roller of the set paper: the paper's
// kinematics need it), an engine, a free vibration measuring the period and overturning.
std::string tiny_study(const std::string& engine) {
    return "name = \"tiny\"\n"
           "description = \"hand-written values\"\n"
           "metrics = [\"period\", \"overturned\"]\n"
           "engines = [\"analytic\", \"" + engine + "\"]\n"
           "[wall]\nheight = 4\nthickness = 0.4\nhinge = [0.5, 0.7]\n"
           "[assumptions]\nset = \"paper\"\nkinematics = [\"paper\", \"exact\"]\nimpact = [\"eq19\", \"whole-mechanism\"]\n"
           "[excitation]\nkind = \"free\"\ntheta0 = 0.5\n";
}

// Period: 1.0 s at hinge 0.5, 1.2 s at 0.7; exact kinematics 5 % longer at 0.5 and 10 % at 0.7; the impact law
// changes nothing; the engine 1 % longer than the exact kinematics. Overturned: only the analytic model with Eq. (19)
// at hinge 0.7.
double tiny_value(const st::CaseSpec& c, const st::RunSpec& run, const std::string& metric) {
    const bool high = c.hinge > 0.6;
    const bool engine = run.engine != "analytic";
    if (metric == "overturned") return !engine && high && text_of(run, 1) == "eq19" ? 1.0 : 0.0;
    const double base = high ? 1.2 : 1.0, exact = high ? 1.10 : 1.05;
    if (engine) return base * exact * 1.01;
    return text_of(run, 0) == "exact" ? base * exact : base;
}

// The numbers of a tornado .dat, row by row: y, lo, median, hi, pairs (the label in `labels`).
struct TornadoRow {
    std::string label;
    double y, lo, median, hi, pairs;
};
std::vector<TornadoRow> tornado_rows(const fs::path& dat) {
    std::vector<TornadoRow> rows;
    std::istringstream in(read(dat));
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        const auto q1 = line.find('"'), q2 = line.find('"', q1 + 1);
        TornadoRow r{line.substr(q1 + 1, q2 - q1 - 1), std::stod(line.substr(0, q1)), 0, 0, 0, 0};
        std::istringstream rest(line.substr(q2 + 1));
        rest >> r.lo >> r.median >> r.hi >> r.pairs;
        rows.push_back(r);
    }
    return rows;
}

// The data lines of a .dat (comments and blank lines left out), each split into words up to a quoted text (a point's
// hover text, the last column).
std::vector<std::vector<std::string>> dat_lines(const fs::path& dat) {
    std::vector<std::vector<std::string>> lines;
    std::istringstream in(read(dat));
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream words(line);
        std::vector<std::string> w;
        for (std::string word; words >> word && word[0] != '"';) w.push_back(word);
        lines.push_back(w);
    }
    return lines;
}

// study.md without its "Run" section (when and how long: the only part a merge and a single run may differ in).
std::string without_run_section(const std::string& md) {
    const auto start = md.find("\n## Run\n");
    if (start == std::string::npos) return md;
    const auto end = md.find("\n## ", start + 1);
    return md.substr(0, start) + (end == std::string::npos ? "" : md.substr(end));
}

st::OutputOptions no_plots() {
    st::OutputOptions o;
    o.plots = false;
    return o;
}

class TinyStudy : public ::testing::Test {
protected:
    void SetUp() override {
        engine_ = an_engine();
        if (engine_.empty()) GTEST_SKIP() << "no engine built besides the analytic model";
        grid_.emplace(spec_of(dir_.path, tiny_study(engine_)));
        write_study(dir_.path / "out", *grid_, tiny_value);
    }
    fs::path out() const { return dir_.path / "out"; }

    TempDir dir_{"study_tiny"};
    std::string engine_;
    std::optional<st::Grid> grid_;
};

TEST_F(TinyStudy, SensitivitiesAreRankedLargestFirstWithTheirNumbers) {
    const st::StudyData d = st::read_study_data(out());
    const std::vector<st::Effect> effects = st::parameter_effects(d);
    ASSERT_EQ(effects.size(), 6u);  // 3 parameters x 1 level after the first x 2 metrics
    // overturned flips on 2 of 4 impact pairs (0.5) and 2 of 5 hinge pairs (0.4); the period's median changes are
    // 25.7 % (hinge), 7.5 % (kinematics), 0 (impact); kinematics never flips overturned.
    const std::vector<std::pair<std::string, std::string>> order = {
        {"impact", "overturned"}, {"hinge", "overturned"},    {"hinge", "period"},
        {"kinematics", "period"}, {"kinematics", "overturned"}, {"impact", "period"}};
    for (std::size_t i = 0; i < order.size(); ++i) {
        EXPECT_EQ(effects[i].parameter, order[i].first) << i;
        EXPECT_EQ(d.metrics[effects[i].metric].name, order[i].second) << i;
    }
    const st::Effect& hinge = effects[2];
    EXPECT_EQ(hinge.pairs, 5);  // four analytic runs and the engine
    EXPECT_NEAR(hinge.median, 1.32 / 1.05 - 1.0, kEffectRoundOff);
    EXPECT_NEAR(hinge.lo, 0.2, kEffectRoundOff);
    EXPECT_EQ(st::effect_sentence(d, hinge),
              "hinge from 0.5 to 0.7 changes period by a median of +25.7 % (from +20.0 % to +25.7 % over 5 pairs of "
              "runs that differ in hinge alone).");
    EXPECT_EQ(st::effect_sentence(d, effects[3]),
              "kinematics from paper to exact changes period by a median of +7.5 % (from +5.0 % to +10.0 % over 4 "
              "pairs of runs that differ in kinematics alone).");
    EXPECT_EQ(st::effect_sentence(d, effects[0]),
              "impact from eq19 to whole-mechanism turns overturned from 0 to 1 on 0 and from 1 to 0 on 2 of 4 pairs "
              "of runs that differ in impact alone (net -50.0 % of the pairs).");
    EXPECT_EQ(st::effect_sentence(d, effects[5]),
              "impact from eq19 to whole-mechanism leaves period unchanged (within 1e-09 relative on 4 pairs of runs "
              "that differ in impact alone).");

    st::write_study_outputs(out(), no_plots());
    const std::string md = read(out() / st::kStudyMarkdown);
    EXPECT_TRUE(contains(md, "# vssw study: tiny\n\nhand-written values\n"));
    EXPECT_TRUE(contains(md, "- hinge: 0.5, 0.7\n- kinematics (assumption): paper, exact\n"
                             "- impact (assumption): eq19, whole-mechanism\n"));
    EXPECT_TRUE(contains(md, "- 10 tasks (case x run).\n- 20 rows, 0 failed.\n"));
    // The sentences in the order of the ranking.
    const auto first = md.find("- impact from eq19 to whole-mechanism turns overturned");
    const auto third = md.find("- hinge from 0.5 to 0.7 changes period by a median of +25.7 %");
    const auto fourth = md.find("- kinematics from paper to exact changes period by a median of +7.5 %");
    ASSERT_NE(first, std::string::npos);
    EXPECT_LT(first, third);
    EXPECT_LT(third, fourth);
    EXPECT_NE(fourth, std::string::npos);
}

TEST_F(TinyStudy, TheEngineIsClosestToTheExactKinematicsAndTheWholeMechanismImpact) {
    const st::StudyData d = st::read_study_data(out());
    const std::vector<std::string> found = st::agreement_sentences(d, st::engine_agreement(d));
    ASSERT_EQ(found.size(), 2u) << "period and overturned";
    // Against the exact kinematics the engine is 1 % off under either impact law (the period ignores it), against the
    // paper's 6.05 % at hinge 0.5 and 11.1 % at 0.7.
    EXPECT_TRUE(contains(found[0], "is closest to the analytic model with kinematics=exact impact=eq19 or "
                                   "kinematics=exact impact=whole-mechanism (|engine/analytic - 1|)"))
        << found[0];
    EXPECT_TRUE(contains(found[0], "with kinematics=exact impact=eq19: median 1.0 %, largest 1.0 % over 2 cases"))
        << found[0];
    EXPECT_TRUE(contains(found[0], "with kinematics=paper impact=eq19: median 8.6 %, largest 11.1 % over 2 cases"))
        << found[0];
    // Overturning: the engine never overturns, the analytic model with Eq. (19) does at hinge 0.7.
    EXPECT_TRUE(contains(found[1], "is closest to the analytic model with kinematics=paper impact=whole-mechanism or "
                                   "kinematics=exact impact=whole-mechanism:"))
        << found[1];
    EXPECT_TRUE(contains(found[1], "with kinematics=paper impact=eq19: disagree on 1 of 2 cases")) << found[1];
}

TEST_F(TinyStudy, TornadoDataHoldTheAssumptionsEffects) {
    if (!gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed (Debian package gnuplot-nox)";
    const st::OutputFiles files = st::write_study_outputs(out(), {});
    EXPECT_TRUE(files.warnings.empty()) << files.warnings.front();
    const fs::path plots = out() / st::kPlotsDir;
    // Period: kinematics +5 % to +10 %, median 7.5 %, at the top (largest reach); impact 0 below it.
    const std::vector<TornadoRow> period = tornado_rows(plots / "tornado_period.dat");
    ASSERT_EQ(period.size(), 2u);
    EXPECT_EQ(period[0].label, "kinematics: paper -> exact");
    EXPECT_EQ(period[0].y, 1.0);
    EXPECT_NEAR(period[0].lo, 0.05, kDatDigits);
    EXPECT_NEAR(period[0].median, 0.075, kDatDigits);
    EXPECT_NEAR(period[0].hi, 0.10, kDatDigits);
    EXPECT_EQ(period[0].pairs, 4.0);
    EXPECT_EQ(period[1].label, "impact: eq19 -> whole-mechanism");
    EXPECT_NEAR(period[1].hi, 0.0, kDatDigits);
    // Overturned: the whole-mechanism impact stands up 2 of the 4 pairs (-0.5), none the other way.
    const std::vector<TornadoRow> over = tornado_rows(plots / "tornado_overturned.dat");
    ASSERT_EQ(over.size(), 2u);
    EXPECT_EQ(over[0].label, "impact: eq19 -> whole-mechanism");
    EXPECT_NEAR(over[0].lo, -0.5, kDatDigits);
    EXPECT_NEAR(over[0].median, -0.5, kDatDigits);
    EXPECT_NEAR(over[0].hi, 0.0, kDatDigits);

    // Every plot the study calls for, drawn and in the prose.
    const std::string md = read(out() / st::kStudyMarkdown);
    for (const char* name : {"value_period_vs_hinge", "value_period_vs_kinematics", "value_period_vs_impact",
                             "value_overturned_vs_hinge", "tornado_period", "tornado_overturned"}) {
        for (const char* ext : {".svg", ".gp", ".dat"})
            EXPECT_TRUE(fs::exists(plots / (std::string(name) + ext))) << name << ext;
        EXPECT_TRUE(contains(md, std::string("](plots/") + name + ".svg)")) << name;
    }
    EXPECT_FALSE(fs::exists(plots / "rocking.svg")) << "a free-vibration study has no rocking curves";
    EXPECT_TRUE(contains(read(out() / st::kStudyHtml), "<svg"));
}

// The page opens with its answer: the main figures (here the first value plots, as the study has no rocking curves,
// ensemble or map) and the first tornado chart, then the largest effects, each parameter and metric once; every detail
// follows, and a figure shown at the top is not repeated under "Plots".
TEST_F(TinyStudy, ThePageOpensWithItsMainFiguresAndLargestEffects) {
    if (!gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed (Debian package gnuplot-nox)";
    st::write_study_outputs(out(), {});
    const std::string md = read(out() / st::kStudyMarkdown);
    const auto glance = md.find("\n## At a glance\n"), varied = md.find("\n## What varied\n"),
               plots = md.find("\n## Plots\n");
    ASSERT_NE(glance, std::string::npos) << md;
    EXPECT_LT(glance, varied);
    const std::string top = md.substr(glance, varied - glance);
    EXPECT_TRUE(contains(top, "](plots/value_period_vs_hinge.svg)")) << top;
    EXPECT_TRUE(contains(top, "](plots/tornado_period.svg)")) << top;
    EXPECT_EQ(std::count(top.begin(), top.end(), '!'), static_cast<long>(st::kGlanceFigures) + 1) << top;
    for (const char* shown : {"](plots/value_period_vs_hinge.svg)", "](plots/tornado_period.svg)"})
        EXPECT_EQ(md.find(shown, plots), std::string::npos) << shown << ": shown twice";
    EXPECT_TRUE(contains(md.substr(plots), "](plots/tornado_overturned.svg)")) << "the other tornado stays below";
    // The largest effects, in the ranking's order (SensitivitiesAreRankedLargestFirstWithTheirNumbers), five of six.
    const std::vector<std::string> rows = {"| impact | eq19 | whole-mechanism | overturned |",
                                           "| hinge | 0.5 | 0.7 | overturned |", "| hinge | 0.5 | 0.7 | period |",
                                           "| kinematics | paper | exact | period |",
                                           "| kinematics | paper | exact | overturned |"};
    std::size_t at = 0;
    for (const std::string& row : rows) {
        const auto found = top.find(row, at);
        ASSERT_NE(found, std::string::npos) << row << "\n" << top;
        at = found;
    }
    EXPECT_FALSE(contains(top, "| impact | eq19 | whole-mechanism | period |")) << "the sixth is below";
}

// The hover texts of every point of the SVG (hostile_names.hpp), no script handler left.
std::vector<std::string> point_texts(const std::string& svg) {
    EXPECT_FALSE(contains(svg, "onmousemove"));
    EXPECT_FALSE(contains(svg, "gnuplot_svg"));
    return vssw::testing::hover_titles(svg);
}

// Every point of a value plot and every median of a tornado names its line, x and value with its unit on hover; every
// script draws in the one font.
TEST_F(TinyStudy, PlotsShowValuesOnHoverInTheOneFont) {
    if (!gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed (Debian package gnuplot-nox)";
    const st::OutputFiles files = st::write_study_outputs(out(), {});
    EXPECT_TRUE(files.warnings.empty()) << files.warnings.front();
    const fs::path plots = out() / st::kPlotsDir;
    // Period against hinge: each series at 0.5 and 0.7 (1 s to 1.2 x 1.10 x 1.01 s), in seconds.
    const std::vector<std::string> values = point_texts(read(plots / "value_period_vs_hinge.svg"));
    EXPECT_GE(values.size(), 4u);
    for (const std::string& t : values)
        EXPECT_TRUE(std::regex_match(t, std::regex(".+, hinge 0\\.[57]: 1(\\.\\d+)? s"))) << t;
    EXPECT_NE(std::find_if(values.begin(), values.end(),
                           [](const std::string& t) { return contains(t, "hinge 0.7: 1.333 s"); }),
              values.end())
        << "the engine at 0.7: 1.2 x 1.10 x 1.01";
    // The tornado's medians: kinematics changes the period by 5 to 10 %, median 7.5 % (its "->" escaped in XML).
    const std::vector<std::string> medians = point_texts(read(plots / "tornado_period.svg"));
    EXPECT_EQ(medians.size(), 2u);
    EXPECT_NE(std::find(medians.begin(), medians.end(), "kinematics: paper -&gt; exact, 5 to 10 %, median: 7.5 %"),
              medians.end())
        << (medians.empty() ? "" : medians.front());
    // An assumption's change axis spans at least +-1 %, however small the changes.
    EXPECT_TRUE(contains(read(plots / "tornado_period.gp"), "set xrange [*<-1:1<*]"));
    // One font: the preamble's terminal, no other size anywhere.
    int scripts = 0;
    for (const auto& entry : fs::directory_iterator(plots)) {
        if (entry.path().extension() != ".gp") continue;
        ++scripts;
        const std::string gp = read(entry.path());
        const std::regex terminal("set terminal svg size \\d+,\\d+ noenhanced " + vssw::io::gp_font() + " background");
        EXPECT_EQ(std::distance(std::sregex_iterator(gp.begin(), gp.end(), terminal), std::sregex_iterator()), 1)
            << entry.path();
        for (auto at = gp.find("font "); at != std::string::npos; at = gp.find("font ", at + 1))
            EXPECT_EQ(gp.compare(at, vssw::io::gp_font().size(), vssw::io::gp_font()), 0) << entry.path();
    }
    EXPECT_GE(scripts, 6);
}

// A value plot's axis never magnifies round-off: values that agree to 8 digits get an axis of at least 1 % of them
// (no tic labels alike), values that differ keep gnuplot's autoscale.
TEST(StudyOutputs, ValuePlotAxesNeverMagnifyRoundOff) {
    st::LineFigure f;
    f.name = "flat";
    f.title = f.xlabel = f.ylabel = "flat";
    f.panel_titles = {"close", "apart"};
    f.lines = {{"line", "pt 7"}};
    f.x = {1.0, 2.0, 3.0};
    f.min_span = 0.01;
    f.resize();
    f.y[0][0] = {0.1234567, 0.1234568, 0.1234569};
    f.y[1][0] = {0.1, 0.2, 0.3};
    const std::string gp = st::line_figure_script(f).gp;
    std::smatch m;
    ASSERT_TRUE(std::regex_search(gp, m, std::regex("set yrange \\[([^:]+):([^\\]]+)\\]"))) << gp;
    EXPECT_GE(std::stod(m[2]) - std::stod(m[1]), 0.01 * 0.1234569 * (1.0 - kDatDigits)) << gp;
    EXPECT_LT(std::stod(m[1]), 0.1234567);
    EXPECT_GT(std::stod(m[2]), 0.1234569);
    EXPECT_TRUE(contains(gp.substr(static_cast<std::size_t>(m.position(0))), "set autoscale y\n")) << gp;
    // An absolute floor: errors of 1e-14 on an axis of at least 1e-6.
    f.min_abs_span = 1e-6;
    f.y[0][0] = {1.3e-14, 1.4e-14, 1.2e-14};
    const std::string floor = st::line_figure_script(f).gp;
    ASSERT_TRUE(std::regex_search(floor, m, std::regex("set yrange \\[([^:]+):([^\\]]+)\\]"))) << floor;
    EXPECT_GE(std::stod(m[2]) - std::stod(m[1]), 1e-6 * (1.0 - kDatDigits)) << floor;
}

TEST_F(TinyStudy, WithoutGnuplotTheStudyIsWrittenWithAWarning) {
    st::OutputOptions options;
    options.gnuplot = "/nonexistent/vssw-test/gnuplot";
    st::OutputFiles files;
    ASSERT_NO_THROW(files = st::write_study_outputs(out(), options));
    ASSERT_EQ(files.warnings.size(), 1u);
    EXPECT_TRUE(contains(files.warnings[0], "could not be run")) << files.warnings[0];
    const std::string md = read(out() / st::kStudyMarkdown);
    EXPECT_TRUE(contains(md, "Plots: gnuplot ('/nonexistent/vssw-test/gnuplot') could not be run"));
    EXPECT_TRUE(contains(md, "## Largest sensitivities first"));
    EXPECT_TRUE(fs::exists(out() / st::kStudyHtml));
    EXPECT_TRUE(fs::exists(out() / st::kPlotsDir / "tornado_period.gp"));
    EXPECT_FALSE(fs::exists(out() / st::kPlotsDir / "tornado_period.svg"));
    EXPECT_FALSE(fs::exists(out() / st::kPlotsDir / "tornado_period.log"));
}

// A plot program that fails after writing to its error stream, run on a plots folder named relative to the working
// folder (as `--out results` names it): what it wrote is in NAME.log beside the script, where the failure note points,
// and not on the user's terminal. The log was once opened after changing into the folder, so a relative path named a
// file that could not be made.
TEST(Gnuplot, AFailedPlotLeavesItsLogBesideItsScriptWhenTheFolderIsRelative) {
    const vssw::testing::TempDir dir("gnuplot_relative");
    const fs::path fake = dir / "fake-gnuplot";
    {
        std::ofstream f(fake);
        f << "#!/bin/sh\necho 'fake gnuplot warning' >&2\nexit 1\n";
    }
    fs::permissions(fake, fs::perms::owner_all);
    // Work in dir, so that the folder is "plots" (a path climbing out with "..", as from the build folder to /tmp,
    // can resolve from inside the folder too and would hide the fault); the working folder is put back after.
    struct WorkingFolder {
        fs::path before = fs::current_path();
        explicit WorkingFolder(const fs::path& to) { fs::current_path(to); }
        ~WorkingFolder() { fs::current_path(before); }
    } in_dir(dir.path);
    const vssw::io::PlotResult r =
        vssw::io::draw_plots({{{"section", "p", "a plot", false}, "plot 1\n", "1 2\n"}}, "plots", fake.string());
    ASSERT_EQ(r.plots.size(), 1u);
    EXPECT_FALSE(r.plots[0].made);
    EXPECT_TRUE(contains(r.note, "gnuplot exit 1, see p.log")) << r.note;
    EXPECT_TRUE(contains(read(dir / "plots" / "p.log"), "fake gnuplot warning"));
}

TEST_F(TinyStudy, AMergedStudyIsWrittenAsASingleRun) {
    for (int k = 1; k <= 2; ++k) write_study(dir_.path / ("shard" + std::to_string(k)), *grid_, tiny_value, {k, 2});
    st::merge_studies({dir_.path / "shard1", dir_.path / "shard2"}, dir_.path / "merged");
    const st::OutputOptions options = gnuplot_available() ? st::OutputOptions{} : no_plots();
    st::write_study_outputs(out(), options);
    st::write_study_outputs(dir_.path / "merged", options);
    EXPECT_EQ(read(dir_.path / "merged" / st::kResultsCsv), read(out() / st::kResultsCsv));
    const std::string single = read(out() / st::kStudyMarkdown);
    const std::string merged = read(dir_.path / "merged" / st::kStudyMarkdown);
    EXPECT_NE(single, merged) << "the Run sections differ (a merge names its shards)";
    EXPECT_EQ(without_run_section(merged), without_run_section(single));
    if (!options.plots) return;
    int compared = 0;
    for (const auto& entry : fs::directory_iterator(out() / st::kPlotsDir)) {
        const std::string ext = entry.path().extension().string();
        if (ext != ".dat" && ext != ".gp") continue;
        EXPECT_EQ(read(dir_.path / "merged" / st::kPlotsDir / entry.path().filename()), read(entry.path()))
            << entry.path().filename();
        ++compared;
    }
    EXPECT_GT(compared, 0);
}

// Past kMaxPanels, the last parameters are summarised by their median and the title says over which.
TEST(StudyOutputs, PanelsPastTheLimitAreMediansOverTheLastParameters) {
    TempDir dir("study_panels");
    const st::Grid grid(spec_of(dir.path, "name = \"panels\"\nmetrics = [\"period\"]\nengines = [\"analytic\"]\n"
                                            "[wall]\nheight = [3, 4, 5]\nthickness = [0.2, 0.3, 0.4]\n"
                                            "hinge = [0.6, 0.7]\nxi = [0, 0.1]\n"
                                            "[excitation]\nkind = \"free\"\ntheta0 = 0.5\n"));
    // period = height + hinge: the median over the two hinges is height + 0.65.
    write_study(dir.path / "out", grid,
                [](const st::CaseSpec& c, const st::RunSpec&, const std::string&) { return c.height + c.hinge; });
    if (!gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed (Debian package gnuplot-nox)";
    st::write_study_outputs(dir.path / "out", {});
    const fs::path plots = dir.path / "out" / st::kPlotsDir;
    // Against xi: height x thickness = 9 panels fit within 12, x hinge = 18 does not.
    EXPECT_TRUE(contains(read(plots / "value_period_vs_xi.gp"), "period against xi (median over hinge)"));
    const auto lines = dat_lines(plots / "value_period_vs_xi.dat");
    ASSERT_EQ(lines.size(), 9u * 2u);  // 9 panels x 1 series x 2 levels of xi
    EXPECT_NEAR(std::stod(lines[0][1]), 3.65, kDatDigits);   // height 3, thickness 0.2, xi 0
    EXPECT_NEAR(std::stod(lines[17][1]), 5.65, kDatDigits);  // height 5, thickness 0.4, xi 0.1
    // Against hinge: height x thickness x xi = 18 panels: xi is summarised.
    EXPECT_TRUE(contains(read(plots / "value_period_vs_hinge.gp"), "(median over xi)"));
}

// Record studies: rocking curves per record and level, a panel per R, an overturned run at 1 and marked.
TEST(StudyOutputs, RockingCurvesMarkOverturnedRunsAtOne) {
    TempDir dir("study_rocking");
    const st::Grid grid(
        spec_of(dir.path, "name = \"rocking\"\nmetrics = [\"peak_rotation\", \"overturned\"]\n"
                          "engines = [\"analytic\"]\n[wall]\nalpha = [0.05, 0.1, 0.2]\nR = [1, 3]\nhinge = 0.6\nxi = 0.1\n"
                          "[excitation]\nkind = \"record\"\nfile = \"" VSSW_DATA_DIR "/NGA_no_1063_RRS228.AT2\"\n"
                          "pga = [0.3, 0.6]\n"));
    // The slenderest wall overturns (its peak is the collapse angle, 4.2 alpha); the others peak at 0.1 / alpha.
    write_study(dir.path / "out", grid, [](const st::CaseSpec& c, const st::RunSpec&, const std::string& metric) {
        const bool over = c.alpha < 0.06;
        if (metric == "overturned") return over ? 1.0 : 0.0;
        return over ? 4.2 : 0.1 / c.alpha;
    });
    const st::StudyData d = st::read_study_data(dir.path / "out");
    EXPECT_EQ(d.columns[d.column("R")].order.size(), 2u) << "R computed from the wall is one level per file level";
    if (!gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed (Debian package gnuplot-nox)";
    st::write_study_outputs(dir.path / "out", {});
    const fs::path plots = dir.path / "out" / st::kPlotsDir;
    for (const char* pga : {"0.3", "0.6"}) {
        const fs::path dat = plots / (std::string("rocking_NGA_no_1063_RRS228_pga") + pga + ".dat");
        ASSERT_TRUE(fs::exists(dat)) << dat;
        const auto lines = dat_lines(dat);
        ASSERT_EQ(lines.size(), 2u * 3u);  // 2 panels (R) x 1 series x 3 alpha
        EXPECT_EQ(lines[0], (std::vector<std::string>{"0.05", "1", "1"})) << "overturned: at 1, marked";
        EXPECT_EQ(lines[1], (std::vector<std::string>{"0.1", "1", "0"}));
        EXPECT_NEAR(std::stod(lines[2][1]), 0.5, kDatDigits);
    }
    EXPECT_TRUE(fs::exists(plots / "rocking_NGA_no_1063_RRS228_pga0.3.svg"));
    // The value plot of peak_rotation shows an overturned run as the rocking curves do, at 1 and marked, not at its
    // collapse angle (4.2): one drawing of an overturned run under one label.
    const auto values = dat_lines(plots / "value_peak_rotation_vs_alpha.dat");
    std::size_t overturned_points = 0;
    for (const auto& line : values) {
        ASSERT_GE(line.size(), 3u);
        if (line[0] != "0.05") continue;
        ++overturned_points;
        EXPECT_EQ(std::vector<std::string>(line.begin(), line.begin() + 3),
                  (std::vector<std::string>{"0.05", "1", "1"}));
    }
    EXPECT_GT(overturned_points, 0u);
    EXPECT_TRUE(contains(read(plots / "value_peak_rotation_vs_alpha.gp"), "title 'overturned'"));
}

// An ensemble's rocking curves ring an overturned median at 1 and name the ring "overturned" in the key; where no
// median overturned, the key has no such entry (a wall standing under every record is not labelled as falling).
TEST(StudyOutputs, EnsembleRockingCurvesNameOverturnedOnlyWhenAMedianOverturned) {
    for (const bool slenderest_falls : {false, true}) {
        TempDir dir("study_ensemble_rocking");
        const st::Grid grid(spec_of(
            dir.path, "name = \"rocking\"\nmetrics = [\"peak_rotation\", \"overturned\"]\nengines = [\"analytic\"]\n"
                      "[wall]\nalpha = [0.05, 0.1]\nR = 2\nhinge = 0.6\nxi = 0.1\n[excitation]\nkind = \"ensemble\"\n"
                      "files = [\"" VSSW_DATA_DIR "/records/northridge1994-rinaldi-228.at2\", \"" VSSW_DATA_DIR
                      "/records/northridge1994-pacoimadam-ew.at2\"]\nintensity = \"pga\"\nlevels = [0.4]\n"));
        // Under both records the slenderest wall falls (its peak the collapse angle, 4.2 alpha) or peaks at 0.5.
        write_study(dir.path / "out", grid, [&](const st::CaseSpec& c, const st::RunSpec&, const std::string& metric) {
            const bool over = slenderest_falls && c.alpha < 0.06;
            if (metric == "overturned") return over ? 1.0 : 0.0;
            return over ? 4.2 : 0.05 / c.alpha;
        });
        st::OutputOptions o;
        o.gnuplot = (dir.path / "no-gnuplot").string();  // the plots' scripts and data without drawing them
        st::write_study_outputs(dir.path / "out", o);
        const std::string gp = read(dir.path / "out" / st::kPlotsDir / "ensemble_rocking.gp");
        ASSERT_TRUE(contains(gp, "($7 > 0.5 ? $2 : NaN)")) << gp;
        EXPECT_EQ(contains(gp, "title 'overturned'"), slenderest_falls) << gp;
    }
}

// Pulse studies: the overturning map's points, peak capped at 1, overturned runs flagged, a block per series.
TEST(StudyOutputs, OverturningMapHoldsEveryPulseWithItsVerdict) {
    TempDir dir("study_map");
    const st::Grid grid(spec_of(dir.path, "name = \"map\"\nmetrics = [\"peak_rotation\", \"overturned\"]\n"
                                            "engines = [\"analytic\"]\n"
                                            "[wall]\nheight = 4\nthickness = 0.4\nhinge = 0.7\n"
                                            "[assumptions]\nimpact = [\"eq19\", \"whole-mechanism\"]\n"
                                            "[excitation]\nkind = \"pulse\"\nshape = \"sine\"\n"
                                            "amplitude = [0.3, 0.6]\npulse_period = [0.5, 1.0]\n"));
    // Eq. (19) overturns from 0.6 g; the peak otherwise is amplitude x period.
    write_study(dir.path / "out", grid, [](const st::CaseSpec& c, const st::RunSpec& run, const std::string& metric) {
        const bool over = c.amplitude_g > 0.5 && text_of(run, 1) == "eq19";
        if (metric == "overturned") return over ? 1.0 : 0.0;
        return over ? 4.0 : c.amplitude_g * c.pulse_period;
    });
    if (!gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed (Debian package gnuplot-nox)";
    st::write_study_outputs(dir.path / "out", {});
    const auto lines = dat_lines(dir.path / "out" / st::kPlotsDir / "overturning_map.dat");
    ASSERT_EQ(lines.size(), 2u * 4u);  // 2 series x 4 pulses
    // Eq. (19): period, amplitude, peak (capped at 1), overturned.
    EXPECT_EQ(lines[0], (std::vector<std::string>{"0.5", "0.3", "0.15", "0"}));
    EXPECT_EQ(lines[2], (std::vector<std::string>{"0.5", "0.6", "1", "1"}));
    // The whole-mechanism impact stands at 0.6 g x 1 s with a peak of 0.6.
    EXPECT_EQ(lines[7], (std::vector<std::string>{"1", "0.6", "0.6", "0"}));
    EXPECT_TRUE(fs::exists(dir.path / "out" / st::kPlotsDir / "overturning_map.svg"));
}

// Text reaches gnuplot only as quoted data: whatever it holds, it is shown as it is and never runs.
TEST(Gnuplot, TextIsQuotedAsDataThatNeverRuns) {
    EXPECT_EQ(vssw::io::gp_string("it's `a` @m $(b)"), "'it''s `a` @m $(b)'");
    EXPECT_EQ(vssw::io::gp_string("line\nnext\r\tend\x7f"), "'line next  end '");
    EXPECT_EQ(vssw::io::gp_comment("a\n!cmd \\"), "a !cmd \\ ") << "one line, not continued by a final backslash";
    EXPECT_EQ(vssw::io::gp_data_string("a \"b\" c\\d\ne"), "\"a 'b' c/d e\"") << "one column of a data file";
    EXPECT_TRUE(vssw::io::gp_safe_name("trace_fig6-vssw_r0.5"));
    for (const char* bad : {"", ".hidden", "-x", "a b", "a'b", "a/b", "a\nb"}) EXPECT_FALSE(vssw::io::gp_safe_name(bad)) << bad;

    if (!gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed (Debian package gnuplot-nox)";
    TempDir dir("gnuplot_hostile");
    const std::string& text = vssw::testing::kHostileName;
    vssw::io::PlotScript s;
    s.plot = {"section", "hostile", text, false};
    s.dat = "# " + vssw::io::gp_comment(text) + "\n0 " + vssw::io::gp_data_string(text) + " 1\n1 " + vssw::io::gp_data_string(text) +
            " 2\n";
    s.gp = vssw::io::gp_preamble("vssw test", "hostile", 640, 480) + "set title " + vssw::io::gp_string("title " + text) +
           "\nset xlabel " + vssw::io::gp_string("x " + text) + "\nset xtics (" + vssw::io::gp_string("tic " + text) +
           " 0)\n# " + vssw::io::gp_comment(text + "\\") + "\nplot 'hostile.dat' using 1:3 with lines title " +
           vssw::io::gp_string("key " + text) + "\n";
    const vssw::io::PlotResult r = vssw::io::draw_plots({s}, dir.path / "plots", "gnuplot");
    EXPECT_TRUE(vssw::testing::markers_made(dir.path).empty()) << vssw::testing::markers_made(dir.path).front();
    ASSERT_TRUE(r.all_made) << r.note;
    const std::string svg = read(dir.path / "plots" / "hostile.svg");
    for (const char* what : {"title ", "x ", "tic ", "key "})
        EXPECT_TRUE(contains(svg, vssw::testing::svg_text(what + text))) << what;

    // A plot whose name is not a plain file stem is refused, not written into a script.
    s.plot.name = "a'b";
    const vssw::io::PlotResult refused = vssw::io::draw_plots({s}, dir.path / "plots", "gnuplot");
    EXPECT_FALSE(refused.all_made);
    EXPECT_TRUE(contains(refused.note, "not a plain file name")) << refused.note;
    EXPECT_FALSE(fs::exists(dir.path / "plots" / "a'b.gp"));
}

// A record study of two walls on a copy of Rinaldi named `record_name` in dir, its results written by hand into
// dir/out (peaks 0.1/alpha, nothing overturns): what the plots of a record's name are tested on.
void write_named_record_study(const fs::path& dir, const std::string& record_name, const std::string& name) {
    const fs::path record = dir / record_name;
    fs::copy_file(VSSW_DATA_DIR "/NGA_no_1063_RRS228.AT2", record);
    const st::Grid grid(spec_of(dir, "name = " + vssw::testing::toml_string(name) +
                                         "\ndescription = " + vssw::testing::toml_string(name) +
                                         "\nmetrics = [\"peak_rotation\", \"overturned\"]\nengines = [\"analytic\"]\n"
                                         "[wall]\nalpha = [0.05, 0.1]\nR = 1\nhinge = 0.6\n"
                                         "[excitation]\nkind = \"record\"\nfile = " +
                                         vssw::testing::toml_string(record.string()) + "\npga = 0.3\n"));
    write_study(dir / "out", grid, [](const st::CaseSpec& c, const st::RunSpec&, const std::string& metric) {
        return metric == "overturned" ? 0.0 : 0.1 / c.alpha;
    });
}

// A study shared with a record file named to run commands, and such a name and description: its plots are drawn with
// the names shown as they are, nothing runs, and its pages show the markup as text.
TEST(StudyOutputs, HostileNamesAreShownAndNeverRun) {
    TempDir dir("study_hostile");
    const std::string name = vssw::testing::kHostileName + " " + vssw::testing::kMarkupName;
    write_named_record_study(dir.path, vssw::testing::kHostileFileName, name);
    if (!gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed (Debian package gnuplot-nox)";
    const st::OutputFiles files = st::write_study_outputs(dir.path / "out", {});
    EXPECT_TRUE(vssw::testing::markers_made(dir.path).empty()) << vssw::testing::markers_made(dir.path).front();
    EXPECT_TRUE(files.warnings.empty()) << files.warnings.front();
    const fs::path plots = dir.path / "out" / st::kPlotsDir;
    const std::string stem = vssw::io::file_stem(fs::path(vssw::testing::kHostileFileName).stem().string());
    const fs::path svg = plots / ("rocking_" + stem + ".svg");
    ASSERT_TRUE(fs::exists(svg)) << svg;
    // The title names the record by its file's name.
    EXPECT_TRUE(contains(read(svg), vssw::testing::svg_text("file " + vssw::testing::kHostileFileName))) << read(svg);
    const std::string html = read(dir.path / "out" / st::kStudyHtml), md = read(dir.path / "out" / st::kStudyMarkdown);
    EXPECT_FALSE(contains(html, "<script"));
    EXPECT_TRUE(contains(html, "&lt;script&gt;alert(1)&lt;/script&gt;"));
    // Markdown as MkDocs renders it: the names as text, no live markup.
    EXPECT_EQ(vssw::testing::markdown_problems(dir.path / "out" / st::kStudyMarkdown, {name}), "") << md;
    for (const std::string& text : {html, md}) EXPECT_TRUE(contains(text, "M\xC3\xBCller \xCE\xB5 \xE5\x9C\xB0\xE9\x9C\x87"));
}

// A record whose file name is as long as a file name may be (250 bytes, +".AT2"): its plot's name ("rocking_" + the
// stem + ".svg") would pass NAME_MAX (255) and the plot would be lost; the stem is cut and tagged instead, and the
// plot is drawn.
TEST(StudyOutputs, ARecordWithTheLongestFileNameStillGetsItsPlot) {
    TempDir dir("study_longname");
    write_named_record_study(dir.path, std::string(250, 'r') + ".AT2", "long");
    if (!gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed (Debian package gnuplot-nox)";
    const st::OutputFiles files = st::write_study_outputs(dir.path / "out", {});
    EXPECT_TRUE(files.warnings.empty()) << files.warnings.front();
    // The record's rocking plot, under a name cut to a file name's length (and tagged).
    int rocking = 0;
    for (const auto& e : fs::directory_iterator(dir.path / "out" / st::kPlotsDir)) {
        const std::string file = e.path().filename().string();
        EXPECT_LE(file.size(), vssw::io::kMaxFileStem + 20) << file;  // a stem and a short extension
        rocking += file.rfind("rocking_rrr", 0) == 0 && e.path().extension() == ".svg";
    }
    EXPECT_EQ(rocking, 1);
}

TEST(StudyOutputs, AFolderWithoutAManifestIsBadInputNamingIt) {
    TempDir dir("study_nomanifest");
    try {
        st::write_study_outputs(dir.path, {});
        FAIL() << "no manifest: InputError expected";
    } catch (const vssw::InputError& e) {
        EXPECT_TRUE(contains(e.what(), (dir.path / st::kManifestFile).string())) << e.what();
    }
}

}  // namespace

namespace {

// Two records whose files reduce to one stem (a/r.AT2 and b/r.AT2) get a rocking plot each: one must not replace the
// other's files in plots/.
TEST(StudyOutputs, RecordsOfTheSameFileNameGetAPlotEach) {
    TempDir dir("study_same_stem");
    for (const char* sub : {"a", "b"}) {
        fs::create_directories(dir.path / sub);
        fs::copy_file(VSSW_DATA_DIR "/NGA_no_1063_RRS228.AT2", dir.path / sub / "r.AT2");
    }
    const st::Grid grid(spec_of(dir.path, "metrics = [\"peak_rotation\", \"overturned\"]\nengines = [\"analytic\"]\n"
                                          "[wall]\nalpha = [0.05, 0.1]\nR = 1\nhinge = 0.6\n"
                                          "[excitation]\nkind = \"record\"\nfile = [\"a/r.AT2\", \"b/r.AT2\"]\n"
                                          "pga = 0.3\n"));
    write_study(dir.path / "out", grid, [](const st::CaseSpec& c, const st::RunSpec&, const std::string& metric) {
        return metric == "overturned" ? 0.0 : (c.file.front() == 'a' ? 0.1 : 0.2) / c.alpha;
    });
    if (!gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed (Debian package gnuplot-nox)";
    (void)st::write_study_outputs(dir.path / "out", {});
    std::vector<std::string> rocking;
    for (const auto& e : fs::directory_iterator(dir.path / "out" / st::kPlotsDir))
        if (e.path().extension() == ".svg" && e.path().stem().string().rfind("rocking_", 0) == 0)
            rocking.push_back(e.path().stem().string());
    std::sort(rocking.begin(), rocking.end());
    EXPECT_EQ(rocking, (std::vector<std::string>{"rocking_r-1", "rocking_r-2"}));
}

}  // namespace
