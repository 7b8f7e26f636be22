// Studies (study/): the study file read as written (and every malformation named), the grid's cases and runs, the
// physics of what a run measures (the threshold against Eq. 12 and its size invariance, free vibrations and records
// against the model run directly; the closed forms in test_shipped_studies.cpp), and the
// machinery: threads, shards and merge give the same rows; an interrupted study resumes; a failing run is a row.
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>
#include <stdexcept>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <fmt/format.h>

#include "analytic/assumption_sets.hpp"
#include "analytic/closed_forms.hpp"
#include "analytic/error.hpp"
#include "analytic/ground_motion.hpp"
#include "analytic/model.hpp"
#include "analytic/simulate.hpp"
#include "analytic/wall.hpp"
#include "compare/targets.hpp"
#include "multibody/engine.hpp"
#include "io/gnuplot.hpp"
#include "study/effects.hpp"
#include "study/merge.hpp"
#include "study/outputs.hpp"
#include "study/study_data.hpp"
#include "study/study_plots.hpp"
#include "validation/suite_file.hpp"
#include "tests/engine_available.hpp"
#include "tests/study_fixtures.hpp"

namespace {

using namespace vssw;
using vssw::testing::engine_available;
using study::Grid;
using study::ResultsTable;
using vssw::testing::TempDir;
using vssw::testing::run_into;
using vssw::testing::study_of;
using vssw::testing::value_of;

// The bisection's relative bracket (compare::ThresholdOptions::rel_tol): two thresholds found by bisection agree to it.
constexpr double kThresholdBracket = 1e-4;
// Floating-point agreement of one formula evaluated two ways (ratios of closed forms).
constexpr double kRoundoff = 1e-12;
// Restitution and period read from samples every 1e-4 s against the model's events. The sampled crossing is misplaced
// by up to dt (1 - sqrt e)/(1 + sqrt e) (compare/metrics.hpp), so the error grows as e falls: measured on Fig. 6,
// 5.4e-6 at Eq. (19)'s 0.951, 2.2e-5 at 0.8, 6.5e-5 at 0.5; this covers e down to 0.5.
constexpr double kSampledRatio = 1e-4;

std::string refusal(const TempDir& dir, const std::string& toml) {
    try {
        const Grid grid(study_of(dir, toml));
        return "";
    } catch (const InputError& e) {
        return e.what();
    }
}

// The study file -------------------------------------------------------------------------------------------------

// The example study file, as validation scripts write it.
const char* const kIssueExample = R"(
name = "hinge-and-overburden"
metrics = ["threshold_g", "period", "restitution"]
engines = ["analytic", "ode"]          # each engine runs every case

[wall]
model = "vssw"
height = 4.88
thickness = [0.356, 0.2]
hinge = [0.5, 0.6, 0.7]
xi = [0.0, 0.1]

[assumptions]                          # the analytic model's; engines ignore them (their physics is their own)
kinematics = ["paper", "exact"]
impact = "eq19"                        # eq19 | whole-mechanism | a number
roller = "bilateral"                   # bilateral | unilateral

[excitation]
kind = "free"                          # threshold | free | pulse | record | scale-to-collapse
theta0 = [0.2, 0.5]                    # record: file = "...", scale = [...] or pga = [...]; pulse: shape, amplitude, pulse_period

[settings.ode]
dt = 2e-4
)";

TEST(StudyFile, TheIssuesExampleReadsAsWritten) {
    if (!engine_available("ode")) GTEST_SKIP() << "ODE is not built";
    const TempDir dir;
    const Grid grid(study_of(dir, kIssueExample));
    EXPECT_EQ(grid.spec().name, "hinge-and-overburden");
    EXPECT_EQ(grid.product_size(), 2u * 3u * 2u * 2u);  // thickness x hinge x xi x theta0
    EXPECT_EQ(grid.case_ids().size(), 24u);
    ASSERT_EQ(grid.runs().size(), 3u);  // analytic paper, analytic exact, ode
    EXPECT_EQ(grid.runs()[0].kinematics, Kinematics::paper);
    EXPECT_EQ(grid.runs()[1].kinematics, Kinematics::exact);
    EXPECT_EQ(grid.runs()[2].engine, "ode");
    EXPECT_EQ(grid.runs()[2].settings.dt, 2e-4);
    EXPECT_EQ(grid.runs()[2].settings_text, "dt=0.0002");
    // The columns the issue names, in its order, between engine and metric.
    const std::vector<std::string> named = {"model", "height", "thickness", "hinge", "xi", "density", "g",
                                            "kinematics", "impact", "roller", "kind", "theta0", "file", "scale",
                                            "pga", "shape", "amplitude", "pulse_period"};
    const auto header = study::results_header(grid);
    ASSERT_GE(header.size(), named.size() + 2);
    EXPECT_EQ(header[0], "case_id");
    EXPECT_EQ(header[1], "engine");
    EXPECT_TRUE(std::equal(named.begin(), named.end(), header.begin() + 2));
    const std::vector<std::string> tail = {"metric", "value", "unit", "status"};
    EXPECT_TRUE(std::search(header.begin(), header.end(), tail.begin(), tail.end()) != header.end());
}

// A study's engines in any letter case are the backends' canonical names, in a list and as a table's keys, and
// [settings.X] finds its engine however X is spelt.
TEST(StudyFile, EngineNamesAreReadInAnyLetterCase) {
    const TempDir dir;
    const std::string rest = "[wall]\nheight = 4\nthickness = 0.4\nhinge = 0.7\n[excitation]\nkind = \"threshold\"\n";
    EXPECT_EQ(study_of(dir, "engines = [\"ANALYTIC\"]\n" + rest).engines.at(0).name, "analytic");
    const study::StudySpec table = study_of(dir, "[engines.Analytic]\nrtol = 1e-9\n" + rest);
    EXPECT_EQ(table.engines.at(0).name, "analytic");
    const study::StudySpec settings = study_of(dir, "engines = [\"analytic\"]\n[settings.ANALYTIC]\nrtol = 1e-9\n" + rest);
    EXPECT_FALSE(settings.engines.at(0).settings.empty());
}

// An engine's setting must have a name: a table key "" is refused naming where it is (the fuzzer found it accepted,
// an axis without a key; tests/fuzz/corpus/study_file/setting-without-a-name.json replays it).
TEST(StudyFile, ASettingWithoutANameIsRefused) {
    const TempDir dir;
    const std::string rest = "[wall]\nheight = 4\nthickness = 0.4\nhinge = 0.7\n[excitation]\nkind = \"threshold\"\n";
    for (const char* table : {"[engines.ode]\n\"\" = 0.2\n", "engines = [\"ode\"]\n[settings.ode]\n\"\" = 0.2\n"}) {
        try {
            (void)study_of(dir, std::string(table) + rest);
            ADD_FAILURE() << "accepted a setting without a name: " << table;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("a setting without a name"), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find(".ode"), std::string::npos) << e.what();
        }
    }
}

// [assumptions] set: the set's three parts are the study's, the default set when the file names none (every command's
// default, analytic/assumption_sets.hpp), and a key the file gives replaces its part alone.
TEST(StudyFile, TheSetGivesEveryAssumptionAndAKeyOverridesItsPart) {
    const TempDir dir;
    const std::string rest = "[wall]\nheight = 4\nthickness = 0.4\nhinge = 0.7\n[excitation]\nkind = \"threshold\"\n";
    const auto read = [&](const std::string& assumptions) {
        const study::StudySpec spec = study_of(dir, assumptions + rest);
        std::vector<study::Level> levels;
        for (const study::Axis& a : spec.assumptions) {
            EXPECT_EQ(a.levels.size(), 1u) << a.key;
            levels.push_back(a.levels.front());
        }
        return study::assumptions_of(levels);
    };
    const Assumptions mechanism = assumptions_of(AssumptionSet::mechanism), paper = assumptions_of(AssumptionSet::paper);
    EXPECT_TRUE(read("") == assumptions_of(kDefaultAssumptionSet));
    EXPECT_TRUE(read("") == mechanism) << "the one default of every entry point";
    EXPECT_TRUE(read("[assumptions]\nset = \"mechanism\"\n") == mechanism);
    EXPECT_TRUE(read("[assumptions]\nset = \"paper\"\n") == paper);
    EXPECT_FALSE(paper == mechanism) << "two sets that differ, or the checks above tell nothing";
    Assumptions paper_whole = paper;
    paper_whole.impact = ImpactLaw{ImpactLaw::Kind::whole_mechanism, 0.0};
    EXPECT_TRUE(read("[assumptions]\nset = \"paper\"\nimpact = \"whole-mechanism\"\n") == paper_whole);
    EXPECT_EQ(set_name(paper_whole), "custom");
    Assumptions mechanism_bilateral = mechanism;
    mechanism_bilateral.roller = Roller::bilateral;
    EXPECT_TRUE(read("[assumptions]\nroller = \"bilateral\"\n") == mechanism_bilateral);
}

TEST(StudyFile, TomlAndJsonSayTheSame) {
    const TempDir dir;
    const std::string toml = "[wall]\nheight = 4\nthickness = [0.2, 0.4]\nhinge = 0.7\n[excitation]\nkind = \"threshold\"\n";
    const std::string json =
        R"({"wall": {"height": 4, "thickness": [0.2, 0.4], "hinge": 0.7}, "excitation": {"kind": "threshold"}})";
    const Grid a(study_of(dir, toml, "s.toml")), b(study_of(dir, json, "s.json"));
    EXPECT_EQ(a.identity(), b.identity());
    EXPECT_EQ(a.case_ids(), b.case_ids());
    EXPECT_EQ(a.spec().metrics, std::vector<std::string>{"threshold_g"});  // the kind's default
}

TEST(StudyFile, EachMalformationIsNamedBeforeAnythingRuns) {
    const TempDir dir;
    const std::string wall = "[wall]\nheight = 4\nthickness = 0.4\nhinge = 0.7\n";
    const std::string threshold = "[excitation]\nkind = \"threshold\"\n";
    struct Case {
        std::string toml, expected;
    };
    const std::vector<Case> cases = {
        {wall + "foo = 1\n" + threshold, "wall: unknown key 'foo'"},
        {"[wall]\nheight = \"4\"\nthickness = 0.4\nhinge = 0.7\n" + threshold, "wall.height: must be a finite number"},
        {"[wall]\nheight = []\nthickness = 0.4\nhinge = 0.7\n" + threshold, "wall.height: an empty list"},
        {"[wall]\nheight = [4, 4]\nthickness = 0.4\nhinge = 0.7\n" + threshold, "wall.height: lists 4 twice"},
        {"[wall]\nheight = 4\nthickness = [0.4, -0.2]\nhinge = 0.7\n" + threshold, "got -0.2"},
        {"[wall]\nheight = nan\nthickness = 0.4\nhinge = 0.7\n" + threshold, "wall.height: must be a finite number"},
        {"[wall]\nheight = 4\nthickness = 0.4\nhinge = 1.5\n" + threshold, "hinge ratio h1/h must be strictly between"},
        {"[wall]\nheight = 4\nthickness = 0.4\n" + threshold, "a VSSW needs 'hinge'"},
        {wall + "overburden_eccentricity = 1.5\n" + threshold, "wall.overburden_eccentricity: must be N's eccentricity"},
        {"[wall]\nheight = 4\nalpha = 0.1\nR = 2\nhinge = 0.7\n" + threshold, "give the geometry one way"},
        {wall, "no [excitation] table"},
        {wall + "[excitation]\nkind = \"earthquake\"\n", "excitation.kind: must be one of"},
        {wall + "[excitation]\nkind = \"free\"\n", "kind free needs 'theta0'"},
        {wall + "[excitation]\nkind = \"free\"\ntheta0 = 0.001\n", "theta0: must be at least 0.01"},
        {wall + "[excitation]\nkind = \"free\"\ntheta0 = 30\n", "beyond the wall's collapse angle"},
        {wall + "[excitation]\nkind = \"record\"\nfile = \"no-such.AT2\"\n", "excitation.file"},
        {wall + "[excitation]\nkind = \"record\"\nfile = \"x\"\nscale = 1\npga = 0.3\n", "not 'scale' and 'pga'"},
        {wall + "[excitation]\nkind = \"record\"\nfile = \"x\"\npga = 0.3\npgv = 0.3\n", "not 'pga' and 'pgv'"},
        {wall + "[excitation]\nkind = \"record\"\nfile = \"x\"\nsa = 0.3\n", "'sa' needs 'sa_period'"},
        {wall + "[excitation]\nkind = \"record\"\nfile = \"x\"\npgv = 0.3\nsa_period = 1\n",
         "excitation.sa_period: is for 'sa'"},
        {wall + "[excitation]\nkind = \"scale-to-collapse\"\nfile = \"x\"\nsa_damping = 0.1\n",
         "excitation.sa_damping: is for the metric collapse_sa"},
        {"metrics = [\"collapse_sa\"]\n" + wall + "[excitation]\nkind = \"scale-to-collapse\"\nfile = \"x\"\n",
         "the metric collapse_sa needs 'sa_period'"},
        {wall + "[excitation]\nkind = \"pulse\"\nshape = \"harmonic\"\namplitude = 0.3\npulse_period = 1\n",
         "shape harmonic needs 'duration'"},
        {wall + "[excitation]\nkind = \"threshold\"\ntheta0 = 0.5\n", "unknown key 'theta0'"},
        // a step of 1e-9 asked for 2e9 runs
        {wall + "[excitation]\nkind = \"scale-to-collapse\"\nfile = \"x\"\nstep = 1e-9\n",
         "excitation.step: must be a relative increment in [0.001, 1], got 1e-09"},
        // a tolerance of 1e-17 never ended: its bisection's mid-point rounds onto an end
        {wall + "[excitation]\nkind = \"scale-to-collapse\"\nfile = \"x\"\ntolerance = 1e-17\n",
         "excitation.tolerance: must be a relative width in [1e-12, 0.1], got 1e-17"},
        {"engines = [\"havok\"]\n" + wall + threshold, "no engine 'havok' in this build"},
        {"engines = [\"Analytik\"]\n" + wall + threshold, "no engine 'Analytik' in this build (did you mean 'analytic'?)"},
        {"engines = [\"analytic\", \"Analytic\"]\n" + wall + threshold, "names engine 'analytic' twice"},
        {"engines = [\"analytic\", \"analytic\"]\n" + wall + threshold, "names engine 'analytic' twice"},
        {"[settings.ode]\ndt = 1e-4\n" + wall + threshold, "settings.ode: settings for an engine the study does not run"},
        {"[settings.analytic]\nrtol = 0\n" + wall + threshold, "settings of analytic (rtol=0)"},
        {"[settings.analytic]\npaper_kinematics = 1\n" + wall + threshold, "go in [assumptions]"},
        {"metrics = [\"period\"]\n" + wall + threshold, "'period' is not measured by an excitation of kind threshold"},
        {"metrics = [\"wobble\"]\n" + wall + threshold, "unknown metric 'wobble'"},
        {"[assumptions]\nimpact = 1.5\n" + wall + threshold, "an impact ratio must be in [0, 1]"},
        {"[assumptions]\nkinematics = \"approximate\"\n" + wall + threshold, "assumptions.kinematics: must be one of"},
        {"[assumptions]\nset = \"linear\"\n" + wall + threshold,
         "assumptions.set: must be one of paper, mechanism, got \"linear\""},
        {"[assumptions]\nset = [\"paper\", \"mechanism\"]\n" + wall + threshold,
         "assumptions.set: one set per study, got [\"paper\",\"mechanism\"]: vary kinematics, impact or roller"},
        {"[assumptions]\nsets = \"paper\"\n" + wall + threshold,
         "assumptions: unknown key 'sets' (known: set, kinematics, impact, roller)"},
        {"speed = 3\n" + wall + threshold, "unknown key 'speed'"},
        {"[wall]\nalpha1 = 0.1\nalpha2 = 0.2\nR1 = 1.5\nhinge = 0.6\n" + threshold, "fix the hinge"},
        {"[wall]\nspecimen = 1e10\n" + threshold, "must be a Table 1 specimen number"},
        {"[settings.analytic]\ndt = 1e-3\n" + wall + threshold, "no step or iterations to set"},
        {"one_at_a_time = [\"xi\"]\n[wall]\nheight = 4\nthickness = 0.4\nhinge = 0.7\nxi = [0, 0.1]\n" + threshold,
         "one_at_a_time: must list two or more wall or excitation keys"},
        {"one_at_a_time = [\"speed\", \"xi\"]\n" + wall + threshold, "'speed' is not a wall or excitation key"},
        {"one_at_a_time = [\"xi\", \"hinge\"]\n[wall]\nheight = 4\nthickness = 0.4\nhinge = 0.7\nxi = [0, 0.1]\n" +
             threshold,
         "one_at_a_time: 'hinge' is not given as a list"},
        {"[settings.analytic]\nrtol = 1e-9\n[[part]]\n[part.wall]\nheight = 4\nthickness = 0.4\nhinge = 0.7\n"
         "[part.excitation]\nkind = \"threshold\"\n[part.settings.analytic]\nrtol = 1e-8\n",
         "part[1].settings.analytic.rtol: given in the study's [settings.analytic] too"},
    };
    for (const Case& c : cases) {
        const std::string message = refusal(dir, c.toml);
        EXPECT_NE(message.find("study file"), std::string::npos) << c.toml;
        EXPECT_NE(message.find(c.expected), std::string::npos) << "expected '" << c.expected << "' in: " << message;
    }
    if (engine_available("ode")) {
        const std::string message = refusal(dir, "engines = [\"ode\"]\n[settings.ode]\nerpp = 0.3\n" + wall + threshold);
        EXPECT_NE(message.find("unknown ODE setting 'erpp'"), std::string::npos) << message;
    }
}

// The grid -----------------------------------------------------------------------------------------------------

TEST(StudyGrid, CaseIdsArePositionsAndAParapetHasNoHingeToVary) {
    const TempDir dir;
    const Grid grid(study_of(dir, "[wall]\nmodel = [\"vssw\", \"parapet\"]\nheight = 4\nthickness = [0.2, 0.4]\n"
                                  "hinge = [0.5, 0.7]\n[excitation]\nkind = \"threshold\"\n"));
    EXPECT_EQ(grid.product_size(), 8u);
    // model x thickness x hinge, the hinge fastest: the parapet's second hinge level repeats its first.
    EXPECT_EQ(grid.case_ids(), (std::vector<int>{1, 2, 3, 4, 5, 7}));
    const study::CaseSpec c = grid.make_case(7);
    EXPECT_EQ(c.model, "parapet");
    EXPECT_DOUBLE_EQ(c.thickness, 0.4);
    EXPECT_TRUE(std::isnan(c.hinge));
    EXPECT_EQ(grid.varied_parameters(), (std::vector<std::string>{"model", "thickness", "hinge"}));
}

// one_at_a_time: a baseline (every such key at its first level) and one case per further level of each, crossed with
// the rest of the grid; ids stay positions in the whole product. A product would give 2 x 3 x 3 = 18 cases.
TEST(StudyGrid, KeysVariedOneAtATimeGiveABaselineAndOneCasePerFurtherLevel) {
    const TempDir dir;
    const Grid grid(study_of(dir, "one_at_a_time = [\"overburden_eccentricity\", \"xi\"]\n[wall]\nheight = 4\n"
                                  "thickness = [0.2, 0.4]\nhinge = 0.7\nxi = [0.1, 0.2, 0.3]\n"
                                  "overburden_eccentricity = [0, 0.5, 1]\n[excitation]\nkind = \"threshold\"\n"));
    EXPECT_EQ(grid.product_size(), 18u);
    ASSERT_EQ(grid.case_ids().size(), 10u);  // 2 thicknesses x (1 + 2 + 2)
    // Position (thickness, xi, e) = 9 t + 3 x + e, 1-based, in product order: each thickness's baseline, then e at its
    // further levels, then xi at its.
    EXPECT_EQ(grid.case_ids(), (std::vector<int>{1, 2, 3, 4, 7, 10, 11, 12, 13, 16}));
    const study::CaseSpec off_e = grid.make_case(12), off_xi = grid.make_case(16);
    EXPECT_EQ(std::make_tuple(off_e.thickness, off_e.xi, off_e.scene.overburden_eccentricity()),
              std::make_tuple(0.4, 0.1, 1.0));
    EXPECT_EQ(std::make_tuple(off_xi.thickness, off_xi.xi, off_xi.scene.overburden_eccentricity()),
              std::make_tuple(0.4, 0.3, 0.0));
    std::set<std::pair<double, double>> seen;
    for (int id : grid.case_ids()) {
        const study::CaseSpec c = grid.make_case(id);
        const double e = c.scene.overburden_eccentricity();
        EXPECT_TRUE(c.xi == 0.1 || e == 0.0) << "case " << id << " leaves the baseline in both keys";
        seen.insert({c.xi, e});
    }
    const std::set<std::pair<double, double>> expected = {{0.1, 0.0}, {0.2, 0.0}, {0.3, 0.0}, {0.1, 0.5}, {0.1, 1.0}};
    EXPECT_EQ(seen, expected);
}

// The pairs of a one-at-a-time study are its cases and their baseline: the parapet's threshold with N at the pivot's
// corner over N at the centre is Eq. (17e) over Eq. (17), 1 / (1 + xi) (xi = 0.5: -1/3), whatever else varies alone.
TEST(StudyMeasure, EffectsOfAOneAtATimeStudyPairEachCaseWithItsBaseline) {
    const TempDir dir;
    const Grid grid(study_of(dir, "metrics = [\"threshold_g\"]\none_at_a_time = [\"overburden_eccentricity\", "
                                  "\"density\"]\n[wall]\nmodel = \"parapet\"\nheight = 1.2\nthickness = 0.2\n"
                                  "xi = 0.5\ndensity = [1800, 2200]\noverburden_eccentricity = [0.0, 1.0]\n"
                                  "[excitation]\nkind = \"threshold\"\n"));
    (void)run_into(grid, dir / "out", 2);
    const study::StudyData d = study::read_study_data(dir / "out");
    const std::vector<study::Effect> effects = study::parameter_effects(d);
    const auto of = [&](const std::string& parameter) {
        const auto it = std::find_if(effects.begin(), effects.end(),
                                     [&](const study::Effect& e) { return e.parameter == parameter; });
        return it == effects.end() ? study::Effect{} : *it;
    };
    const study::Effect ecc = of("overburden_eccentricity"), density = of("density");
    EXPECT_TRUE(ecc.physical);
    EXPECT_FALSE(density.physical);
    EXPECT_EQ(ecc.pairs, 1);
    EXPECT_NEAR(ecc.median, 1.0 / 1.5 - 1.0, kThresholdBracket);
    EXPECT_EQ(density.pairs, 1);
    EXPECT_NEAR(density.median, 0.0, kThresholdBracket);  // the threshold does not depend on the density (Eq. 17)
    // Its tornado chart is of the paper's physical assumptions, and it is the only one: no model assumption varies.
    const study::StudyPlots plots = study::study_plot_scripts(d, effects);
    std::vector<std::string> tornadoes;
    for (const io::PlotScript& s : plots.scripts)
        if (s.plot.name.rfind("tornado", 0) == 0) tornadoes.push_back(s.plot.name + " in " + s.plot.section);
    EXPECT_EQ(tornadoes, (std::vector<std::string>{std::string("tornado_physical_threshold_g in ") +
                                                   study::kPhysicalTornadoSection}));
}

// Rocking curves per relaxation: a record study over alpha with N's position relaxed draws, per record, peak rotation
// against alpha with a line per level of the relaxation (the paper's first) in a panel per backend; the model's line
// at e/b 0 is the run at that level, point for point.
TEST(StudyPlotsRelaxed, ARelaxationsRockingCurvesHaveALinePerLevel) {
    const TempDir dir;
    const Grid grid(study_of(dir, "metrics = [\"peak_rotation\", \"overturned\"]\n[wall]\nmodel = \"parapet\"\n"
                                  "alpha = [0.15, 0.2]\nR = 1\nxi = 0.5\noverburden_eccentricity = [0.0, 1.0]\n"
                                  "[excitation]\nkind = \"record\"\nfile = \"" +
                                      std::string(VSSW_DATA_DIR) + "/elcentro_chopra.txt\"\npga = 0.3\n"));
    const ResultsTable t = run_into(grid, dir / "out", 2);
    const study::StudyData d = study::read_study_data(dir / "out");
    const study::StudyPlots plots = study::study_plot_scripts(d, study::parameter_effects(d));
    const auto it = std::find_if(plots.scripts.begin(), plots.scripts.end(), [](const io::PlotScript& s) {
        return s.plot.name == "relaxed_overburden_eccentricity_elcentro_chopra";
    });
    ASSERT_NE(it, plots.scripts.end());
    EXPECT_EQ(it->plot.section, study::kRelaxationSection);
    EXPECT_NE(it->dat.find("line 1: overburden_eccentricity 0 (the paper's)"), std::string::npos) << it->dat;
    EXPECT_NE(it->dat.find("line 2: overburden_eccentricity 1"), std::string::npos) << it->dat;
    // A standing run is drawn at its peak, unmarked (an overturned one at 1, marked).
    for (const char* alpha : {"0.15", "0.2"}) {
        const std::vector<std::pair<std::string, std::string>> run = {{"overburden_eccentricity", "0"}, {"alpha", alpha}};
        const bool fell = value_of(t, "overturned", run) == 1.0;
        const std::string point = fmt::format("{} {} {} ", alpha, fell ? "1" : io::gp_number(value_of(t, "peak_rotation", run)),
                                              fell ? 1 : 0);
        EXPECT_NE(it->dat.find(point), std::string::npos) << point << "\n" << it->dat;
    }
}

TEST(StudyGrid, ThePapersKinematicsWithAUnilateralRollerIsNotAModel) {
    const TempDir dir;
    const Grid grid(study_of(dir, "[wall]\nheight = 4\nthickness = 0.4\nhinge = 0.7\n[assumptions]\n"
                                  "kinematics = [\"paper\", \"exact\"]\nroller = [\"bilateral\", \"unilateral\"]\n"
                                  "[excitation]\nkind = \"threshold\"\n"));
    ASSERT_EQ(grid.runs().size(), 3u);
    for (const study::RunSpec& r : grid.runs())
        EXPECT_FALSE(r.kinematics == Kinematics::paper && r.roller == Roller::unilateral);
    ASSERT_EQ(grid.skipped_runs().size(), 1u);
    EXPECT_NE(grid.skipped_runs()[0].find("not a model"), std::string::npos);
}

// Under the set mechanism the roller is unilateral unless the file gives it: the paper's kinematics with it is no model,
// and the reason names the set that chose the roller (and how to choose another). A roller the file gives is its own.
TEST(StudyGrid, ThePapersKinematicsUnderTheSetMechanismNamesTheSetsRoller) {
    const TempDir dir;
    const std::string wall = "[wall]\nheight = 4\nthickness = 0.4\nhinge = 0.7\n[excitation]\nkind = \"threshold\"\n";
    const std::string by_set = refusal(dir, "[assumptions]\nkinematics = \"paper\"\n" + wall);
    EXPECT_NE(by_set.find("no run left: the paper's kinematics with the unilateral roller (the set mechanism's roller: "
                          "give roller = \"bilateral\" with kinematics = \"paper\", or set = \"paper\"): not a model"),
              std::string::npos)
        << by_set;
    const std::string given = refusal(dir, "[assumptions]\nkinematics = \"paper\"\nroller = \"unilateral\"\n" + wall);
    EXPECT_NE(given.find("no run left: the paper's kinematics with the unilateral roller: not a model"),
              std::string::npos)
        << given;
    EXPECT_EQ(refusal(dir, "[assumptions]\nset = \"paper\"\n" + wall), "") << "the set paper's roller is bilateral";
}

TEST(StudyGrid, WallsGivenBySlendernessAndSizeAreTheWallsOfThatShape) {
    const TempDir dir;
    const Grid grid(study_of(dir, "[wall]\nalpha = 0.1\nR = 2.5\nhinge = 0.6\n[excitation]\nkind = \"threshold\"\n"));
    const study::CaseSpec c = grid.make_case(1);
    EXPECT_NEAR(c.alpha, 0.1, kRoundoff);
    EXPECT_NEAR(c.R, 2.5, kRoundoff);
    EXPECT_NEAR(std::atan(c.thickness / c.height), 0.1, kRoundoff);
    EXPECT_NEAR(c.scene.vssw->hinge_ratio(), 0.6, kRoundoff);
}

// What a run measures: simulations --------------------------------------------------------------------------------

// The threshold found by bisection on the analytic model is Eq. (12), and it does not depend on the wall's size.
TEST(StudyMeasure, ThresholdIsEq12AndDoesNotDependOnSize) {
    const TempDir dir;
    const Grid grid(study_of(dir, "metrics = [\"threshold_g\", \"threshold_closed_form_g\"]\n[wall]\nalpha = 0.1\n"
                                  "R = [0.5, 2.0, 8.0]\nhinge = 0.6\nxi = 0.1\n[excitation]\nkind = \"threshold\"\n"));
    const ResultsTable t = run_into(grid, dir / "out", 2);
    const double eq12 = value_of(t, "threshold_closed_form_g", {{"R", "0.5"}});
    for (const char* R : {"0.5", "2", "8"}) {
        EXPECT_NEAR(value_of(t, "threshold_closed_form_g", {{"R", R}}), eq12, kRoundoff * eq12);
        EXPECT_NEAR(value_of(t, "threshold_g", {{"R", R}}) / eq12 - 1.0, 0.0, kThresholdBracket) << "R " << R;
    }
}

// N's position as a wall axis: each case's wall has it, and the threshold is Eq. (17e)'s lower direction; N over the
// parapet's pivot (e/b = 1) leaves Housner's g b / h, a third below the centred N's at xi 0.5.
TEST(StudyMeasure, OverburdenEccentricityIsAWallAxis) {
    const TempDir dir;
    const Grid grid(study_of(dir, "metrics = [\"threshold_g\"]\n[wall]\nmodel = \"parapet\"\nheight = 1.2\n"
                                  "thickness = 0.2\nxi = 0.5\noverburden_eccentricity = [0.0, 1.0]\n"
                                  "[excitation]\nkind = \"threshold\"\n"));
    const ResultsTable t = run_into(grid, dir / "out", 2);
    const double b_over_h = 0.2 / 1.2;
    EXPECT_NEAR(value_of(t, "threshold_g", {{"overburden_eccentricity", "0"}}) / (1.5 * b_over_h) - 1.0, 0.0,
                kThresholdBracket);
    EXPECT_NEAR(value_of(t, "threshold_g", {{"overburden_eccentricity", "1"}}) / b_over_h - 1.0, 0.0,
                kThresholdBracket);
}

// diaphragm_period is a wall axis: T_d = 0 is the rigid top's row; T_d > 0 under a pulse is a failed row of the analytic
// model naming the reason (it cannot follow the moving top: docs/model/top-support.md), never a silent rigid run.
TEST(StudyMeasure, DiaphragmPeriodIsAWallAxis) {
    const TempDir dir;
    const Grid grid(study_of(dir, "metrics = [\"peak_rotation\"]\n[wall]\nheight = 4\nthickness = 0.4\nhinge = 0.7\n"
                                  "diaphragm_period = [0.0, 0.2]\n[excitation]\nkind = \"pulse\"\nshape = \"sine\"\n"
                                  "amplitude = 0.3\npulse_period = 0.5\n"));
    const ResultsTable t = run_into(grid, dir / "out");
    const std::size_t period = t.column("diaphragm_period"), status = t.column("status");
    ASSERT_EQ(t.rows.size(), 2u);
    for (const auto& row : t.rows) {
        if (row[period] == "0") EXPECT_EQ(row[status], "ok");
        else EXPECT_NE(row[status].find("cannot follow a flexible diaphragm"), std::string::npos) << row[status];
    }
    EXPECT_GT(value_of(t, "peak_rotation", {{"diaphragm_period", "0"}}), 0.0);
}

// A parapet has no top support: a diaphragm period for it is refused.
TEST(StudyMeasure, DiaphragmOnAParapetIsRefused) {
    const TempDir dir;
    EXPECT_THROW(Grid(study_of(dir, "metrics = [\"threshold_g\"]\n[wall]\nmodel = \"parapet\"\nheight = 1.2\n"
                                    "thickness = 0.2\ndiaphragm_period = 0.2\n[excitation]\nkind = \"threshold\"\n")),
                 InputError);
}

// threshold_ratio_to_parapet divides the VSSW's threshold by that of the parapet of its size with N at the same e/b and
// the same rounded corners, as `vssw wall` does (Eq. 12r / 17r); before, by the sharp centred Eq. (17): 37 % low at
// e/b 0.5, r/b 0.2. By hand, masses per unit depth over 4 b rho_m (m_i ~ h_i): h 2, h1 1.4, h2 0.6, k = 7/3, m1 + m2
// = 2, N = 1 (xi 0.5), the lower sides: VSSW/g = (b/h1) [(1 - r)(m1 + m2 (2 + k) + N (2 + k)) - N k |e|] / 2,
// parapet/g = (b/h) [(1 - r)(1 + xi) - xi |e|].
TEST(StudyMeasure, ThresholdRatioToParapetIsOfTheSameSizedParapetWithNAndCornersAsTheWall) {
    const TempDir dir;
    const Grid grid(study_of(dir, "metrics = [\"threshold_ratio_to_parapet\"]\n[wall]\nheight = 4\nthickness = 0.4\n"
                                  "hinge = 0.7\nxi = 0.5\noverburden_eccentricity = [0.0, 0.5]\n"
                                  "corner_radius = [0.0, 0.2]\n[excitation]\nkind = \"closed-form\"\ntheta0 = 0.5\n"));
    const ResultsTable t = run_into(grid, dir / "out");
    const double h = 2.0, h1 = 1.4, k = 1.4 / 0.6, xi = 0.5;
    for (const char* e : {"0", "0.5"})
        for (const char* r : {"0", "0.2"}) {
            const double eps = std::stod(e), rho = std::stod(r);
            const double vssw = ((1.0 - rho) * (1.4 + 0.6 * (2.0 + k) + 1.0 * (2.0 + k)) - k * eps) / (2.0 * h1);
            const double parapet = ((1.0 - rho) * (1.0 + xi) - xi * eps) / h;
            EXPECT_NEAR(value_of(t, "threshold_ratio_to_parapet", {{"overburden_eccentricity", e}, {"corner_radius", r}}),
                        vssw / parapet, kRoundoff * vssw / parapet)
                << "e/b " << e << ", r/b " << r;
        }
}

// A wall N tips over at rest (N outside the rounded pivot's flat, Eq. 17r <= 0 past |e/b| 0.875 here:
// RoundedCorners.NOutsideTheRoundedPivotThatTipsTheWallAtRestIsRefused) is refused with the study, naming the values;
// before, its negative threshold was recorded as an ok row.
TEST(StudyMeasure, AWallThatCannotStandIsRefused) {
    const TempDir dir;
    try {
        (void)Grid(study_of(dir, "metrics = [\"threshold_g\"]\n[wall]\nmodel = \"parapet\"\nheight = 1.2\n"
                                 "thickness = 0.2\nxi = 4\noverburden_eccentricity = [0.0, 1.0]\ncorner_radius = 0.3\n"
                                 "[excitation]\nkind = \"threshold\"\n"));
        ADD_FAILURE() << "not refused";
    } catch (const InputError& e) {
        for (const char* word : {"cannot stand", "e/b 1", "xi 4", "r/b 0.3"})
            EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
    }
}

// corner_radius is a wall axis: an engine that rounds its blocks lifts the parapet at Eq. (17r), (1 - r/b) times the
// sharp threshold (1 + xi) b/h; at r/b 0.2 the sharp value would be 25 % off, and r/b 0 must give it.
TEST(StudyMeasure, CornerRadiusIsAWallAxis) {
    if (!vssw::testing::engine_available("box2d")) GTEST_SKIP() << "no Box2D in this build";
    constexpr double kEngineThreshold = compare::kThresholdTarget;  // the project's target for an engine's threshold
    const TempDir dir;
    const Grid grid(study_of(dir, "metrics = [\"threshold_g\"]\nengines = [\"box2d\"]\n[wall]\nmodel = \"parapet\"\n"
                                  "height = 1.2\nthickness = 0.2\nxi = 0.5\ncorner_radius = [0.0, 0.2]\n"
                                  "[excitation]\nkind = \"threshold\"\n"));
    const ResultsTable t = run_into(grid, dir / "out", 2);
    const double sharp = 1.5 * 0.2 / 1.2;
    EXPECT_NEAR(value_of(t, "threshold_g", {{"corner_radius", "0"}}) / sharp - 1.0, 0.0, kEngineThreshold);
    EXPECT_NEAR(value_of(t, "threshold_g", {{"corner_radius", "0.2"}}) / (0.8 * sharp) - 1.0, 0.0, kEngineThreshold);
}

// Friction as a wall axis: each case's scene has it, and the analytic model reports the friction it needs, the same at
// every level, as is its motion (the model cannot slide).
TEST(StudyMeasure, FrictionIsAWallAxis) {
    const TempDir dir;
    const Grid grid(study_of(dir, "metrics = [\"base_friction_needed\", \"peak_rotation\"]\nengines = [\"analytic\"]\n"
                                  "[wall]\nspecimen = 2\nfriction = [0.1, 0.3]\n[excitation]\nkind = \"pulse\"\n"
                                  "shape = \"sine\"\namplitude = 0.35\npulse_period = 0.5\n"));
    const ResultsTable t = run_into(grid, dir / "out", 2);
    const double low = value_of(t, "base_friction_needed", {{"friction", "0.1"}});
    EXPECT_GT(low, 0.1);  // 0.169 measured: the pulse asks more than 0.1 and less than 0.3 of the base
    EXPECT_LT(low, 0.3);
    EXPECT_EQ(value_of(t, "base_friction_needed", {{"friction", "0.3"}}), low);
    EXPECT_EQ(value_of(t, "peak_rotation", {{"friction", "0.3"}}), value_of(t, "peak_rotation", {{"friction", "0.1"}}));
}

// A wall that slides off its support neither stood nor overturned: a collapse search cannot go on from it and fails
// naming the slide, and the run's rocking metrics fail the same way (before, a slide-off read as "standing", and the
// search climbed on to max_pga); a free vibration's period names the slide, not "no impact within the run", and its
// warnings keep it. A 1.2 x 0.2 m parapet at mu 0.05 needs tan(alpha) = 0.167 not to slide: ODE slides off under
// Rinaldi at the first scale the search runs, where the model lifts off. The Table 1-like VSSW (4 x 0.4 m, h1/h 0.7)
// released at 0.9 alpha1 with mu 0.02 slides off at the hinge before its first impact.
TEST(StudyMeasure, AWallThatSlidOffFailsItsCollapseSearchAndRockingMetrics) {
    if (!vssw::testing::engine_available("ode")) GTEST_SKIP() << "no ODE in this build";
    const TempDir dir;
    const std::string record = std::string(VSSW_DATA_DIR) + "/NGA_no_1063_RRS228.AT2";
    const std::string parapet = "engines = [\"ode\"]\n[wall]\nmodel = \"parapet\"\nheight = 1.2\nthickness = 0.2\n"
                                "friction = 0.05\n[excitation]\n";
    const Grid collapse(study_of(dir, "metrics = [\"collapse_pga\"]\n" + parapet + "kind = \"scale-to-collapse\"\nfile = \"" +
                                          record + "\"\n", "collapse.toml"));
    const Grid record_run(study_of(dir, "metrics = [\"overturned\", \"peak_rotation\", \"base_slip\"]\n" + parapet +
                                            "kind = \"record\"\nfile = \"" + record + "\"\npga = 0.5\n", "record.toml"));
    const Grid free_run(study_of(dir, "metrics = [\"period\", \"hinge_slip\"]\nengines = [\"ode\"]\n[wall]\nheight = 4\n"
                                          "thickness = 0.4\nhinge = 0.7\nfriction = 0.02\n[excitation]\nkind = \"free\"\n"
                                          "theta0 = 0.9\n", "free.toml"));
    for (const auto& [grid, out] :
         {std::pair{&collapse, "collapse"}, std::pair{&record_run, "record"}, std::pair{&free_run, "free"}}) {
        const ResultsTable t = run_into(*grid, dir / out);
        const std::size_t metric = t.column("metric"), value = t.column("value"), status = t.column("status");
        for (const auto& row : t.rows) {
            if (row[metric] == "base_slip" || row[metric] == "hinge_slip") {  // measured: a whole b (kSlidOffLimit)
                EXPECT_GE(std::stod(row[value]), 1.0) << out;
                EXPECT_NE(row[t.column("warnings")].find("slid off its support"), std::string::npos) << out;
                continue;
            }
            EXPECT_TRUE(row[value].empty()) << row[metric];
            EXPECT_NE(row[status].find("slid off its support"), std::string::npos) << row[metric] << ": " << row[status];
        }
    }
}

// A free vibration's restitution is the run's impact law (Eq. 19, the whole mechanism's) and its period the model's.
TEST(StudyMeasure, FreeVibrationGivesTheModelsImpactLawAndPeriod) {
    const TempDir dir;
    const Grid grid(study_of(dir, "metrics = [\"period\", \"restitution\", \"peak_rotation\"]\n[wall]\nheight = 4\n"
                                  "thickness = 0.4\nhinge = 0.7\n[assumptions]\nkinematics = \"exact\"\n"
                                  "impact = [\"eq19\", \"whole-mechanism\", 0.8]\n[excitation]\nkind = \"free\"\n"
                                  "theta0 = 0.5\n"));
    const ResultsTable t = run_into(grid, dir / "out");
    const VsswGeometry w = make_vssw(4.0, 0.4, 0.7);
    EXPECT_NEAR(value_of(t, "restitution", {{"impact", "eq19"}}), eq19_restitution(w), kSampledRatio);
    EXPECT_NEAR(value_of(t, "restitution", {{"impact", "whole-mechanism"}}), restitution_whole_mechanism(w),
                kSampledRatio);
    EXPECT_NEAR(value_of(t, "restitution", {{"impact", "0.8"}}), 0.8, kSampledRatio);
    const auto model = make_vssw_model(w, Kinematics::exact);
    SimulationOptions o;
    o.keep_samples = false;
    const SimulationResult run = free_vibration(*model, 0.5 * w.alpha1, o);
    ASSERT_FALSE(run.impacts.empty());
    EXPECT_NEAR(value_of(t, "period", {{"impact", "eq19"}}) / (4.0 * run.impacts.front().t) - 1.0, 0.0, kSampledRatio);
    EXPECT_DOUBLE_EQ(value_of(t, "peak_rotation", {{"impact", "eq19"}}), 0.5) << "the release is the largest rotation";
}

// Under a record, the study's analytic peak is the model's own (the same run `vssw history` makes): the set paper with
// the exact kinematics, so Eq. (19) and the bilateral roller, as the simulation's defaults below.
TEST(StudyMeasure, RecordPeakIsTheModelsRunDirectly) {
    const TempDir dir;
    const std::string record = std::string(VSSW_DATA_DIR) + "/NGA_no_1063_RRS228.AT2";
    const Grid grid(study_of(dir, "metrics = [\"peak_rotation\", \"overturned\", \"energy_balance_error\"]\n"
                                  "[wall]\nheight = 3.05\nthickness = 0.143\nhinge = 0.6\nxi = 0.1\n"
                                  "[assumptions]\nset = \"paper\"\nkinematics = \"exact\"\n[excitation]\nkind = "
                                  "\"record\"\nfile = \"" + record + "\"\nscale = 0.25\n"));
    const ResultsTable t = run_into(grid, dir / "out");
    const VsswGeometry w = make_vssw(3.05, 0.143, 0.6, 0.1);
    const GroundMotion motion = read_record(record).scaled(0.25);  // rocks through the whole record (docs/measurements/speed.md)
    SimulationOptions o;
    o.keep_samples = false;
    o.t_end = motion.duration() + compare::kResponseTail;
    const SimulationResult run =
        simulate(*make_vssw_model(w, Kinematics::exact), motion, GroundMotion::none(), {}, o);
    ASSERT_FALSE(run.overturned);
    EXPECT_NEAR(value_of(t, "peak_rotation", {}), run.max_abs_theta / w.alpha1, kRoundoff);
    EXPECT_EQ(value_of(t, "overturned", {}), 0.0);
    EXPECT_LT(value_of(t, "energy_balance_error", {}), SimulationOptions{}.energy_ceiling);
}

// A run that fails is rows with the reason, and the study goes on: a loose integrator tolerance (rtol 1e-2) on a wall
// under a heavy overburden (h1/h 0.5, xi 2, from 0.5 alpha1) misses its energy ceiling 1e-6 by 70x, while the default
// tolerance gives values.
TEST(StudyMeasure, AFailingRunIsARowWithItsReason) {
    const TempDir dir;
    const Grid grid(study_of(dir, "metrics = [\"period\", \"peak_rotation\"]\n[wall]\nheight = 4\n"
                                  "thickness = 0.4\nhinge = 0.5\nxi = 2\n[assumptions]\nkinematics = \"exact\"\n"
                                  "[settings.analytic]\nrtol = [1e-10, 1e-2]\n[excitation]\nkind = \"free\"\n"
                                  "theta0 = 0.5\n"));
    const ResultsTable t = run_into(grid, dir / "out");
    ASSERT_EQ(t.rows.size(), 4u);
    const std::size_t status = t.column("status"), settings = t.column("settings");
    for (const auto& row : t.rows) {
        if (row[settings].find("rtol=0.01") == std::string::npos) {
            EXPECT_EQ(row[status], "ok") << row[settings];
        } else {
            EXPECT_EQ(row[status].rfind("failed: ", 0), 0u);
            EXPECT_NE(row[status].find("energy balance"), std::string::npos) << row[status];
        }
    }
}

// The machinery ----------------------------------------------------------------------------------------------------

const char* const kSmallStudy = R"(
metrics = ["period", "restitution", "peak_rotation"]  # thresholds are slow and tested on their own
[wall]
height = [3.05, 4.0]
thickness = 0.3
hinge = [0.55, 0.7]
xi = [0.0, 0.2]
[assumptions]
kinematics = ["paper", "exact"]
impact = ["eq19", "whole-mechanism"]
[excitation]
kind = "free"
theta0 = [0.3, 0.6]
)";

TEST(StudyRun, ThreadsShardsAndMergeGiveTheSameRows) {
    const TempDir dir;
    const Grid grid(study_of(dir, kSmallStudy));
    run_into(grid, dir / "one", 1);
    run_into(grid, dir / "two", 2);
    const std::string one = vssw::testing::read_file(dir / "one" / "results.csv");
    EXPECT_EQ(one, vssw::testing::read_file(dir / "two" / "results.csv"));
    std::vector<std::filesystem::path> shards;
    for (int k = 1; k <= 3; ++k) {
        shards.push_back(dir / ("shard" + std::to_string(k)));
        run_into(grid, shards.back(), 1, {k, 3});
    }
    std::reverse(shards.begin(), shards.end());  // the order the folders are named in does not matter
    const study::MergeResult merged = study::merge_studies(shards, dir / "merged");
    EXPECT_EQ(merged.shards, 3);
    EXPECT_EQ(one, vssw::testing::read_file(dir / "merged" / "results.csv"));
    EXPECT_EQ(merged.rows, static_cast<long>(std::count(one.begin(), one.end(), '\n')) - 1);
}

TEST(StudyRun, MergeRefusesShardsThatAreNotOneStudy) {
    const TempDir dir;
    const Grid grid(study_of(dir, kSmallStudy));
    run_into(grid, dir / "a1", 1, {1, 2});
    run_into(grid, dir / "a2", 1, {2, 2});
    const Grid other(study_of(dir, std::string(kSmallStudy) + "\n[settings.analytic]\nrtol = 1e-9\n", "other.toml"));
    run_into(other, dir / "b2", 1, {2, 2});
    const auto refusal_of = [&](std::vector<std::filesystem::path> dirs) {
        try {
            study::merge_studies(dirs, dir / "merged");
            return std::string();
        } catch (const InputError& e) {
            return std::string(e.what());
        }
    };
    EXPECT_NE(refusal_of({dir / "a1"}).find("shard 2 of 2 missing"), std::string::npos);
    EXPECT_NE(refusal_of({dir / "a1", dir / "a1"}).find("given twice"), std::string::npos);
    EXPECT_NE(refusal_of({dir / "a1", dir / "b2"}).find("another study"), std::string::npos);
    EXPECT_FALSE(std::filesystem::exists(dir / "merged" / "results.csv"));
    // Into one of its own shards: the merged files would replace the shard's (they once did, exit 0).
    ASSERT_TRUE(std::filesystem::exists(dir / "a1" / "results.csv"));
    const std::string a1_before = vssw::testing::read_file(dir / "a1" / "results.csv");
    try {
        study::merge_studies({dir / "a1", dir / "a2"}, dir / "a2" / ".." / "a1");
        ADD_FAILURE() << "merged into a shard";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("is the shard folder"), std::string::npos) << e.what();
    }
    EXPECT_EQ(vssw::testing::read_file(dir / "a1" / "results.csv"), a1_before);
}

// A damaged shard is refused, naming it and the counts: cut short, a row given twice, a value edited (each merged
// with exit 0 once). Its manifest records the rows and a hash of results.csv.
TEST(StudyRun, MergeRefusesDamagedShards) {
    const TempDir dir;
    const Grid grid(study_of(dir, kSmallStudy));
    run_into(grid, dir / "a1", 1, {1, 2});
    run_into(grid, dir / "a2", 1, {2, 2});
    const std::string whole = vssw::testing::read_file(dir / "a2" / "results.csv");
    const auto lines = [](const std::string& text) {
        std::vector<std::string> out;
        std::istringstream in(text);
        for (std::string line; std::getline(in, line);) out.push_back(line + "\n");
        return out;
    };
    const std::vector<std::string> rows = lines(whole);
    ASSERT_GT(rows.size(), 4u);
    const long n = static_cast<long>(rows.size()) - 1;
    const auto damaged = [&](const std::string& text) {
        std::ofstream(dir / "a2" / "results.csv", std::ios::binary | std::ios::trunc) << text;
        try {
            study::merge_studies({dir / "a1", dir / "a2"}, dir / "merged");
            return std::string();
        } catch (const InputError& e) {
            return std::string(e.what());
        }
    };
    const std::string shard = (dir / "a2" / "results.csv").string();
    std::string cut;
    for (std::size_t i = 0; i + 1 < rows.size(); ++i) cut += rows[i];  // the last row lost
    std::string e = damaged(cut);
    EXPECT_NE(e.find(shard + "' holds " + std::to_string(n - 1) + " rows, its manifest.json records " +
                     std::to_string(n)),
              std::string::npos)
        << e;
    std::string twice = whole;
    twice.insert(twice.find(rows[2]), rows[2]);
    e = damaged(twice);
    EXPECT_NE(e.find(shard + "' repeats a row at line 4"), std::string::npos) << e;
    std::string edited = whole;
    const std::size_t at = edited.find(",ok,");
    ASSERT_NE(at, std::string::npos);
    const std::size_t unit = edited.rfind(',', at - 1);      // ...,metric,value,unit,ok,...
    const std::size_t digit = edited.rfind(',', unit - 1) + 1;  // the value's first digit
    edited[digit] = edited[digit] == '1' ? '2' : '1';
    e = damaged(edited);
    EXPECT_NE(e.find(shard + "' is not the results.csv its manifest records"), std::string::npos) << e;
    EXPECT_FALSE(std::filesystem::exists(dir / "merged" / "manifest.json"));
    EXPECT_EQ(damaged(whole), "") << "the shard as written merges";
}

// One process at a time in a study folder: a second run or a --resume while the first holds the folder is refused,
// naming the first (two --resume runs once interleaved their appends and corrupted the journal for good).
TEST(StudyRun, ASecondRunInAFolderInUseIsRefusedNamingTheFirst) {
    const TempDir dir;
    const Grid grid(study_of(dir, kSmallStudy));
    study::StudyRunOptions o;
    const io::FolderLock held = study::prepare_study_dir(grid, dir / "s", o);
    study::StudyRunOptions resume;
    resume.resume = true;
    for (const study::StudyRunOptions& second : {o, resume}) {
        try {
            (void)study::prepare_study_dir(grid, dir / "s", second);
            ADD_FAILURE() << "a second run was let in";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("in use by another vssw command (process " + std::to_string(getpid())),
                      std::string::npos)
                << e.what();
        }
    }
}

// An interrupted study leaves its journal; --resume runs only the missing tasks (a task cut off mid-write again) and
// ends with the rows of an uninterrupted run.
TEST(StudyRun, AnInterruptedStudyResumesWhereItStopped) {
    const TempDir dir;
    const Grid grid(study_of(dir, kSmallStudy));
    run_into(grid, dir / "whole", 2);

    struct Interrupt : std::runtime_error {
        using std::runtime_error::runtime_error;
    };
    constexpr long kStopAfter = 10;
    study::StudyRunOptions o;
    o.threads = 1;
    o.progress = [&](long done, long, const std::string&) {
        if (done == kStopAfter) throw Interrupt("stopped");
    };
    study::prepare_study_dir(grid, dir / "cut", o);
    EXPECT_THROW(study::run_study(grid, dir / "cut", o), Interrupt);
    ASSERT_TRUE(std::filesystem::exists(dir / "cut" / "journal.csv"));
    std::ofstream(dir / "cut" / "journal.csv", std::ios::app) << "3,1,0,0.5,ok,\n3,1,1,0.";  // a task cut off

    study::StudyRunOptions plain;
    EXPECT_THROW(study::prepare_study_dir(grid, dir / "cut", plain), InputError) << "without --resume: refused";
    study::StudyRunOptions resume;
    resume.resume = true;
    study::prepare_study_dir(grid, dir / "cut", resume);
    const study::StudyRunResult r = study::run_study(grid, dir / "cut", resume);
    EXPECT_EQ(r.meta.tasks_resumed, kStopAfter);
    EXPECT_EQ(vssw::testing::read_file(dir / "whole" / "results.csv"), vssw::testing::read_file(dir / "cut" / "results.csv"));
    EXPECT_FALSE(std::filesystem::exists(dir / "cut" / "journal.csv"));

    const Grid other(study_of(dir, std::string(kSmallStudy) + "\n[settings.analytic]\nrtol = 1e-9\n", "other.toml"));
    std::ofstream(dir / "cut" / "journal.csv") << "#vssw-study-journal," << grid.identity() << ",1/1\n";
    std::set<study::TaskKey> done;
    EXPECT_THROW(study::Journal(dir / "cut" / "journal.csv", other.identity(), {}, done), InputError)
        << "a journal of another study is not continued";
    // A journal whose own first line was cut short is refused by name, not continued past its end; whole, it is.
    std::ofstream(dir / "cut" / "journal.csv") << "#vssw-study-journal," << grid.identity() << ",1/1";
    try {
        study::Journal(dir / "cut" / "journal.csv", grid.identity(), {}, done);
        ADD_FAILURE() << "a journal without its first line's end was continued";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("its first line is cut short"), std::string::npos) << e.what();
    }
    std::ofstream(dir / "cut" / "journal.csv") << "#vssw-study-journal," << grid.identity() << ",1/1\n";
    EXPECT_NO_THROW(study::Journal(dir / "cut" / "journal.csv", grid.identity(), {}, done));
}

}  // namespace

// Suite files -------------------------------------------------------------------------------------------------------
// (The shipped suites, studies/validation-*.toml, are read by the suite's own tests, tests/test_suite.cpp, and were
// checked against the suites the code built before they became data: the same walls, records and cases, 46 and 233.)

namespace {

const char* const kSuite = R"(
name = "mine"
engines = ["analytic", "ode"]
[[part]]
wall_name = "w{thickness}"
wall_label = "a wall {thickness:.2f} m thick"
[part.wall]
height = 4.0
thickness = [0.3, 0.4]
hinge = 0.7
[part.excitation]
kind = "threshold"
[[part]]
wall_name = "t1-01-xi{xi}"
skip_falling_releases = true
[part.wall]
specimen = 1
xi = 0.5
[part.excitation]
kind = "free"
theta0 = [0.5, 0.8]
[[part]]
wall_name = "w{thickness}"
[part.wall]
height = 4.0
thickness = 0.4
hinge = 0.7
[part.excitation]
kind = "free"
theta0 = 0.5
[part.settings.ode]
dt = [1e-3, 5e-4]
)";

TEST(SuiteFile, AUsersSuiteFollowsTheSuitesIdConventions) {
    const TempDir dir;
    const validation::Suite s = validation::suite_from_study(Grid(study_of(dir, kSuite)), "mine");
    std::vector<std::string> ids;
    for (const validation::SuiteCase& c : s.cases) ids.push_back(c.id);
    // Table 1 #1 at xi 0.5 falls from 0.8 alpha1 (its unstable equilibrium is lower): that release is left out.
    EXPECT_EQ(ids, (std::vector<std::string>{"w0.3", "w0.4", "t1-01-xi0.5/r0.5", "w0.4/r0.5/dt0.001/ode",
                                             "w0.4/r0.5/dt0.0005/ode"}));
    ASSERT_EQ(s.walls.size(), 3u);
    EXPECT_EQ(s.walls[0].label, "a wall 0.30 m thick");
    EXPECT_EQ(s.step_study.at("ode"), (std::vector<double>{1e-3, 5e-4}));
}

// response_tail: a part's [excitation] key for a study's runs and a suite's history cases; without it each keeps its
// own default (compare/experiments.hpp), and the shipped files give none. A negative tail is refused, naming it.
TEST(SuiteFile, ResponseTailIsAKeyOfTheStudyAndTheSuite) {
    const TempDir dir;
    const std::string record = std::string(VSSW_DATA_DIR) + "/NGA_no_1063_RRS228.AT2";
    const auto part = [&](const std::string& tail) {
        return "[[part]]\nwall_name = \"w\"\nrecord_name = \"r\"\n[part.wall]\nheight = 4.0\nthickness = 0.4\n"
               "hinge = 0.7\n[part.excitation]\nkind = \"record\"\nfile = \"" + record + "\"\nscale = 0.3\n" + tail;
    };
    const Grid given(study_of(dir, part("response_tail = 2.5\n")));
    EXPECT_EQ(given.make_case(given.case_ids().front()).response_tail, 2.5);
    EXPECT_EQ(validation::suite_from_study(given, "x").cases.front().response_tail, 2.5);
    const Grid plain(study_of(dir, part("")));
    EXPECT_EQ(plain.make_case(plain.case_ids().front()).response_tail, compare::kResponseTail);
    EXPECT_EQ(validation::suite_from_study(plain, "x").cases.front().response_tail, compare::kSuiteResponseTail);
    try {
        (void)study_of(dir, part("response_tail = -1\n"));
        ADD_FAILURE() << "a negative response_tail was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("response_tail"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("-1"), std::string::npos) << e.what();
    }
}

TEST(SuiteFile, WhatASuiteCannotHoldIsNamed) {
    const TempDir dir;
    const auto refusal_of = [&](const std::string& toml) {
        try {
            (void)validation::suite_from_study(Grid(study_of(dir, toml)), "x");
            return std::string();
        } catch (const InputError& e) {
            return std::string(e.what());
        }
    };
    const std::string wall = "[part.wall]\nheight = 4.0\nthickness = 0.4\nhinge = 0.7\n";
    EXPECT_NE(refusal_of("[[part]]\n" + wall + "[part.excitation]\nkind = \"threshold\"\n").find("names its walls"),
              std::string::npos);
    EXPECT_NE(refusal_of("[[part]]\nwall_name = \"w\"\n" + wall +
                         "[part.excitation]\nkind = \"pulse\"\nshape = \"sine\"\namplitude = 0.3\npulse_period = 1\n")
                  .find("not kind pulse"),
              std::string::npos);
    EXPECT_NE(refusal_of("[[part]]\nwall_name = \"w\"\n[part.wall]\nheight = 4.0\nthickness = [0.3, 0.4]\nhinge = 0.7\n"
                         "[part.excitation]\nkind = \"threshold\"\n")
                  .find("given to two different walls"),
              std::string::npos);
    EXPECT_NE(refusal_of("[[part]]\nwall_name = \"w\"\n" + wall + "[part.excitation]\nkind = \"threshold\"\n[[part]]\n"
                         "wall_name = \"w\"\n" + wall + "[part.excitation]\nkind = \"threshold\"\n")
                  .find("the case id 'w' comes twice"),
              std::string::npos);
    EXPECT_NE(refusal_of("[[part]]\nwall_name = \"w{nothing}\"\n" + wall + "[part.excitation]\nkind = \"threshold\"\n")
                  .find("no value 'nothing'"),
              std::string::npos);
    // A study file of one grid and parts at once is refused when read.
    EXPECT_NE(refusal_of("[wall]\nheight = 4\nthickness = 0.4\nhinge = 0.7\n[excitation]\nkind = \"threshold\"\n[[part]]\n" +
                         wall + "[part.excitation]\nkind = \"threshold\"\n")
                  .find("not both"),
              std::string::npos);
}

// A study of several parts runs as one: each part's cases only with its own runs, ids after the previous part's.
TEST(SuiteFile, AStudyOfPartsRunsEachPartsCasesWithItsRuns) {
    const TempDir dir;
    const Grid grid(study_of(dir, kSuite));
    EXPECT_EQ(grid.case_ids(), (std::vector<int>{1, 2, 3, 5}));  // case 4, #1 released from 0.8 alpha1, falls
    const ResultsTable t = run_into(grid, dir / "out", 2);
    std::set<std::string> seen;
    for (const auto& row : t.rows)
        seen.insert(row[t.column("case_id")] + " " + row[t.column("engine")] + " " + row[t.column("settings")] + " " +
                    row[t.column("metric")] + " " + row[t.column("wall_name")]);
    EXPECT_TRUE(seen.count("1 analytic  threshold_g w0.3"));
    EXPECT_TRUE(seen.count("3 ode  period t1-01-xi0.5"));
    EXPECT_TRUE(seen.count("5 ode dt=0.001 period w0.4"));
    EXPECT_FALSE(seen.count("3 ode dt=0.001 period t1-01-xi0.5")) << "a part's settings are its own";
    EXPECT_FALSE(seen.count("1 analytic  period w0.3")) << "a threshold part measures no period";
}

}  // namespace

namespace {

// A closed form outside its range is a row with the reason; the other rows of the study stand.
TEST(StudyMeasure, AClosedFormOutsideItsRangeIsARowNotTheEnd) {
    const TempDir dir;
    const Grid grid(study_of(dir, "metrics = [\"period_ratio_to_parapet\"]\n[wall]\nheight = 4\nthickness = 0.4\n"
                                  "hinge = 0.7\n[excitation]\nkind = \"closed-form\"\ntheta0 = [0.5, 1.2]\n"));
    const ResultsTable t = run_into(grid, dir / "out");
    ASSERT_EQ(t.rows.size(), 2u);
    EXPECT_EQ(t.rows[0][t.column("status")], "ok");
    EXPECT_NE(t.rows[1][t.column("status")].find("failed: theta0 1.2 is not below"), std::string::npos)
        << t.rows[1][t.column("status")];
}

// A parapet's analytic run is the first one built, also when the first levels of kinematics and roller are not a
// model together (the paper's kinematics with a unilateral roller).
TEST(StudyGrid, AParapetKeepsItsAnalyticRunWhenTheFirstLevelsAreNotAModel) {
    const TempDir dir;
    const Grid grid(study_of(dir, "[wall]\nmodel = \"parapet\"\nheight = 2\nthickness = 0.2\n[assumptions]\n"
                                  "kinematics = [\"paper\", \"exact\"]\nroller = [\"unilateral\", \"bilateral\"]\n"
                                  "[excitation]\nkind = \"threshold\"\n"));
    const study::CaseSpec c = grid.make_case(1);
    int applying = 0;
    for (const study::RunSpec& r : grid.runs()) applying += grid.run_applies(r, c) ? 1 : 0;
    EXPECT_EQ(applying, 1);
}

// A record that is zero everywhere is bad input: it can be scaled to no PGA and shakes nothing.
TEST(StudyFile, ARecordOfZerosIsRefused) {
    const TempDir dir;
    vssw::testing::write_file(dir / "zeros.txt", "0 0\n0.01 0\n0.02 0\n");
    try {
        const Grid grid(study_of(dir, "[wall]\nheight = 4\nthickness = 0.4\nhinge = 0.7\n[excitation]\n"
                                      "kind = \"record\"\nfile = \"zeros.txt\"\npga = 0.3\n"));
        FAIL() << "refused";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("zero everywhere"), std::string::npos) << e.what();
    }
}

// ODE's quickstep reorders its rows with a process-wide random generator: a run must not depend on the runs before it
// (else a study's rows would depend on threads, shards and processes).
TEST(StudyRun, OdeQuickstepGivesTheSameRunWhateverRanBefore) {
    if (!engine_available("ode")) GTEST_SKIP() << "ODE is not built";
    const auto ode = multibody::make_engine("ode");
    multibody::EngineSettings s = ode->default_settings();
    s.knobs["quickstep"] = 1.0;
    const multibody::WallScene wall = multibody::WallScene::of(make_vssw(4.0, 0.4, 0.7));
    multibody::Excitation ex;
    ex.theta0 = 0.5 * wall.alpha();
    ex.t_end = 1.0;
    const multibody::Trajectory first = ode->simulate(wall, ex, s);
    multibody::Excitation other = ex;
    other.theta0 = 0.3 * wall.alpha();
    (void)ode->simulate(wall, other, s);
    const multibody::Trajectory again = ode->simulate(wall, ex, s);
    ASSERT_EQ(first.samples.size(), again.samples.size());
    EXPECT_EQ(first.samples.back().theta1, again.samples.back().theta1);
}

// Suite files read their records in the files' own units: a part that says otherwise is refused.
TEST(SuiteFile, UnitsAreRefused) {
    const TempDir dir;
    const std::string record = std::string(VSSW_DATA_DIR) + "/elcentro_chopra.txt";
    try {
        (void)validation::suite_from_study(Grid(study_of(dir, "[[part]]\nwall_name = \"w\"\nrecord_name = \"r\"\n"
                                                         "[part.wall]\nheight = 4\nthickness = 0.4\nhinge = 0.7\n"
                                                         "[part.excitation]\nkind = \"record\"\nfile = \"" +
                                                             record + "\"\nunits = \"g\"\n")),
                                      "x");
        FAIL() << "refused";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("no 'units'"), std::string::npos) << e.what();
    }
}

}  // namespace

namespace {

// threshold_g belongs to the wall: one task per wall and run, its value given to every case of the wall (here the two
// releases of each), the same in a single run and in shards merged.
TEST(StudyRun, AThresholdIsATaskOfItsWallGivenToEveryCaseOfIt) {
    const TempDir dir;
    const Grid grid(study_of(dir, "metrics = [\"threshold_g\", \"period\"]\n[wall]\nheight = 4\n"
                                  "thickness = [0.3, 0.4]\nhinge = 0.7\n[excitation]\nkind = \"free\"\n"
                                  "theta0 = [0.3, 0.6]\n"));
    study::StudyRunOptions o;
    o.threads = 2;
    study::prepare_study_dir(grid, dir / "one", o);
    const study::StudyRunResult r = study::run_study(grid, dir / "one", o);
    EXPECT_EQ(r.meta.tasks_run, 4 + 2) << "four cases and two walls' thresholds";
    const ResultsTable t = study::read_results_csv(dir / "one" / "results.csv");
    for (const char* thickness : {"0.3", "0.4"}) {
        const double a = value_of(t, "threshold_g", {{"thickness", thickness}, {"theta0", "0.3"}});
        EXPECT_EQ(a, value_of(t, "threshold_g", {{"thickness", thickness}, {"theta0", "0.6"}}));
        EXPECT_TRUE(std::isfinite(a));
    }
    run_into(grid, dir / "s1", 1, {1, 2});
    run_into(grid, dir / "s2", 1, {2, 2});
    (void)study::merge_studies({dir / "s1", dir / "s2"}, dir / "merged");
    EXPECT_EQ(vssw::testing::read_file(dir / "one" / "results.csv"),
              vssw::testing::read_file(dir / "merged" / "results.csv"));
}

}  // namespace

// Found by a bad-input sweep ------------------------------------------------------------------------------------------

namespace {

// A TOML list of n distinct numbers from `first` in steps of `step`.
std::string number_list(std::size_t n, double first, double step) {
    std::string text = "[";
    for (std::size_t i = 0; i < n; ++i) text += fmt::format("{}{}", i ? ", " : "", first + static_cast<double>(i) * step);
    return text + "]";
}

// A run's data is built from the rows as it writes results.csv, not read back from it: it is the data read back, to the
// byte of results.json, on a study with a word level (Eq. 15's hinge), derived columns (walls given by alpha and R)
// and a part whose columns do not apply to the other's.
TEST(StudyData, TheRowsAsWrittenAreTheRowsReadBack) {
    const TempDir dir;
    const Grid grid(study_of(dir, "metrics = [\"threshold_closed_form_g\", \"restitution_closed_form\"]\n"
                                  "[[part]]\n[part.wall]\nalpha = [0.15, 0.2]\nR = [1.0, 3.0]\nxi = [0.3, 0.5]\n"
                                  "hinge = [\"eq15\", 0.7]\n[part.excitation]\nkind = \"closed-form\"\n"
                                  "[[part]]\n[part.wall]\nmodel = \"parapet\"\nheight = [1.2, 1.5]\nthickness = 0.2\n"
                                  "[part.excitation]\nkind = \"closed-form\"\n"));
    const study::StudyRunResult run = vssw::testing::run_study_into(grid, dir / "out", 2);
    ASSERT_TRUE(run.data.has_value());
    const study::StudyData read = study::read_study_data(dir / "out");
    const auto json = [](const study::StudyData& d) {
        std::ostringstream out;
        study::write_results_json(out, d);
        return out.str();
    };
    const auto levels = [](const study::StudyData& d) {
        std::vector<std::vector<std::string>> texts;
        for (const study::StudyRow& r : d.rows) {
            texts.emplace_back();
            for (std::size_t c = 0; c < d.columns.size(); ++c) texts.back().push_back(d.text(r, c));
        }
        return texts;
    };
    EXPECT_EQ(read.rows.size(), 36u);
    EXPECT_EQ(json(*run.data), json(read));
    EXPECT_EQ(levels(*run.data), levels(read));
    EXPECT_EQ(run.data->manifest, read.manifest);
    // The comparison sees one row's value moved by one unit in the last place.
    study::StudyData moved = read;
    moved.rows[5].value = std::nextafter(moved.rows[5].value, 2.0);
    EXPECT_NE(json(moved), json(read));
}

}  // namespace

// Six lists whose product is 2^64 + 418: the unchecked product wrapped to a grid of 418 cases, which ran under --force.
TEST(StudyGrid, AGridWhoseSizeOverflowsIsRefusedBeforeAnythingIsBuilt) {
    const TempDir dir;
    const std::string toml = "metrics = [\"threshold_closed_form_g\"]\nengines = [\"analytic\"]\n[wall]\n"
                             "height = " + number_list(7621, 4.0, 1e-4) + "\nthickness = " +
                             number_list(5821, 0.4, 1e-5) + "\nhinge = " + number_list(1669, 0.5, 1e-4) +
                             "\nxi = " + number_list(853, 0.0, 1e-3) + "\ndensity = " + number_list(673, 1800.0, 1.0) +
                             "\ng = " + number_list(434, 9.81, 1e-3) +
                             "\n[excitation]\nkind = \"closed-form\"\ntheta0 = 0.5\n";
    const std::string message = refusal(dir, toml);
    EXPECT_NE(message.find("a grid of more than 2147483647 cases"), std::string::npos) << message;
}

// Eight keys of 16 levels varied one at a time are 1 + 8 x 15 = 121 cases, though their product, 16^8, is beyond
// ints: they were refused as a grid of more than 2^31 - 1 cases. Such a part numbers its cases 1 to 121, in product
// order: the baseline, then the last key (corner_radius, the last of kWallKeys) at its further levels, ..., the first
// (height) last.
TEST(StudyGrid, EightKeysOfSixteenLevelsOneAtATimeAre121Cases) {
    const TempDir dir;
    const Grid grid(study_of(dir, "metrics = [\"threshold_closed_form_g\"]\none_at_a_time = [\"height\", "
                                  "\"thickness\", \"hinge\", \"xi\", \"overburden_eccentricity\", \"density\", \"g\", "
                                  "\"corner_radius\"]\n[wall]\nheight = " + number_list(16, 3.0, 0.1) +
                                  "\nthickness = " + number_list(16, 0.3, 0.01) + "\nhinge = " +
                                  number_list(16, 0.6, 0.01) + "\nxi = " + number_list(16, 0.0, 0.02) +
                                  "\noverburden_eccentricity = " + number_list(16, 0.0, 0.05) + "\ndensity = " +
                                  number_list(16, 1600.0, 10.0) + "\ng = " + number_list(16, 9.7, 0.01) +
                                  "\ncorner_radius = " + number_list(16, 0.0, 0.005) +
                                  "\n[excitation]\nkind = \"closed-form\"\n"));
    std::vector<int> one_to_121(121);
    std::iota(one_to_121.begin(), one_to_121.end(), 1);
    EXPECT_EQ(grid.case_ids(), one_to_121);
    const auto levels = [&](int id) {  // as the file gives them, in kWallKeys order
        std::vector<double> out;
        for (const study::Level& l : grid.make_case(id).levels) out.push_back(std::get<double>(l));
        return out;
    };
    const std::vector<double> baseline = {3.0, 0.3, 0.6, 0.0, 0.0, 1600.0, 9.7, 0.0};
    EXPECT_EQ(levels(1), baseline);
    std::set<std::vector<double>> seen;
    std::set<std::size_t> walls;
    for (int id : grid.case_ids()) {
        const std::vector<double> l = levels(id);
        std::size_t off = 0;
        for (std::size_t k = 0; k < l.size(); ++k) off += l[k] != baseline[k];
        EXPECT_LE(off, 1u) << "case " << id << " leaves the baseline in two keys";
        seen.insert(l);
        walls.insert(grid.make_case(id).wall_index);
    }
    EXPECT_EQ(seen.size(), 121u);
    EXPECT_EQ(walls.size(), 121u);  // each case a wall of its own: none shares another's threshold
    std::vector<double> second = baseline, seventeenth = baseline, last = baseline;
    second[7] = 0.0 + 1 * 0.005;     // corner_radius's second level
    seventeenth[6] = 9.7 + 1 * 0.01;  // g's second level, after corner_radius's 15
    last[0] = 3.0 + 15 * 0.1;         // height's last
    EXPECT_EQ(levels(2), second);
    EXPECT_EQ(levels(17), seventeenth);
    EXPECT_EQ(levels(121), last);
}

// Duplicates were looked for pairwise: 400,000 values ran past 150 s. A list longer than the limit is refused at once;
// a long one within it is read in well under a second.
TEST(StudyFile, ListsLongerThanTheCapAreRefusedAndRepeatsFoundAtIt) {
    const TempDir dir;
    const std::string rest = "\nthickness = 0.4\nhinge = 0.6\n[excitation]\nkind = \"threshold\"\n";
    const std::string too_long = refusal(dir, "[wall]\nheight = " + number_list(100001, 1.0, 1e-6) + rest);
    EXPECT_NE(too_long.find("wall.height: a list of 100001 values, more than 100000"), std::string::npos) << too_long;

    std::string values = number_list(100000, 1.0, 1.0);
    values.replace(values.rfind(", ") + 2, std::string::npos, "51]");  // the last repeats the 51st
    // At the cap the repeat is still found, by sorting (a pairwise check took 6.5 s at 65,536 values; speed is
    // not timed here: a quadratic check at this size would show as a test taking seconds).
    const std::string repeated = refusal(dir, "[wall]\nheight = " + values + rest);
    EXPECT_NE(repeated.find("wall.height: lists 51 twice"), std::string::npos) << repeated;
}
