// Ensembles in study files (kind = "ensemble", study/spec.hpp): read into the record or scale-to-collapse study they
// stand for (the same ids and rows but for the kind), a folder's records listed in name order, every malformed key
// named, and the sensitivity band: the analytic model's perturbed repeats of each stripe case (PGA x (1 +- 1e-2),
// every impact's ratio x (1 +- 2e-2), the wall's size x (1 +- 1e-2)), which engines do not run.
#include <sys/stat.h>

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <iterator>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <utility>
#include <string>
#include <vector>

#include "analytic/error.hpp"
#include "analytic/ground_motion.hpp"
#include "analytic/intensity_measures.hpp"
#include "io/csv.hpp"
#include "study/ida_curves.hpp"
#include "study/merge.hpp"
#include "study/overturned_runs.hpp"
#include "study/outputs.hpp"
#include "study/results_files.hpp"
#include "analytic/model.hpp"
#include "analytic/wall.hpp"
#include "analytic/wall_scene.hpp"
#include "study/ensemble_measures.hpp"
#include "study/study_data.hpp"
#include "tests/engine_available.hpp"
#include "tests/study_fixtures.hpp"

namespace {

using namespace vssw;
using study::Grid;
using study::ResultsTable;
using vssw::testing::engine_available;
using vssw::testing::run_into;
using vssw::testing::study_of;
using vssw::testing::TempDir;
using vssw::testing::write_file;

// A PGA set by scaling the record (scale = level g / PGA, then PGA x scale / g) is the level to rounding: a few ulps.
constexpr double kScaledPga = 1e-14;
// Picks a level's rows out of a band: theirs are within 1e-2 (kBandIntensityStep) of it, the other levels' 50 % away.
constexpr double kNearLevel = 2e-2;

const std::string kRecords = std::string(VSSW_DATA_DIR) + "/records";
// Two of the shortest shipped records (20 s each), so that the runs stay quick.
const std::string kRinaldi = kRecords + "/northridge1994-rinaldi-228.at2";
const std::string kPacoimaDam = kRecords + "/northridge1994-pacoimadam-ew.at2";
const std::string kWall = "[wall]\nheight = 4\nthickness = 0.4\nhinge = 0.7\n";

std::string refusal(const TempDir& dir, const std::string& toml) {
    try {
        const Grid grid(study_of(dir, toml));
        return "";
    } catch (const InputError& e) {
        return e.what();
    }
}

// Every row of a results table with the `kind` column blanked.
std::vector<std::vector<std::string>> rows_but_kind(const ResultsTable& t) {
    std::vector<std::vector<std::string>> rows = t.rows;
    for (auto& row : rows) row[t.column("kind")] = "";
    return rows;
}

std::string file_list() { return "[\"" + kRinaldi + "\", \"" + kPacoimaDam + "\"]"; }

TEST(StudyEnsemble, StripesAreTheRecordStudysCasesAndRows) {
    const TempDir dir;
    const std::string head = "metrics = [\"peak_rotation\", \"overturned\"]\n" + kWall;
    const Grid ensemble(study_of(dir, head + "[excitation]\nkind = \"ensemble\"\nfiles = " + file_list() +
                                          "\nintensity = \"pga\"\nlevels = [0.35, 0.5, 0.7]\n",
                                 "ensemble.toml"));
    const Grid record(study_of(dir, head + "[excitation]\nkind = \"record\"\nfile = " + file_list() +
                                        "\npga = [0.35, 0.5, 0.7]\n",
                               "record.toml"));
    EXPECT_EQ(ensemble.spec().kind_text(), "ensemble");
    ASSERT_TRUE(ensemble.spec().parts[0].ensemble.has_value());
    EXPECT_FALSE(ensemble.spec().parts[0].ensemble->collapse);
    EXPECT_EQ(ensemble.spec().parts[0].kind, study::ExcitationKind::record);
    EXPECT_EQ(ensemble.case_ids(), record.case_ids());
    EXPECT_EQ(ensemble.case_ids().size(), 6u);
    EXPECT_EQ(ensemble.columns(), record.columns());
    const ResultsTable e = run_into(ensemble, dir / "ensemble", 2);
    const ResultsTable r = run_into(record, dir / "record", 2);
    EXPECT_EQ(e.rows.size(), 6u * 2u);  // cases x metrics, one run
    EXPECT_EQ(rows_but_kind(e), rows_but_kind(r));
    for (const auto& row : e.rows) EXPECT_EQ(row[e.column("kind")], "ensemble");
    // The rows say which record and level, as a record study's do.
    EXPECT_EQ(e.rows.front()[e.column("file")], kRinaldi);
    EXPECT_EQ(e.rows.front()[e.column("pga")], "0.35");
}

TEST(StudyEnsemble, CollapseIsTheScaleToCollapseStudysCasesAndRows) {
    const TempDir dir;
    const Grid ensemble(study_of(dir, kWall + "[excitation]\nkind = \"ensemble\"\nfiles = " + file_list() +
                                          "\nintensity = \"pga\"\ncollapse = true\nmax_pga = 3\n",
                                 "ensemble.toml"));
    const Grid collapse(study_of(dir, kWall + "[excitation]\nkind = \"scale-to-collapse\"\nfile = " + file_list() +
                                          "\nmax_pga = 3\n",
                                 "collapse.toml"));
    EXPECT_EQ(ensemble.spec().parts[0].kind, study::ExcitationKind::scale_to_collapse);
    EXPECT_TRUE(ensemble.spec().parts[0].ensemble->collapse);
    EXPECT_EQ(ensemble.spec().metrics, collapse.spec().metrics);  // collapse_scale, collapse_pga
    EXPECT_EQ(ensemble.case_ids(), collapse.case_ids());
    const ResultsTable e = run_into(ensemble, dir / "ensemble", 2);
    const ResultsTable c = run_into(collapse, dir / "collapse", 2);
    EXPECT_EQ(e.rows.size(), 2u * 2u);  // cases x (collapse_scale, collapse_pga)
    EXPECT_EQ(rows_but_kind(e), rows_but_kind(c));
}

// A folder's records: its *.at2 files in any case and what its records.csv lists, each once, in byte order of name;
// other files are not records.
TEST(StudyEnsemble, AFolderGivesItsRecordsInNameOrder) {
    const TempDir dir;
    const std::filesystem::path folder = dir / "set";
    std::filesystem::create_directories(folder);
    for (const char* name : {"b.at2", "A.AT2", "c.At2"}) std::filesystem::copy_file(kRinaldi, folder / name);
    write_file(folder / "d.txt", "0 0.1\n0.01 -0.2\n0.02 0.05\n");
    write_file(folder / "e.txt", "0 0.1\n0.01 -0.2\n0.02 0.05\n");  // listed nowhere: not a record
    write_file(folder / "records.csv", "file,pga_g\nd.txt,0.2\nb.at2,0.8\n");
    const study::StudySpec spec = study_of(dir, kWall + "[excitation]\nkind = \"ensemble\"\nensemble = \"set\"\n"
                                                        "intensity = \"pga\"\nlevels = 0.4\n");
    const study::Axis* files = spec.parts[0].excitation_axis("file");
    ASSERT_NE(files, nullptr);
    EXPECT_EQ(files->levels, (std::vector<study::Level>{std::string("set/A.AT2"), std::string("set/b.at2"),
                                                        std::string("set/c.At2"), std::string("set/d.txt")}));
    EXPECT_EQ(spec.parts[0].ensemble->folder, "set");
    const Grid grid(spec);  // every one reads
    EXPECT_EQ(grid.case_ids().size(), 4u);

    // The shipped records: all 26, as data/records/records.csv lists them.
    const study::StudySpec shipped = study_of(dir, kWall + "[excitation]\nkind = \"ensemble\"\nensemble = \"" +
                                                       kRecords + "\"\nintensity = \"pga\"\ncollapse = true\n");
    EXPECT_EQ(shipped.parts[0].excitation_axis("file")->levels.size(), 26u);
}

TEST(StudyEnsemble, EachMalformationIsNamed) {
    const TempDir dir;
    std::filesystem::create_directories(dir / "empty");
    write_file(dir / "empty" / "notes.txt", "no records here\n");
    const std::string ex = kWall + "[excitation]\nkind = \"ensemble\"\n";
    const std::string files = "files = " + file_list() + "\n";
    const std::string pga = "intensity = \"pga\"\n";
    struct Case {
        std::string toml, expected;
    };
    const std::vector<Case> cases = {
        {ex + "files = []\n" + pga + "levels = [0.4]\n", "excitation.files: an empty list"},
        {ex + "files = [3]\n" + pga + "levels = [0.4]\n", "excitation.files: must list paths of record files, got 3"},
        {ex + "ensemble = \"nowhere\"\n" + pga + "levels = [0.4]\n", "excitation.ensemble: no folder \"nowhere\""},
        {ex + "ensemble = \"empty\"\n" + pga + "levels = [0.4]\n", "excitation.ensemble: no records in \"empty\""},
        {ex + files + "ensemble = \"empty\"\n" + pga + "levels = [0.4]\n", "excitation: give the records one way"},
        {ex + pga + "levels = [0.4]\n", "excitation: give the records one way"},
        {ex + files + pga + "levels = [0.4]\ncollapse = true\n", "excitation: give 'levels'"},
        {ex + files + pga, "excitation: give 'levels'"},
        {ex + files + pga + "levels = [0.4, 0]\n", "excitation.levels: must be a PGA in g, > 0, got 0"},
        {ex + files + pga + "levels = [0.4, -0.2]\n", "excitation.levels: must be a PGA in g, > 0, got -0.2"},
        {ex + files + pga + "levels = [\"high\"]\n", "excitation.levels: must be a finite number (a PGA in g, > 0), got \"high\""},
        {ex + files + pga + "levels = [0.4, 0.4]\n", "excitation.levels: lists 0.4 twice"},
        {ex + files + pga + "levels = [0.4, 0.40000001]\n",
         "excitation.levels: 0.4 and 0.40000001 are one level to 6 significant digits"},
        {ex + files + "intensity = \"pgd\"\nlevels = [0.4]\n",
         "excitation.intensity: must be one of pga, pgv, sa, arias, got \"pgd\""},
        {ex + files + "intensity = \"sa\"\nlevels = [0.4]\n", "intensity \"sa\" needs 'sa_period'"},
        {ex + files + "intensity = \"pgv\"\nsa_period = 1\nlevels = [0.4]\n",
         "excitation.sa_period: is for intensity = \"sa\""},
        {ex + files + "intensity = \"sa\"\nsa_period = 0\nlevels = [0.4]\n", "excitation.sa_period: must be"},
        {ex + files + "intensity = \"sa\"\nsa_period = 1\nsa_damping = 1\nlevels = [0.4]\n",
         "excitation.sa_damping: must be a damping ratio in [0, 1), got 1"},
        {ex + files + "intensity = \"pgv\"\nlevels = [0.4, 0]\n", "excitation.levels: must be a PGV in m/s, > 0, got 0"},
        {ex + files + "levels = [0.4]\n", "kind ensemble needs 'intensity'"},
        {ex + files + pga + "collapse = \"yes\"\n", "excitation.collapse: must be true or false, got \"yes\""},
        {ex + files + pga + "collapse = true\nband = true\n", "excitation.band: is for a stripe analysis"},
        {ex + files + pga + "levels = [0.4]\nmax_pga = 2\n", "excitation.max_pga: is for collapse = true"},
        {ex + files + pga + "levels = [0.4]\npga = 0.3\n", "unknown key 'pga'"},
        {ex + "files = [\"" + kRinaldi + "\", \"missing.at2\"]\n" + pga + "levels = [0.4]\n", "missing.at2"},
        {ex + "files = [\"" + kRinaldi + "\"]\n" + pga + "levels = [0.4]\n", "at least two records, got 1"},
    };
    for (const Case& c : cases) {
        const std::string message = refusal(dir, c.toml);
        EXPECT_NE(message.find("study file"), std::string::npos) << c.toml;
        EXPECT_NE(message.find(c.expected), std::string::npos) << "expected '" << c.expected << "' in: " << message;
    }
}

// A record is the file its path resolves to (study/record_files.hpp): one file named twice, however spelled ("./",
// "..", a symlinked folder, a symbolic link or a hard link to it), is refused naming both spellings; two byte-identical
// copies are two files and run as two records.
TEST(StudyEnsemble, OneFileSpelledTwiceIsRefusedNamingBothSpellings) {
    namespace fs = std::filesystem;
    const TempDir dir;
    fs::create_directories(dir / "recs");
    fs::copy_file(kRinaldi, dir / "recs" / "a.at2");
    fs::copy_file(kPacoimaDam, dir / "recs" / "b.at2");
    fs::create_directory_symlink("recs", dir / "recs_link");
    fs::create_symlink("a.at2", dir / "recs" / "a_alias.at2");
    fs::create_hard_link(dir / "recs" / "b.at2", dir / "b_hard.at2");
    const std::string tail = "\nintensity = \"pga\"\nlevels = [0.4]\n";
    const auto files = [&](const std::string& one, const std::string& two) {
        return kWall + "[excitation]\nkind = \"ensemble\"\nfiles = [\"" + one + "\", \"" + two + "\"]" + tail;
    };
    const std::vector<std::pair<std::string, std::string>> pairs = {
        {"recs/a.at2", "recs/./a.at2"},
        {"recs/a.at2", "recs/../recs/a.at2"},
        {"recs/a.at2", "recs_link/a.at2"},
        {"recs/a.at2", "recs/a_alias.at2"},
        {"recs/b.at2", "b_hard.at2"},
        {"recs/a.at2", (dir / "recs" / "a.at2").string()},
    };
    for (const auto& [one, two] : pairs) {
        const std::string message = refusal(dir, files(one, two));
        EXPECT_NE(message.find("excitation.files: \"" + one + "\" and \"" + two + "\" are one file"), std::string::npos)
            << message;
    }
    // A folder holding a symbolic link to one of its records (the same file under two names).
    const std::string folder = kWall + "[excitation]\nkind = \"ensemble\"\nensemble = \"recs\"" + tail;
    const std::string message = refusal(dir, folder);
    EXPECT_NE(message.find("excitation.ensemble: \"recs/a.at2\" and \"recs/a_alias.at2\" are one file"),
              std::string::npos)
        << message;
    // Byte-identical copies: two files.
    fs::remove(dir / "recs" / "a_alias.at2");
    fs::copy_file(dir / "recs" / "a.at2", dir / "recs" / "a_copy.at2");
    EXPECT_EQ(refusal(dir, folder), "");
    EXPECT_EQ(refusal(dir, files("recs/a.at2", "recs/a_copy.at2")), "");
}

// An entry of an ensemble folder named *.at2 that is no file is refused by name, not skipped (the ensemble would
// shrink without a word): a dangling link, a link loop, a FIFO, a device, a folder. So is one its records.csv lists.
TEST(StudyEnsemble, AFolderEntryThatIsNoFileIsRefusedByName) {
    namespace fs = std::filesystem;
    const TempDir dir;
    const std::string toml =
        kWall + "[excitation]\nkind = \"ensemble\"\nensemble = \"set\"\nintensity = \"pga\"\nlevels = [0.4]\n";
    const auto fresh_set = [&] {
        fs::remove_all(dir / "set");
        fs::create_directories(dir / "set");
        fs::copy_file(kRinaldi, dir / "set" / "a.at2");
        fs::copy_file(kPacoimaDam, dir / "set" / "b.at2");
    };
    fresh_set();
    ASSERT_EQ(refusal(dir, toml), "") << "the set as it is runs";
    const std::vector<std::pair<std::function<void()>, std::string>> entries = {
        {[&] { fs::create_symlink("missing.at2", dir / "set" / "x.at2"); }, "a symbolic link to a missing file"},
        {[&] { fs::create_symlink("x.at2", dir / "set" / "x.at2"); }, "a symbolic link loop"},
        {[&] { ASSERT_EQ(mkfifo((dir / "set" / "x.at2").c_str(), 0600), 0); }, "a FIFO"},
        {[&] { fs::create_symlink("/dev/zero", dir / "set" / "x.at2"); }, "a device"},
        {[&] { fs::create_directory(dir / "set" / "x.at2"); }, "a folder"},
    };
    for (const auto& [make, what] : entries) {
        fresh_set();
        make();
        const std::string message = refusal(dir, toml);
        EXPECT_NE(message.find("excitation.ensemble: \"x.at2\" in \"set\" is " + what), std::string::npos) << message;
    }
    fresh_set();
    fs::create_symlink("missing.txt", dir / "set" / "c.txt");
    write_file(dir / "set" / "records.csv", "file\nc.txt\n");
    const std::string message = refusal(dir, toml);
    EXPECT_NE(message.find("\"records.csv\" lists \"c.txt\", which is not a file in \"set\" (a symbolic link to a "
                           "missing file)"),
              std::string::npos)
        << message;
}

// The band: each stripe case again as the free-vibration targets allow (PGA x (1 +- 1e-2), restitution x (1 +- 2e-2),
// the wall's size x (1 +- 1e-2)), run by the analytic model alone, each row saying which in its `perturbation` column.
TEST(StudyEnsemble, TheBandIsTheAnalyticModelsAlone) {
    const TempDir dir;
    const std::vector<double> levels = {0.4, 0.6};
    const std::string engines = engine_available("ode") ? "engines = [\"analytic\", \"ode\"]\n" : "";
    const Grid grid(study_of(dir, engines + "metrics = [\"peak_rotation\"]\n" + kWall +
                                      "[excitation]\nkind = \"ensemble\"\nfiles = [\"" + kRinaldi + "\", \"" +
                                      kPacoimaDam + "\"]\nintensity = \"pga\"\nlevels = [0.4, 0.6]\nband = true\n"));
    ASSERT_EQ(grid.case_ids().size(), 2u * levels.size() * study::kPerturbations.size());
    for (const int id : grid.case_ids()) {
        const study::CaseSpec c = grid.make_case(id);
        for (const study::RunSpec& run : grid.runs())
            EXPECT_EQ(grid.run_applies(run, c), run.engine == "analytic" || c.perturbation == "none")
                << c.perturbation << " " << run.engine;
        // The wall's columns stay the nominal wall's; its scene is the perturbed one.
        EXPECT_EQ(c.height, 4.0);
        EXPECT_EQ(2.0 * c.scene.vssw->h(), 4.0 * study::band_factors(c.perturbation).size) << c.perturbation;
    }
    if (!engines.empty()) {
        EXPECT_EQ(grid.skipped_runs().size(), 1u);
    }

    const ResultsTable t = run_into(grid, dir / "out", 2);
    const std::size_t perturbation = t.column("perturbation"), engine = t.column("engine"), pga = t.column("pga");
    std::size_t band_rows = 0;
    for (const auto& row : t.rows) {
        EXPECT_EQ(row[t.column("status")], "ok");
        if (row[perturbation] == "none") continue;
        ++band_rows;
        EXPECT_EQ(row[engine], "analytic");
    }
    constexpr std::size_t kRecordsRun = 2;
    EXPECT_EQ(band_rows, kRecordsRun * levels.size() * (study::kPerturbations.size() - 1));
    EXPECT_EQ(t.rows.size(), kRecordsRun * levels.size() * (study::kPerturbations.size() + (engines.empty() ? 0 : 1)));
    // The level's rows: at the level but for the nudged ones at level x (1 +- 1e-2); at 0.4 g, where the wall stands,
    // each perturbation moves the peak (each a different run from the nominal one; at 0.6 g every one overturns).
    for (const double level : levels) {
        std::map<std::string, double> peak;
        for (const std::string& name : study::kPerturbations) {
            const auto row = std::find_if(t.rows.begin(), t.rows.end(), [&](const auto& r) {
                return r[perturbation] == name && r[engine] == "analytic" &&
                       std::abs(std::stod(r[pga]) / level - 1.0) < kNearLevel && r[t.column("file")] == kRinaldi;
            });
            ASSERT_NE(row, t.rows.end()) << name << " at " << level;
            EXPECT_NEAR(std::stod((*row)[pga]), level * study::band_factors(name).intensity, kScaledPga * level)
                << name;
            peak[name] = std::stod((*row)[t.column("value")]);
        }
        for (const std::string& name : study::kPerturbations)
            if (name != "none" && level == levels.front()) {
                EXPECT_NE(peak[name], peak["none"]) << name << " at " << level;
            }
    }
}

// The band's size perturbation is the period target's +-0.5 % at the same threshold: height and thickness x (1 +- 1 %)
// keep the slenderness (and the hinge ratio), so the rest threshold (a function of the angles) stays, and the
// rocking frequency p = sqrt(|V_r| / M(0)) up to a constant of the shape (V ~ m g R ~ R^3, M ~ m R^2 ~ R^4) scales as
// R^-1/2 (Housner's p = sqrt(3 g / 4R) for a block).
TEST(StudyEnsemble, TheBandsSizeIsThePeriodTargetAtTheSameThreshold) {
    constexpr double kRoundOff = 1e-12;  // ratios of closed forms of the same angles
    constexpr double kPeriodTarget = 5e-3;  // the free-vibration period target, +-0.5 %
    const auto model = [](double f) {
        return analytic_model(Wall::of(make_vssw(4.0 * f, 0.4 * f, 0.7)), Kinematics::exact);
    };
    const auto p = [](const RockingModel& m) {
        return std::sqrt(std::abs(m.reference_energy()) / (2.0 * m.kinetic(0.0, 1.0)));  // kinetic(0, 1) = M(0) / 2
    };
    const auto nominal = model(1.0);
    for (const double f : {1.0 + study::kBandSizeStep, 1.0 - study::kBandSizeStep}) {
        const auto scaled = model(f);
        EXPECT_NEAR(scaled->rest_threshold(0.0) / nominal->rest_threshold(0.0), 1.0, kRoundOff) << f;
        EXPECT_NEAR(p(*scaled) / p(*nominal), 1.0 / std::sqrt(f), kRoundOff) << f;
        // 1 -+ 0.5 %, to the first order's 1 % (0.4975 % and 0.5038 %).
        EXPECT_NEAR(std::abs(p(*scaled) / p(*nominal) - 1.0), kPeriodTarget, 0.01 * kPeriodTarget) << f;
    }
}

// Fig. 10's rocking curves over an ensemble (study::rocking_curves): at each alpha the median and quartiles of the
// records' peaks as results.csv holds them, computed here from the rows; the overturned runs counted.
TEST(StudyEnsemble, RockingCurvesAreTheRecordsPeakQuartilesAtEachAlpha) {
    constexpr double kSamePeak = 1e-12;  // results.csv prints each peak in full (17 digits): relative round-off
    const TempDir dir(TempDir::test_name());
    const Grid grid(study_of(dir, "metrics = [\"peak_rotation\", \"overturned\"]\nengines = [\"analytic\"]\n"
                                  "[wall]\nalpha = [0.05, 0.1]\nR = 2.0\nhinge = 0.6\nxi = 0.1\n"
                                  "[assumptions]\nkinematics = \"exact\"\nimpact = \"whole-mechanism\"\n"
                                  "roller = \"unilateral\"\n[excitation]\nkind = \"ensemble\"\nfiles = [\"" +
                                      kRinaldi + "\", \"" + kPacoimaDam + "\", \"" + kRecords +
                                      "/parkfield1966-cholame8-050.at2\"]\nintensity = \"pga\"\nlevels = [0.4]\n"));
    const ResultsTable t = run_into(grid, dir / "out");
    const std::vector<study::RockingCurve> curves = study::rocking_curves(study::read_study_data(dir / "out"));
    ASSERT_EQ(curves.size(), 1u);
    ASSERT_EQ(curves[0].points.size(), 2u);
    // An overturned run's peak counts as the largest (infinite: study/overturned_runs.hpp), not its collapse angle.
    const auto same = [&](double value, double expected) {
        if (std::isinf(expected)) EXPECT_EQ(value, expected);
        else EXPECT_NEAR(value, expected, kSamePeak * std::abs(expected));
    };
    for (const study::RockingPoint& p : curves[0].points) {
        std::map<std::string, double> peak_of, over_of;  // by record file
        const std::string alpha = p.alpha == 0.05 ? "0.05" : "0.1";
        for (const auto& row : t.rows) {
            if (row[t.column("alpha")] != alpha) continue;
            const std::string& file = row[t.column("file")];
            if (row[t.column("metric")] == "peak_rotation") peak_of[file] = std::stod(row[t.column("value")]);
            if (row[t.column("metric")] == "overturned") over_of[file] = std::stod(row[t.column("value")]);
        }
        std::vector<double> peaks;
        long overturned = 0;
        for (const auto& [file, peak] : peak_of) {
            const bool over = over_of.at(file) == 1.0;
            overturned += over ? 1 : 0;
            peaks.push_back(over ? HUGE_VAL : peak);
        }
        ASSERT_EQ(peaks.size(), 3u);
        std::sort(peaks.begin(), peaks.end());
        same(p.peak.median, peaks[1]);  // the middle of three
        same(p.peak.q1, peaks[0] == peaks[1] ? peaks[0] : 0.5 * (peaks[0] + peaks[1]));  // type 7 at 1/4 of three
        same(p.peak.q3, peaks[1] == peaks[2] ? peaks[1] : 0.5 * (peaks[1] + peaks[2]));
        EXPECT_EQ(p.overturned, overturned);
    }

}

// The record's PGV and Arias intensity computed here, apart from the library: trapezoidal, from rest.
double pgv_of(const GroundMotion& r) {
    const std::vector<double>&t = r.sample_times(), &a = r.sample_values();
    double v = 0.0, peak = 0.0;
    for (std::size_t i = 1; i < t.size(); ++i) {
        v += 0.5 * (t[i] - t[i - 1]) * (a[i] + a[i - 1]);
        peak = std::max(peak, std::abs(v));
    }
    return peak;
}
double arias_of(const GroundMotion& r) {
    const std::vector<double>&t = r.sample_times(), &a = r.sample_values();
    double sum = 0.0;
    for (std::size_t i = 1; i < t.size(); ++i) sum += 0.5 * (t[i] - t[i - 1]) * (a[i] * a[i] + a[i - 1] * a[i - 1]);
    return M_PI / (2.0 * kStandardGravity) * sum;
}

// Stripes in another measure: each record scaled so that its measure equals the level (the Arias intensity by the
// square root of the ratio), every scale recomputed here from the record file and the level; the rows carry the
// measure's value, name and unit, and the PGA the scale gives.
TEST(StudyEnsemble, StripesInPgvSaAndAriasScaleEachRecordToItsLevel) {
    // Sums in another order than the library's over a few thousand samples, then a ratio: a few ulps of each.
    constexpr double kRecomputed = 1e-12;
    const TempDir dir;
    struct Measure {
        std::string word, unit, extra;
        double level;
    };
    for (const Measure& m : {Measure{"pgv", "m/s", "", 0.3}, Measure{"sa", "g", "sa_period = 1\n", 0.5},
                             Measure{"arias", "m/s", "", 0.8}}) {
        const Grid grid(study_of(dir, "metrics = [\"overturned\"]\n" + kWall + "[excitation]\nkind = \"ensemble\"\n" +
                                          "files = " + file_list() + "\nintensity = \"" + m.word + "\"\n" + m.extra +
                                          fmt::format("levels = [{}, {}]\n", m.level, 2.0 * m.level),
                                 m.word + ".toml"));
        const ResultsTable t = run_into(grid, dir / m.word, 2);
        ASSERT_EQ(t.rows.size(), 4u) << m.word;
        for (const auto& row : t.rows) {
            const GroundMotion record = read_record(row[t.column("file")]);
            const double at_one = m.word == "pgv"  ? pgv_of(record)
                                  : m.word == "sa" ? spectral_acceleration(record.sample_times(),
                                                                           record.sample_values(), 1.0, 0.05) /
                                                         kStandardGravity
                                                   : arias_of(record);
            const double level = std::stod(row[t.column(m.word)]);
            const double scale = m.word == "arias" ? std::sqrt(level / at_one) : level / at_one;
            EXPECT_NEAR(std::stod(row[t.column("scale")]) / scale, 1.0, kRecomputed) << m.word;
            EXPECT_TRUE(std::abs(level / m.level - 1.0) < kRecomputed || std::abs(level / (2.0 * m.level) - 1.0) < kRecomputed)
                << m.word << " " << level;
            EXPECT_NEAR(std::stod(row[t.column("pga")]) / (scale * record.pga() / kStandardGravity), 1.0, kRecomputed);
            EXPECT_EQ(row[t.column("intensity")], m.word);
            EXPECT_EQ(row[t.column("intensity_unit")], m.unit);
        }
    }
}

// The IDA plot draws an overturned run as every plot of the peak rotation does: at theta1 = alpha1 (1), ringed and
// titled "overturned" (its value, the collapse angle over alpha1, would squash the rocking peaks).
void expect_overturned_runs_ringed_at_one(const std::filesystem::path& plots) {
    std::ifstream dat(plots / "ida.dat");
    std::string line;
    int overturned = 0;
    while (std::getline(dat, line)) {
        double intensity = 0.0, drawn = 0.0;
        int flag = 0;
        if (line.empty() || line[0] == '#' || std::sscanf(line.c_str(), "%lf %lf %d", &intensity, &drawn, &flag) != 3)
            continue;
        if (flag != 1) continue;
        ++overturned;
        EXPECT_EQ(drawn, 1.0) << line;
    }
    EXPECT_GT(overturned, 0) << "each search ends on overturning runs";
    std::ifstream gp_in(plots / "ida.gp");
    const std::string gp((std::istreambuf_iterator<char>(gp_in)), std::istreambuf_iterator<char>());
    EXPECT_NE(gp.find("using 1:($3 > 0.5 ? $2 : NaN) with points " + std::string(study::kOverturnedRing)),
              std::string::npos) << gp;
    EXPECT_NE(gp.find("title 'overturned'"), std::string::npos) << gp;
    EXPECT_EQ(gp.find("overturned at the top"), std::string::npos) << gp;
}

// An IDA in PGV: collapse_pgv is collapse_scale times the record's PGV (collapse_pga stays); ida.csv holds every run
// of each search, the smallest overturning intensity among them the collapse intensity; fragility.csv's fit is the
// log-moments of results.csv's collapse_pgv rows, in m/s.
TEST(StudyEnsemble, IdaInPgvReportsItsCollapseIntensitiesAndCurves) {
    constexpr double kRecomputed = 1e-12;  // as above
    const TempDir dir;
    const Grid grid(study_of(dir, kWall + "[excitation]\nkind = \"ensemble\"\nfiles = " + file_list() +
                                      "\nintensity = \"pgv\"\ncollapse = true\nstep = 0.1\ntolerance = 0.01\n"));
    EXPECT_EQ(grid.spec().metrics, (std::vector<std::string>{"collapse_scale", "collapse_pga", "collapse_pgv"}));
    const ResultsTable t = run_into(grid, dir / "ida", 2);
    std::map<int, std::map<std::string, double>> by_case;
    std::map<int, std::string> file;
    for (const auto& row : t.rows) {
        by_case[std::stoi(row[t.column("case_id")])][row[t.column("metric")]] = std::stod(row[t.column("value")]);
        file[std::stoi(row[t.column("case_id")])] = row[t.column("file")];
        if (row[t.column("metric")] == "collapse_pgv") {
            EXPECT_EQ(row[t.column("unit")], "m/s");
        }
    }
    ASSERT_EQ(by_case.size(), 2u);
    std::vector<double> logs;
    const std::vector<study::IdaCurve> curves = study::read_ida_csv(dir / "ida" / study::kIdaCsv);
    ASSERT_EQ(curves.size(), 2u);
    for (const auto& [id, values] : by_case) {
        const GroundMotion record = read_record(file[id]);
        EXPECT_NEAR(values.at("collapse_pgv") / (values.at("collapse_scale") * pgv_of(record)), 1.0, kRecomputed);
        logs.push_back(std::log(values.at("collapse_pgv")));
        const study::IdaCurve& curve = curves[id == curves[0].case_id ? 0 : 1];
        EXPECT_EQ(curve.case_id, id);
        EXPECT_EQ(curve.measure, "pgv");
        double first_overturning = INFINITY;
        for (std::size_t i = 0; i < curve.intensity.size(); ++i)
            if (curve.overturned[i]) first_overturning = std::min(first_overturning, curve.intensity[i]);
        EXPECT_NEAR(first_overturning / values.at("collapse_pgv"), 1.0, kRecomputed);
        EXPECT_GT(curve.intensity.size(), 3u);  // the steps and the bisection
    }
    study::OutputOptions o;
    o.gnuplot = (dir / "no-gnuplot").string();  // the plots' scripts and data without drawing them
    study::write_study_outputs(dir / "ida", o);
    expect_overturned_runs_ringed_at_one(dir / "ida" / study::kPlotsDir);
    std::ifstream in(dir / "ida" / "fragility.csv");
    std::vector<std::string> header, row, more;
    ASSERT_TRUE(io::read_csv_record(in, header) && io::read_csv_record(in, row));
    EXPECT_FALSE(io::read_csv_record(in, more) && !(more.size() == 1 && more[0].empty()));  // one series, one wall
    const auto field = [&](const std::string& name) {
        return row.at(static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin()));
    };
    EXPECT_EQ(field("intensity"), "pgv_ida");
    EXPECT_EQ(field("intensity_unit"), "m/s");
    const double mean = 0.5 * (logs[0] + logs[1]);
    EXPECT_NEAR(std::log(std::stod(field("median"))), mean, kRecomputed);
    EXPECT_NEAR(std::stod(field("beta")), std::abs(logs[0] - logs[1]) / std::sqrt(2.0), kRecomputed);
}

// The IDA plot names its rings "overturned" only when some run overturned: the same search read back with every run
// marked standing (its peaks below 1) draws no ring title, where the search as run has one.
TEST(StudyEnsemble, IdaPlotNamesOverturnedOnlyWhenARunOverturned) {
    const TempDir dir;
    const Grid grid(study_of(dir, kWall + "[excitation]\nkind = \"ensemble\"\nfiles = " + file_list() +
                                      "\nintensity = \"pga\"\ncollapse = true\nstep = 0.2\ntolerance = 0.05\n"));
    run_into(grid, dir / "ida", 2);
    study::OutputOptions o;
    o.gnuplot = (dir / "no-gnuplot").string();  // the plots' scripts and data without drawing them
    const auto ida_gp = [&] {
        study::write_study_outputs(dir / "ida", o);
        std::ifstream in(dir / "ida" / study::kPlotsDir / "ida.gp");
        return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    };
    const std::string rings = "using 1:($3 > 0.5 ? $2 : NaN) with points " + std::string(study::kOverturnedRing);
    const std::string as_run = ida_gp();
    ASSERT_NE(as_run.find(rings + " title 'overturned'"), std::string::npos) << "the search ends on overturning runs";
    // ida.csv rewritten: every run standing, at half its peak (an overturned one's is the collapse angle, above 1).
    const std::filesystem::path csv = dir / "ida" / study::kIdaCsv;
    std::ifstream in(csv);
    std::vector<std::string> header, fields;
    ASSERT_TRUE(io::read_csv_record(in, header));
    const auto at = [&](const std::string& name) {
        return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
    };
    std::string standing;
    for (const std::string& h : header) standing += (standing.empty() ? "" : ",") + io::csv_field(h);
    while (io::read_csv_record(in, fields)) {
        if (fields.size() != header.size()) continue;
        fields.at(at("overturned")) = "0";
        const double peak = std::stod(fields.at(at("peak_over_alpha1")));
        fields.at(at("peak_over_alpha1")) = io::csv_number(0.5 * std::min(1.0, peak));
        std::string line;
        for (const std::string& f : fields) line += (line.empty() ? "" : ",") + io::csv_field(f);
        standing += "\n" + line;
    }
    in.close();
    std::ofstream(csv) << standing << "\n";
    const std::string none_over = ida_gp();
    EXPECT_NE(none_over.find(rings + " notitle"), std::string::npos) << none_over;
    EXPECT_EQ(none_over.find("overturned'"), std::string::npos) << none_over;
}

// An ida.csv of an older vssw (its peak column was peak_over_alpha) is refused naming the header expected, written
// out here, so the reader can see which column differs.
TEST(StudyEnsemble, IdaCsvWithAnOldHeaderIsRefusedNamingTheHeaderExpected) {
    const TempDir dir;
    std::ofstream(dir / "ida.csv") << "case_id,engine,assumptions,settings,record,scale,measure,intensity,"
                                      "intensity_unit,peak_over_alpha,overturned\n";
    try {
        study::read_ida_csv(dir / "ida.csv");
        FAIL() << "an ida.csv with the old header was read";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("its header is not 'case_id,engine,assumptions,settings,record,scale,"
                                             "measure,intensity,intensity_unit,peak_over_alpha1,overturned'"),
                  std::string::npos)
            << e.what();
    }
}

// The fractiles of the IDA curves: the lowest intensity reaching a peak on a curve linear between its runs, and
// quantiles that stay infinite where a record never reaches the peak.
TEST(StudyEnsemble, IdaFractilesReadTheCurvesLowestCrossing) {
    study::IdaCurve c;
    c.intensity = {0.1, 0.2, 0.3, 0.4};
    c.peak = {0.1, 0.5, 0.3, 2.0};  // a resurrection: the peak falls at 0.3
    c.overturned = {false, false, false, true};
    EXPECT_DOUBLE_EQ(study::intensity_reaching(c, 0.05), 0.05);
    EXPECT_DOUBLE_EQ(study::intensity_reaching(c, 0.3), 0.15);  // the first crossing, not the one after 0.3
    EXPECT_DOUBLE_EQ(study::intensity_reaching(c, 1.0), 0.3 + 0.1 * 0.7 / 1.7);
    EXPECT_TRUE(std::isinf(study::intensity_reaching(c, 3.0)));
    EXPECT_DOUBLE_EQ(study::fractile({3.0, 1.0, 2.0}, 0.5), 2.0);
    EXPECT_DOUBLE_EQ(study::fractile({1.0, 2.0, 3.0, 4.0, 5.0}, 0.16), 1.64);
    EXPECT_TRUE(std::isinf(study::fractile({1.0, 2.0, INFINITY}, 0.84)));
}

// ida.csv from shards merged is the same bytes as from one run (each task's points in the order run, cases in order).
TEST(StudyEnsemble, IdaCurvesOfShardsMergeIntoTheOneRunsFile) {
    const TempDir dir;
    const Grid grid(study_of(dir, kWall + "[excitation]\nkind = \"ensemble\"\nfiles = " + file_list() +
                                      "\nintensity = \"arias\"\ncollapse = true\nstep = 0.1\ntolerance = 0.01\n"));
    run_into(grid, dir / "one", 2);
    run_into(grid, dir / "s1", 1, {1, 2});
    run_into(grid, dir / "s2", 1, {2, 2});
    study::merge_studies({dir / "s1", dir / "s2"}, dir / "merged", {});
    const std::string one = vssw::testing::read_file(dir / "one" / study::kIdaCsv);
    EXPECT_NE(one.find(",arias,"), std::string::npos);
    EXPECT_EQ(vssw::testing::read_file(dir / "merged" / study::kIdaCsv), one);
}

}  // namespace
