// `vssw study` and `vssw study merge` as a user runs them: exit codes, the JSON summary, refusals before anything is
// created, --strict, --force, --shard, merge.
#include <sys/stat.h>
#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "analytic/error.hpp"
#include "analytic/input_file.hpp"
#include "io/folder_swap.hpp"
#include "tests/cli_runner.hpp"
#include "tests/engine_available.hpp"
#include "tests/study_fixtures.hpp"

namespace {

using vssw::testing::run_cli;
using vssw::testing::TempDir;
using vssw::testing::write_file;

const char* const kStudy = R"(
name = "cli"
metrics = ["period", "restitution"]
[wall]
height = 4
thickness = 0.4
hinge = [0.6, 0.7]
[assumptions]
set = "paper"
kinematics = ["paper", "exact"]
[excitation]
kind = "free"
theta0 = 0.5
)";

// The unilateral roller fails its energy ceiling on Table 1 #6 at xi 0.5 from 0.8 alpha1
// (docs/measurements/findings.md): a study with a failed row.
const char* const kFailingStudy = R"(
metrics = ["period"]
[wall]
height = 3.05
thickness = 0.143
hinge = 0.67
xi = 0.5
[assumptions]
kinematics = "exact"
roller = "unilateral"
[excitation]
kind = "free"
theta0 = 0.8
)";

// Runs the study `file` as shards 1/2 and 2/2 into dir/1 and dir/2; whether both succeeded.
bool run_two_shards(const TempDir& dir, const std::string& file) {
    for (const char* k : {"1", "2"})
        if (run_cli({"study", file, "--out", (dir / k).string(), "--shard", std::string(k) + "/2", "--no-plots"}).code != 0)
            return false;
    return true;
}

TEST(StudyCli, RunsAStudyAndSummarisesItInJson) {
    const TempDir dir;
    const std::string file = write_file(dir / "s.toml", kStudy).string(), out = (dir / "out").string();
    const auto r = run_cli({"study", file, "--out", out, "--json", "--no-plots"});
    ASSERT_EQ(r.code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["study"], "cli");
    EXPECT_EQ(j["cases"], 2);
    EXPECT_EQ(j["runs"], 2);
    EXPECT_EQ(j["tasks_run"], 4);
    EXPECT_EQ(j["rows"], 8);  // 2 cases x 2 runs x 2 metrics
    EXPECT_EQ(j["failed_rows"], 0);
    for (const char* f : {"results.csv", "results.json", "manifest.json"})
        EXPECT_TRUE(std::filesystem::exists(dir / "out" / f)) << f;
    const auto results = nlohmann::json::parse(vssw::testing::read_file(dir / "out" / "results.json"));
    ASSERT_EQ(results["rows"].size(), 8u);
    EXPECT_EQ(results["rows"][0]["case_id"], 1);
    EXPECT_TRUE(results["rows"][0]["value"].is_number());
    EXPECT_EQ(results["study"]["as_read"]["wall"]["hinge"], nlohmann::json::parse("[0.6, 0.7]"));
    EXPECT_FALSE(results["vssw"]["commit"].get<std::string>().empty());
}

TEST(StudyCli, BadInputIsRefusedBeforeAnythingIsCreated) {
    const TempDir dir;
    const std::string out = (dir / "out").string();
    const std::string good = write_file(dir / "s.toml", kStudy).string();
    const std::string bad = write_file(dir / "bad.toml", std::string(kStudy) + "\n[settings.ode]\ndt = 1e-4\n").string();
    const std::string huge = write_file(dir / "huge.toml", "[wall]\nheight = 4\nthickness = 0.4\nhinge = 0.7\n"
                                                           "xi = [" + [] {
                                                               std::string l;
                                                               for (int i = 0; i < 10001; ++i)
                                                                   l += (i ? "," : "") + std::to_string(i * 1e-3);
                                                               return l;
                                                           }() + "]\n[excitation]\nkind = \"threshold\"\n")
                                 .string();
    const std::string threshold = "[wall]\nheight = 4\nthickness = 0.4\nhinge = 0.7\n[excitation]\nkind = \"threshold\"\n";
    const std::string bad_set = write_file(dir / "set.toml", "[assumptions]\nset = \"exact\"\n" + threshold).string();
    const std::string two_sets =
        write_file(dir / "sets.toml", "[assumptions]\nset = [\"paper\", \"mechanism\"]\n" + threshold).string();
    struct Case {
        std::vector<std::string> args;
        std::string expected;
    };
    const std::vector<Case> cases = {
        {{"study", bad, "--out", out}, "settings for an engine the study does not run"},
        {{"study", (dir / "missing.toml").string(), "--out", out}, "no such file"},
        {{"study", good}, "--out DIR is required"},
        {{"study", good, "--out", out, "--shard", "0/2"}, "--shard must be K/N"},
        {{"study", good, "--out", out, "--shard", "3/2"}, "--shard must be K/N"},
        {{"study", good, "--out", out, "--threads", "-1"}, "--threads must be an integer"},
        {{"study", huge, "--out", out}, "10001 tasks (cases x runs), more than 10000: add --force"},
        {{"study", bad_set, "--out", out}, "assumptions.set: must be one of paper, mechanism, got \"exact\""},
        {{"study", two_sets, "--out", out}, "assumptions.set: one set per study, got [\"paper\",\"mechanism\"]"},
    };
    for (const Case& c : cases) {
        const auto r = run_cli(c.args);
        EXPECT_EQ(r.code, 2) << c.expected;
        EXPECT_NE(r.err.find(c.expected), std::string::npos) << "expected '" << c.expected << "' in: " << r.err;
        EXPECT_FALSE(std::filesystem::exists(out)) << c.expected;
    }
}

// --strict: a row that failed is a failed study (exit 3), its results still written.
TEST(StudyCli, StrictFailsAStudyWithAFailedRow) {
    const TempDir dir;
    const std::string file = write_file(dir / "s.toml", kFailingStudy)
                                 .string();
    const auto lenient = run_cli({"study", file, "--out", (dir / "a").string(), "--no-plots"});
    EXPECT_EQ(lenient.code, 0) << lenient.err;
    EXPECT_NE(lenient.out.find("1 failed"), std::string::npos) << lenient.out;
    const auto strict = run_cli({"study", file, "--out", (dir / "b").string(), "--no-plots", "--strict"});
    EXPECT_EQ(strict.code, 3);
    EXPECT_NE(strict.err.find("--strict: 1 row failed"), std::string::npos) << strict.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "b" / "results.csv"));
}

TEST(StudyCli, ShardsMergeIntoOneRunsFiles) {
    const TempDir dir;
    const std::string file = write_file(dir / "s.toml", kStudy).string();
    ASSERT_EQ(run_cli({"study", file, "--out", (dir / "one").string(), "--no-plots"}).code, 0);
    ASSERT_TRUE(run_two_shards(dir, file));
    const auto missing = run_cli({"study", "merge", (dir / "1").string(), "--out", (dir / "m").string()});
    EXPECT_EQ(missing.code, 2);
    EXPECT_NE(missing.err.find("shard 2 of 2 missing"), std::string::npos) << missing.err;
    const auto merged =
        run_cli({"study", "merge", (dir / "2").string(), (dir / "1").string(), "--out", (dir / "m").string(), "--json",
                 "--no-plots"});
    ASSERT_EQ(merged.code, 0) << merged.err;
    EXPECT_EQ(nlohmann::json::parse(merged.out)["shards"], 2);
    EXPECT_EQ(vssw::testing::read_file(dir / "one" / "results.csv"), vssw::testing::read_file(dir / "m" / "results.csv"));
}

// A study folder's files are read only when they are regular files within their bound (analytic/input_file.hpp): a
// FIFO in place of results.csv, manifest.json or journal.csv blocked `study merge` and `--resume` forever, a symbolic
// link to /dev/zero grew memory without end. Each is refused unread (exit 2, one line naming the file).
TEST(StudyCli, AStudyFolderFileThatIsNoRegularFileIsRefusedUnread) {
    namespace fs = std::filesystem;
    const TempDir dir;
    const std::string file = write_file(dir / "s.toml", kStudy).string();
    ASSERT_TRUE(run_two_shards(dir, file));
    const std::vector<std::pair<std::string, std::function<void(const fs::path&)>>> stand_ins = {
        {"a FIFO", [](const fs::path& p) { ASSERT_EQ(mkfifo(p.c_str(), 0600), 0); }},
        {"a device", [](const fs::path& p) { fs::create_symlink("/dev/zero", p); }},
        {"bytes, more than", [](const fs::path& p) {  // a sparse file past the bound: nothing is written
             write_file(p, "");
             fs::resize_file(p, vssw::kMaxResultsBytes + 1);
         }},
    };
    const auto expect_refused = [](const vssw::testing::CliResult& r, const fs::path& path, const std::string& what) {
        EXPECT_EQ(r.code, 2) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_NE(r.err.find("'" + path.string() + "'"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find(what), std::string::npos) << r.err;
    };
    for (const auto& [what, make] : stand_ins) {
        for (const char* name : {"results.csv", "manifest.json"}) {
            if (std::string(name) == "manifest.json" && what == "bytes, more than") continue;  // its bound is 256 MiB
            const fs::path path = dir / "2" / name, kept = dir / "kept";
            fs::rename(path, kept);
            make(path);
            const auto r = run_cli({"study", "merge", (dir / "1").string(), (dir / "2").string(), "--out",
                                    (dir / "m").string(), "--no-plots"});
            expect_refused(r, path, what);
            EXPECT_FALSE(fs::exists(dir / "m"));
            fs::remove(path);
            fs::rename(kept, path);
        }
        const fs::path journal = dir / "r" / "journal.csv";
        fs::create_directories(dir / "r");
        make(journal);
        const auto r = run_cli({"study", file, "--out", (dir / "r").string(), "--resume", "--no-plots"});
        expect_refused(r, journal, what);
        fs::remove_all(dir / "r");
    }
}

TEST(StudyCli, HelpListsEveryMetric) {
    const auto r = run_cli({"study", "--help"});
    EXPECT_EQ(r.code, 0);
    for (const char* m : {"threshold_g", "period", "restitution", "peak_rotation", "peak_time", "overturned",
                          "t_overturn", "roller_tension_time", "collapse_scale", "energy_balance_error"})
        EXPECT_NE(r.out.find(m), std::string::npos) << m;
}

// `vssw compare` under a ground motion is a one-case study: the same numbers as `vssw study` on that case, and the
// analytic run is `vssw history`'s.
TEST(CompareResponse, IsAOneCaseStudyAndItsAnalyticRunIsHistorys) {
    const TempDir dir;
    const std::string record = std::string(VSSW_DATA_DIR) + "/elcentro_chopra.txt";
    const std::vector<std::string> wall = {"--height", "4", "--thickness", "0.4", "--hinge", "0.7", "--xi", "0.1"};
    std::vector<std::string> args = {"compare", "--engine", "analytic", "--record", record, "--pga", "0.35",
                                     "--impact", "whole-mechanism", "--json"};
    args.insert(args.end(), wall.begin(), wall.end());
    const auto c = run_cli(args);
    ASSERT_EQ(c.code, 0) << c.err;
    const auto cj = nlohmann::json::parse(c.out);
    ASSERT_EQ(cj["runs"].size(), 1u);  // "analytic" named as an engine is the reference's own run
    const double peak = cj["runs"][0]["peak_rotation"].get<double>();

    const std::string file =
        write_file(dir / "one.toml", "metrics = [\"peak_rotation\"]\n[wall]\nheight = 4\nthickness = 0.4\nhinge = 0.7\n"
                                     "xi = 0.1\n[assumptions]\nkinematics = \"exact\"\nimpact = \"whole-mechanism\"\n"
                                     "[excitation]\nkind = \"record\"\nfile = \"" + record + "\"\npga = 0.35\n")
            .string();
    ASSERT_EQ(run_cli({"study", file, "--out", (dir / "out").string(), "--no-plots"}).code, 0);
    const auto table = vssw::study::read_results_csv(dir / "out" / "results.csv");
    EXPECT_EQ(std::stod(table.rows.at(0).at(table.column("value"))), peak);

    std::vector<std::string> h = {"history", "--record", record, "--pga", "0.35", "--kinematics", "exact",
                                  "--impact", "whole-mechanism", "--json"};
    h.insert(h.end(), wall.begin(), wall.end());
    const auto history = run_cli(h);
    ASSERT_EQ(history.code, 0) << history.err;
    EXPECT_EQ(nlohmann::json::parse(history.out)["max_theta_over_alpha1"].get<double>(), peak);
}

// One reference everywhere: a study's analytic run is `vssw history`'s under the same assumptions, the default set's
// when the file names none, the set paper's (the defaults studies had before the sets) with set = "paper", and a key
// beside the set changes its part alone. The manifest names each run's set. Peaks are compared to the bit: the same
// run, not a close one. At 0.6 g El Centro overturns the paper's model and rocks the mechanism to 0.28 alpha1 (0.26
// with the paper's kinematics and the whole mechanism's impact): each equality tells which model ran.
struct StudyPeak {
    double peak;
    std::string set;
};

StudyPeak study_peak(const TempDir& dir, const std::string& name, const std::string& assumptions) {
    const std::string record = std::string(VSSW_DATA_DIR) + "/elcentro_chopra.txt";
    const std::string file =
        write_file(dir / (name + ".toml"), "metrics = [\"peak_rotation\"]\n[wall]\nheight = 4\nthickness = 0.4\n"
                                           "hinge = 0.7\nxi = 0.1\n" + assumptions + "[excitation]\nkind = \"record\"\n"
                                           "file = \"" + record + "\"\npga = 0.6\n")
            .string();
    const auto r = run_cli({"study", file, "--out", (dir / name).string(), "--no-plots"});
    EXPECT_EQ(r.code, 0) << r.err;
    if (r.code != 0) return {std::nan(""), ""};
    const auto table = vssw::study::read_results_csv(dir / name / "results.csv");
    const auto manifest = nlohmann::json::parse(vssw::testing::read_file(dir / name / "manifest.json"));
    return {std::stod(table.rows.at(0).at(table.column("value"))), manifest["runs"][0].value("set", "")};
}

double history_peak(const std::vector<std::string>& assumption_options) {
    std::vector<std::string> h = {"history", "--record", std::string(VSSW_DATA_DIR) + "/elcentro_chopra.txt", "--pga",
                                  "0.6", "--height", "4", "--thickness", "0.4", "--hinge", "0.7", "--xi", "0.1",
                                  "--json"};
    h.insert(h.end(), assumption_options.begin(), assumption_options.end());
    const auto r = run_cli(h);
    EXPECT_EQ(r.code, 0) << r.err;
    return r.code == 0 ? nlohmann::json::parse(r.out)["max_theta_over_alpha1"].get<double>() : std::nan("");
}

TEST(StudyAssumptions, AStudyWithoutAssumptionsRunsHistorysDefaultModel) {
    const TempDir dir;
    const StudyPeak study = study_peak(dir, "default", "");
    EXPECT_EQ(study.peak, history_peak({}));
    EXPECT_EQ(study.set, "mechanism");
    EXPECT_NE(study.peak, history_peak({"--assumptions", "paper"})) << "the two sets' peaks must differ";
}

TEST(StudyAssumptions, SetPaperIsTheOldDefaultsAndAKeyOverridesOnePart) {
    const TempDir dir;
    const StudyPeak paper = study_peak(dir, "paper", "[assumptions]\nset = \"paper\"\n");
    EXPECT_EQ(paper.peak, history_peak({"--assumptions", "paper"}));
    EXPECT_EQ(paper.set, "paper");
    // The defaults every study had before the sets, written out.
    const StudyPeak old = study_peak(dir, "old", "[assumptions]\nkinematics = \"paper\"\nimpact = \"eq19\"\n"
                                                 "roller = \"bilateral\"\n");
    EXPECT_EQ(old.peak, paper.peak);
    EXPECT_EQ(old.set, "paper") << "the set is named from the parts, however they were given";
    const StudyPeak whole = study_peak(dir, "whole", "[assumptions]\nset = \"paper\"\nimpact = \"whole-mechanism\"\n");
    EXPECT_EQ(whole.peak, history_peak({"--assumptions", "paper", "--impact", "whole-mechanism"}));
    EXPECT_NE(whole.peak, paper.peak) << "the override must change the run, or the check above tells nothing";
    EXPECT_EQ(whole.set, "custom");
}

TEST(StudyAssumptions, ABadSetIsOneLineNamingTheValue) {
    const TempDir dir;
    const std::string file = write_file(dir / "s.toml", "[assumptions]\nset = \"Paper\"\n[wall]\nheight = 4\n"
                                                        "thickness = 0.4\nhinge = 0.7\n[excitation]\nkind = "
                                                        "\"threshold\"\n")
                                 .string();
    const auto r = run_cli({"study", file, "--out", (dir / "out").string()});
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.err.rfind("vssw: error: ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("assumptions.set: must be one of paper, mechanism, got \"Paper\""), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out"));
}

TEST(CompareResponse, ARecordAndAReleaseAreRefusedTogether) {
    const auto r = run_cli({"compare", "--engine", "analytic", "--pulse", "sine", "--amplitude", "0.5",
                            "--pulse-period", "0.5", "--height", "4", "--thickness", "0.4", "--hinge", "0.7", "--theta0",
                            "0.3"});
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("--theta0 is a release for the free vibration"), std::string::npos) << r.err;
    const auto both = run_cli({"compare", "--engine", "analytic", "--pulse", "sine", "--record", "x.AT2", "--height",
                               "4", "--thickness", "0.4", "--hinge", "0.7"});
    EXPECT_EQ(both.code, 2);
    EXPECT_NE(both.err.find("either --record or --pulse"), std::string::npos) << both.err;
}

// compare reads a record the way a study does (with its times): --record-dt is refused saying so, not read as a
// two-column file and refused for its numbers (it said "expected 2 numbers (time, acceleration)").
TEST(CompareResponse, ARecordFormatOptionIsRefusedSayingWhy) {
    const TempDir dir;
    const std::string record = write_file(dir / "acc.txt", "0.01\n0.02\n-0.01\n0.0\n").string();
    const auto r = run_cli({"compare", "--engine", "analytic", "--record", record, "--record-dt", "0.001", "--pga",
                            "0.3", "--height", "4", "--thickness", "0.4", "--hinge", "0.7"});
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("--record-dt"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("not yet by compare"), std::string::npos) << r.err;
}

// More shards than cases: a shard with no case writes empty results, and the shards still merge into the study.
TEST(StudyCli, AnEmptyShardIsEmptyResultsNotAnError) {
    const TempDir dir;
    const std::string file = write_file(dir / "s.toml", kStudy).string();
    ASSERT_EQ(run_cli({"study", file, "--out", (dir / "one").string(), "--no-plots"}).code, 0);
    for (const char* k : {"1", "2", "3"}) {
        const auto r = run_cli({"study", file, "--out", (dir / k).string(), "--shard", std::string(k) + "/3", "--no-plots"});
        ASSERT_EQ(r.code, 0) << r.err;
    }
    ASSERT_EQ(run_cli({"study", "merge", (dir / "1").string(), (dir / "2").string(), (dir / "3").string(), "--out",
                       (dir / "m").string(), "--no-plots"})
                  .code,
              0);
    EXPECT_EQ(vssw::testing::read_file(dir / "one" / "results.csv"), vssw::testing::read_file(dir / "m" / "results.csv"));
}

// --strict judges the rows of a study that a --resume finds finished, as it judged them when they were written.
TEST(StudyCli, StrictJudgesAFinishedStudyOnResumeToo) {
    const TempDir dir;
    const std::string file = write_file(dir / "s.toml", kFailingStudy)
                                 .string();
    const std::string out = (dir / "a").string();
    EXPECT_EQ(run_cli({"study", file, "--out", out, "--no-plots", "--strict"}).code, 3);
    const auto again = run_cli({"study", file, "--out", out, "--no-plots", "--strict", "--resume"});
    EXPECT_EQ(again.code, 3) << again.out;
    EXPECT_NE(again.out.find("1 failed"), std::string::npos) << again.out;
}

// A harmonic of 2e7 cycles is refused by `vssw history`; in a study it made the folder and exited 0 with every row
// "failed: harmonic cycles ...". Refused as bad input before any folder, naming the case.
TEST(StudyCli, AHarmonicOfTooManyCyclesIsRefusedBeforeAnyFolder) {
    const TempDir dir;
    const std::string out = (dir / "out").string();
    const std::string file = write_file(dir / "h.toml", "metrics = [\"peak_rotation\"]\n[wall]\nheight = 4\n"
                                                        "thickness = 0.4\nhinge = 0.7\n[excitation]\nkind = \"pulse\"\n"
                                                        "shape = \"harmonic\"\namplitude = 0.3\npulse_period = 0.5\n"
                                                        "duration = [10.0, 1e7]\n")
                                 .string();
    const auto r = run_cli({"study", file, "--out", out, "--no-plots"});
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("case 2 ("), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("harmonic cycles (duration / period T) must be at most 1e+06"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("got 20000000"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out));
}

// impact = 0 gave rows "failed: no impact within the run" while `vssw free --impact 0` lists one impact: a study
// measures impacts as crossings of upright, and a wall that stops there makes none. Refused saying so. impact = 1 gave
// "a theta1_dot ratio of 1, outside (0, 1]": the ratio measured (the set paper's model) is just above 1, and now says
// so.
TEST(StudyCli, ImpactRatiosAtTheEndsOfTheirRangeAreExplained) {
    const TempDir dir;
    const std::string study = "metrics = [\"period\", \"restitution\"]\n[wall]\nheight = 4\nthickness = 0.4\n"
                              "hinge = 0.7\n[excitation]\nkind = \"free\"\ntheta0 = 0.5\n[assumptions]\nset = \"paper\"\n"
                              "impact = ";
    const std::string zero = write_file(dir / "zero.toml", study + "[0.5, 0.0]\n").string();
    const auto refused = run_cli({"study", zero, "--out", (dir / "zero").string(), "--no-plots"});
    EXPECT_EQ(refused.code, 2);
    EXPECT_NE(refused.err.find("assumptions.impact: 0 stops the wall at its first return to upright"),
              std::string::npos)
        << refused.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "zero"));

    const std::string one = write_file(dir / "one.toml", study + "1.0\n").string();
    const auto r = run_cli({"study", one, "--out", (dir / "one").string(), "--no-plots"});
    ASSERT_EQ(r.code, 0) << r.err;
    const std::string csv = vssw::testing::read_file(dir / "one" / "results.csv");
    EXPECT_NE(csv.find(", above 1, outside (0, 1]: the wall gained energy"), std::string::npos) << csv;
    EXPECT_EQ(csv.find("ratio of 1, outside"), std::string::npos) << csv;
}

}  // namespace

// Results folders (io/folder_swap.hpp) ---------------------------------------------------------------------------

namespace {

std::string record_text() {
    std::string text;
    for (int i = 0; i < 1000; ++i) text += std::to_string(i * 0.01) + "," + std::to_string(0.5 * std::sin(i * 0.05)) + "\n";
    return text;
}

}  // namespace

// A study whose record or study file is one of the files it writes in --out is refused before anything is written,
// naming the file (both were replaced by the results, exit 0).
TEST(StudyCli, AStudyDoesNotOverwriteItsOwnInputs) {
    const TempDir dir;
    const std::string record = record_text();
    write_file(dir / "results.csv", record);
    const std::string study = "name = \"c\"\nmetrics = [\"peak_rotation\"]\n[wall]\nheight = 4.0\nthickness = 0.4\n"
                              "hinge = [0.6, 0.7]\n[excitation]\nkind = \"record\"\nfile = \"results.csv\"\n";
    const std::string file = write_file(dir / "s.toml", study).string();
    auto r = run_cli({"study", file, "--out", dir.path.string(), "--no-plots"});
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("the record '" + (dir / "results.csv").string() + "' is the file"), std::string::npos) << r.err;
    EXPECT_EQ(vssw::testing::read_file(dir / "results.csv"), record);
    EXPECT_FALSE(std::filesystem::exists(dir / "manifest.json"));

    // The study file named results.json, --out spelled another way.
    const std::string json = R"({"name": "j", "metrics": ["period"], "wall": {"height": 4, "thickness": 0.4,
        "hinge": 0.7}, "excitation": {"kind": "free", "theta0": 0.5}})";
    std::filesystem::create_directories(dir / "j");
    const std::string jfile = write_file(dir / "j" / "results.json", json).string();
    r = run_cli({"study", jfile, "--out", (dir / "j" / ".." / "j" / ".").string(), "--no-plots"});
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("the study file '" + jfile + "' is the file"), std::string::npos) << r.err;
    EXPECT_EQ(vssw::testing::read_file(jfile), json);
}

// A study and a report in one folder would replace each other's results.json: each is refused, naming what the
// folder holds.
TEST(StudyCli, AStudyAndAReportRefuseEachOthersFolder) {
    const TempDir dir;
    const std::string file = write_file(dir / "s.toml", kStudy).string();
    const std::string study = (dir / "study").string(), report = (dir / "report").string();
    ASSERT_EQ(run_cli({"study", file, "--out", study, "--no-plots"}).code, 0);
    ASSERT_EQ(run_cli({"report", "--engines", "analytic", "--cases", "fig6-vssw", "--no-plots", "--out", report}).code,
              0);
    const std::string study_json = vssw::testing::read_file(dir / "study" / "results.json");
    auto r = run_cli({"report", "--engines", "analytic", "--cases", "fig6-vssw", "--no-plots", "--out", study});
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("--out '" + study + "' holds a study's results"), std::string::npos) << r.err;
    EXPECT_EQ(vssw::testing::read_file(dir / "study" / "results.json"), study_json);
    r = run_cli({"study", file, "--out", report, "--no-plots"});
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("--out '" + report + "' holds a report"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "report" / "manifest.json"));
}

// Resuming a finished incremental dynamic analysis rewrites its outputs in place: ida.csv is the study's own file (it
// was carried over as a user's file and clashed with the new one: "cannot carry its other files over").
TEST(StudyCli, AFinishedIdaResumesAndRewritesItsOutputs) {
    const TempDir dir;
    const std::string file = write_file(dir / "ida.toml", "engines = [\"analytic\"]\n[wall]\nheight = 4\n"
                                                          "thickness = 0.4\nhinge = 0.7\n[excitation]\n"
                                                          "kind = \"scale-to-collapse\"\nfile = \"" +
                                                              std::string(VSSW_DATA_DIR) + "/elcentro_chopra.txt\"\n")
                                     .string();
    const std::string out = (dir / "out").string();
    ASSERT_EQ(run_cli({"study", file, "--out", out, "--no-plots"}).code, 0);
    ASSERT_TRUE(std::filesystem::exists(dir / "out" / "ida.csv"));
    const auto again = run_cli({"study", file, "--out", out, "--no-plots", "--resume"});
    EXPECT_EQ(again.code, 0) << again.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "out" / "ida.csv"));
}

// The folder is replaced whole: a second study leaves none of the first's files, and the files that are not vssw's
// (a user's notes, study_slurm.sh's shards/) are carried over.
TEST(StudyCli, ASecondStudyReplacesTheFolderWholeAndKeepsTheUsersFiles) {
    const TempDir dir;
    const std::string file = write_file(dir / "s.toml", kStudy).string(), out = (dir / "out").string();
    ASSERT_EQ(run_cli({"study", file, "--out", out, "--no-plots"}).code, 0);
    write_file(dir / "out" / "notes.txt", "mine\n");
    std::filesystem::create_directories(dir / "out" / "shards" / "1-of-2");
    write_file(dir / "out" / "shards" / "1-of-2" / "log.txt", "a log\n");
    write_file(dir / "out" / "plots" / "stale.svg", "an old plot\n");
    const std::string other = write_file(dir / "o.toml", std::string(kStudy) + "\n[settings.analytic]\nrtol = 1e-9\n")
                                  .string();
    const auto r = run_cli({"study", other, "--out", out, "--no-plots"});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(vssw::testing::read_file(dir / "out" / "notes.txt"), "mine\n");
    EXPECT_EQ(vssw::testing::read_file(dir / "out" / "shards" / "1-of-2" / "log.txt"), "a log\n");
    EXPECT_FALSE(std::filesystem::exists(dir / "out" / "plots")) << "the old run's plots/ went with the old folder";
    for (const auto& e : std::filesystem::directory_iterator(dir.path))
        EXPECT_EQ(e.path().filename().string().find(".vssw-tmp-"), std::string::npos) << e.path();
    EXPECT_NE(r.out.find("  " + out + "/results.json"), std::string::npos) << "named where it is now: " << r.out;
}

namespace {

// A refused study leaves no folder behind: --resume of a folder that is not there used to create it (empty) first.
TEST(StudyCli, AResumeOfAFolderThatIsNotThereIsRefusedAndMakesNone) {
    const TempDir dir;
    const std::string file = write_file(dir / "s.toml", kStudy).string(), out = (dir / "out").string();
    const auto r = run_cli({"study", file, "--out", out, "--resume", "--no-plots"});
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("does not exist"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out"));
}

}  // namespace

namespace {

// A step too coarse for a case's ground motion is refused before any folder is made, naming the case and the run
// (it gave rows "ok" with a peak of 0, exit 0).
TEST(StudyCli, AStepTooCoarseForACaseIsRefusedBeforeAnything) {
    if (!vssw::testing::engine_available("ode")) GTEST_SKIP() << "ODE is not built";
    const TempDir dir;
    const std::string file = write_file(dir / "s.toml", R"(
metrics = ["peak_rotation"]
engines = ["analytic", "ode"]
[wall]
height = 4
thickness = 0.4
hinge = 0.7
[excitation]
kind = "pulse"
shape = "sine"
amplitude = 0.5
pulse_period = 0.5
[settings.ode]
dt = [0.001, 1000.0]
)").string();
    const auto r = run_cli({"study", file, "--out", (dir / "out").string(), "--no-plots"});
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("case 1 (ode dt=1000)"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("for the ground motion"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out"));
}

// Every class of value a study's runs cannot honour is refused while the file is read, exit 2 naming the key (or
// engine and setting) and value, before the folder exists: a step of more than 1e8 steps in a free vibration, a
// threshold and under a pulse; a setting for a parapet only on a VSSW and one for a VSSW only on a parapet; a PGA,
// scale or ensemble level whose scale factor overflows; a collapse search's max_pga below the wall's threshold; a
// fractional iteration count.
TEST(StudyCli, EveryValueARunCannotHonourIsRefusedBeforeTheFolder) {
    const std::string wall = "[wall]\nheight = 4\nthickness = 0.4\nhinge = 0.7\n";
    const std::string parapet = "[wall]\nmodel = \"parapet\"\nheight = 2\nthickness = 0.3\n";
    const std::string record = std::string(VSSW_DATA_DIR) + "/records/northridge1994-rinaldi-228.at2";
    const std::string free = "[excitation]\nkind = \"free\"\ntheta0 = 0.5\n";
    const std::string pulse = "[excitation]\nkind = \"pulse\"\nshape = \"sine\"\namplitude = 0.5\npulse_period = 0.5\n";
    const std::string on_record = "[excitation]\nkind = \"record\"\nfile = \"" + record + "\"\n";
    const std::string other = std::string(VSSW_DATA_DIR) + "/records/northridge1994-pacoimadam-ew.at2";
    const std::string ensemble = "[excitation]\nkind = \"ensemble\"\nfiles = [\"" + record + "\", \"" + other +
                                 "\"]\nintensity = \"pga\"\n";
    struct Case {
        const char* engine;  // needed in this build ("" for none)
        std::string body;    // after metrics and engines
        std::vector<std::string> expected;
    };
    const std::vector<Case> cases = {
        {"ode", wall + free + "[settings.ode]\ndt = 1e-9\n", {"dt = 1e-09", "more than the 1e+08 allowed"}},
        {"ode", wall + pulse + "[settings.ode]\ndt = 1e-9\n", {"dt = 1e-09", "more than the 1e+08 allowed"}},
        {"mujoco", wall + free + "[settings.mujoco]\ndt = 1e-310\n", {"steps", "more than the 1e+08 allowed"}},
        {"mujoco", wall + free + "[settings.mujoco]\nnoslip_iterations = 2.5\n", {"noslip_iterations", "whole number"}},
        {"box2d", wall + pulse + "[settings.box2d]\nskin = 0.05\n", {"Box2D setting skin = 0.05", "parapet wall only"}},
        {"siconos", parapet + free + "[settings.siconos]\ne_hinge = 0.5\n",
         {"Siconos setting e_hinge = 0.5", "VSSW (two blocks and a roller) only"}},
        {"", wall + on_record + "pga = [1e308]\n", {"pga 1e+308", "overflows"}},
        {"", wall + on_record + "scale = [1e308]\n", {"scale 1e+308", "overflows"}},
        {"", wall + ensemble + "levels = [1e308]\n", {"pga 1e+308", "overflows"}},
        {"", wall + ensemble + "collapse = true\nmax_pga = 0.1\n", {"max_pga 0.1 g is not above", "threshold"}},
        {"", wall + ensemble + "collapse = true\nmax_pga = 1e-310\n", {"max_pga 1e-310 g is not above"}},
    };
    for (const Case& c : cases) {
        if (*c.engine && !vssw::testing::engine_available(c.engine)) continue;
        const TempDir dir;
        const std::string engines = *c.engine ? std::string("engines = [\"analytic\", \"") + c.engine + "\"]\n" : "";
        const std::string metrics = c.body.find("ensemble") != std::string::npos && c.body.find("collapse") != std::string::npos
                                        ? "metrics = [\"collapse_pga\"]\n"
                                        : c.body.find("free") != std::string::npos ? "metrics = [\"period\"]\n"
                                                                                  : "metrics = [\"peak_rotation\"]\n";
        const std::string file = write_file(dir / "s.toml", metrics + engines + c.body).string();
        const auto r = run_cli({"study", file, "--out", (dir / "out").string(), "--no-plots"});
        EXPECT_EQ(r.code, 2) << c.body << r.err;
        for (const std::string& e : c.expected) EXPECT_NE(r.err.find(e), std::string::npos) << e << " in: " << r.err;
        EXPECT_FALSE(std::filesystem::exists(dir / "out")) << c.body;
    }
}

}  // namespace


namespace {

// A row failed for its budget depends on --run-budget: the manifest says which was given (null: the default).
TEST(StudyCli, TheManifestRecordsTheRunBudget) {
    const TempDir dir;
    const std::string file = write_file(dir / "s.toml", kStudy).string();
    ASSERT_EQ(run_cli({"study", file, "--out", (dir / "given").string(), "--no-plots", "--run-budget", "50"}).code, 0);
    ASSERT_EQ(run_cli({"study", file, "--out", (dir / "default").string(), "--no-plots"}).code, 0);
    const auto given = nlohmann::json::parse(vssw::testing::read_file(dir / "given" / "manifest.json"));
    const auto by_default = nlohmann::json::parse(vssw::testing::read_file(dir / "default" / "manifest.json"));
    EXPECT_EQ(given["run_budget_s"], 50.0);
    EXPECT_TRUE(by_default["run_budget_s"].is_null());
}

}  // namespace

// Two commands on one --out: every command that writes a results folder holds its lock (io/folder_lock.hpp) from its
// check of --out to its swap, so a second one meanwhile is refused up front, naming the first's process, and the
// folder holds only the first's files. Here this process holds the lock (a flock is per open file: the command run
// in-process is refused as another process would be).
TEST(StudyCli, AnOutFolderInUseIsRefusedToEveryCommandThatWritesOne) {
    namespace fs = std::filesystem;
    const TempDir dir;
    const std::string file = write_file(dir / "s.toml", kStudy).string();
    ASSERT_TRUE(run_two_shards(dir, file));
    ASSERT_EQ(run_cli({"study", file, "--out", (dir / "resumed").string(), "--no-plots"}).code, 0);
    const std::string busy = (dir / "busy").string();
    const std::vector<std::vector<std::string>> commands = {
        {"study", file, "--out", busy, "--no-plots"},
        {"study", "merge", (dir / "1").string(), (dir / "2").string(), "--out", busy, "--no-plots"},
        {"motions", "generate", "--count", "1", "--seed", "1", "--out", busy},
        {"report", "--cases", "fig6-vssw", "--engines", "analytic", "--no-plots", "--out", busy},
        {"bench", "--quick", "--engines", "analytic", "--no-plots", "--out", busy},
        {"stress", "--quick", "--engines", "analytic", "--cases", "xi-50", "--out", busy},
    };
    const std::string named = "is in use by another vssw command (process " + std::to_string(getpid()) + ")";
    for (const bool exists : {false, true}) {
        if (exists) {
            fs::create_directories(dir / "busy");
            write_file(dir / "busy" / "notes.txt", "the user's\n");
        }
        const vssw::io::FolderLock held = vssw::io::check_out_folder(busy, vssw::io::OutKind::study);
        for (const std::vector<std::string>& command : commands) {
            const auto r = run_cli(command);
            EXPECT_EQ(r.code, 2) << command[0] << ": " << r.err;
            EXPECT_NE(r.err.find("--out '" + busy + "' " + named), std::string::npos) << command[0] << ": " << r.err;
            std::vector<std::string> names;
            std::error_code ec;
            for (const fs::directory_entry& e : fs::directory_iterator(dir / "busy", ec))
                names.push_back(e.path().filename().string());
            EXPECT_EQ(names, exists ? std::vector<std::string>{"notes.txt"} : std::vector<std::string>{}) << command[0];
            EXPECT_EQ(fs::exists(dir / "busy"), exists) << command[0] << ": no folder made";
        }
    }
    // A --resume of a folder in use, too.
    const vssw::io::FolderLock held = vssw::io::check_out_folder(dir / "resumed", vssw::io::OutKind::study);
    const auto r = run_cli({"study", file, "--out", (dir / "resumed").string(), "--resume", "--no-plots"});
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find(named), std::string::npos) << r.err;
}

// The swap checks the folder again: a command that did not take the lock (an older vssw) and wrote its results there
// meanwhile is not mixed in; the swap fails naming them, and the folder is as that command left it.
TEST(StudyCli, TheSwapRefusesAFolderAnotherCommandFilledMeanwhile) {
    namespace fs = std::filesystem;
    const TempDir dir;
    const fs::path out = dir / "out";
    fs::create_directories(out);
    const vssw::io::FolderLock lock = vssw::io::check_out_folder(out, vssw::io::OutKind::study);
    vssw::io::StagedFolder staged(out, vssw::io::OutKind::study);
    staged.create();
    write_file(staged.path() / "results.csv", "case_id\n");
    write_file(out / "motions.csv", "file\n");  // the other command's, written after our check
    try {
        staged.commit();
        ADD_FAILURE() << "the swap mixed the folders";
    } catch (const vssw::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("holds generated motions (motions.csv)"), std::string::npos) << e.what();
    }
    EXPECT_TRUE(fs::exists(out / "motions.csv"));
    EXPECT_FALSE(fs::exists(out / "results.csv"));
}
