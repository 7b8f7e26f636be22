// Ensembles in study files (kind = "ensemble", study/spec.hpp): read into the record or scale-to-collapse study they
// stand for (the same ids and rows but for the kind), a folder's records listed in name order, every malformed key
// named, and the sensitivity band: the analytic model's perturbed repeats of each stripe case, which engines do not
// run, with a record one sample shorter (GroundMotion::drop_first_sample).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "analytic/error.hpp"
#include "analytic/ground_motion.hpp"
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
// Times shifted by a subtraction (t - t1) are the originals' differences to rounding of numbers below 100 s.
constexpr double kShiftedTime = 1e-12;
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
        {ex + files + "intensity = \"sa\"\nlevels = [0.4]\n", "excitation.intensity: must be one of pga, got \"sa\""},
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

// Dropping the first sample: one sample fewer, the old second sample at t = 0, the same accelerations one sample
// earlier. Shifted to 0 (not left to start at the old second time) because a record is zero before its first sample:
// unshifted it would be the original with its first interval ramped from 0, no perturbation of the motion's phase.
TEST(StudyEnsemble, DroppingTheFirstSampleShiftsTheRecordOneSampleEarlier) {
    const GroundMotion original = read_record(kRinaldi);
    const GroundMotion dropped = original.drop_first_sample();
    ASSERT_EQ(dropped.sample_times().size() + 1, original.sample_times().size());
    const double t1 = original.sample_times()[1];
    EXPECT_EQ(dropped.sample_times().front(), 0.0);
    for (std::size_t i = 0; i < dropped.sample_times().size(); i += 97) {
        EXPECT_NEAR(dropped.sample_times()[i], original.sample_times()[i + 1] - t1, kShiftedTime) << i;
        EXPECT_EQ(dropped.sample_values()[i], original.sample_values()[i + 1]) << i;
    }
    EXPECT_NEAR(dropped.duration(), original.duration() - t1, kShiftedTime);

    const GroundMotion three = GroundMotion::sampled({0.5, 0.6, 0.8}, {1.0, -2.0, 3.0}, "three");
    const GroundMotion two = three.drop_first_sample();
    EXPECT_EQ(two.sample_times(), (std::vector<double>{0.0, 0.8 - 0.6}));
    EXPECT_EQ(two.sample_values(), (std::vector<double>{-2.0, 3.0}));
    EXPECT_THROW((void)two.drop_first_sample(), InputError);  // one sample cannot be a record
    EXPECT_THROW((void)sine_pulse(1.0, 0.5).drop_first_sample(), InputError);
    EXPECT_THROW((void)GroundMotion::none().drop_first_sample(), InputError);
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
    for (const study::RockingPoint& p : curves[0].points) {
        std::vector<double> peaks;
        long overturned = 0;
        const std::string alpha = p.alpha == 0.05 ? "0.05" : "0.1";
        for (const auto& row : t.rows) {
            if (row[t.column("alpha")] != alpha) continue;
            if (row[t.column("metric")] == "peak_rotation") peaks.push_back(std::stod(row[t.column("value")]));
            if (row[t.column("metric")] == "overturned") overturned += row[t.column("value")] == "1";
        }
        ASSERT_EQ(peaks.size(), 3u);
        std::sort(peaks.begin(), peaks.end());
        EXPECT_NEAR(p.peak.median, peaks[1], kSamePeak * peaks[1]);  // the middle of three
        EXPECT_NEAR(p.peak.q1, 0.5 * (peaks[0] + peaks[1]), kSamePeak * peaks[1]);  // type 7 at 1/4 of three
        EXPECT_NEAR(p.peak.q3, 0.5 * (peaks[1] + peaks[2]), kSamePeak * peaks[2]);
        EXPECT_EQ(p.overturned, overturned);
    }
}

}  // namespace
