// A record study's ensemble measures (study/ensemble_measures.hpp, study/ensemble_outputs.hpp) on hand-written
// results: the Fig. 6 wall (height 4, thickness 0.4, hinge 0.7) under four records, a stripe part (file x pga) and an
// IDA part (scale-to-collapse), the analytic model under two assumption sets (the preferred reference and Eq. 19's
// impact). What is checked: fragility.csv's median and beta are the log-mean and n-1 standard deviation of
// results.csv's collapse_pga rows; a record that stood to max_pga is counted as censored; agreement.csv's overturning
// agreement is the count of matching rows with the Wilson interval's closed form; the files are the same bytes when
// written twice and when written from a merge of two shards.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "io/csv.hpp"
#include "compare/ensemble_statistics.hpp"
#include "study/ensemble_outputs.hpp"
#include "study/grid.hpp"
#include "study/merge.hpp"
#include "study/outputs.hpp"
#include "study/results_files.hpp"
#include "study/runner.hpp"
#include "study/spec.hpp"
#include "tests/temp_files.hpp"

namespace {

namespace fs = std::filesystem;
namespace st = vssw::study;
using vssw::testing::TempDir;

// csv_number writes 17 significant digits, and the test sums the logs in another order than the library: a few ulps.
constexpr double kRoundOff = 1e-12;
// Phi^-1(0.975), to the digits of compare/ensemble_statistics.hpp.
constexpr double kZ95 = 1.959963984540054;

std::string read(const fs::path& p) { return vssw::testing::read_file(p); }

std::string study_toml() {
    const std::string records = std::string("[\"") + VSSW_DATA_DIR + "/records/kern1952-taft-021.at2\", \"" +
                                VSSW_DATA_DIR + "/records/borrego1968-elcentro9-180.at2\", \"" + VSSW_DATA_DIR +
                                "/records/landers1992-yermo-ew.at2\", \"" + VSSW_DATA_DIR +
                                "/records/coalinga1983-parkfieldfz14-090.at2\"]";
    return "name = \"ensemble\"\nengines = [\"analytic\"]\n"
           "[assumptions]\nkinematics = \"exact\"\nimpact = [\"whole-mechanism\", \"eq19\"]\nroller = \"unilateral\"\n"
           "[[part]]\n[part.wall]\nheight = 4\nthickness = 0.4\nhinge = 0.7\n"
           "[part.excitation]\nkind = \"record\"\nfile = " + records + "\npga = [0.2, 0.4, 0.6]\n"
           "[[part]]\n[part.wall]\nheight = 4\nthickness = 0.4\nhinge = 0.7\n"
           "[part.excitation]\nkind = \"scale-to-collapse\"\nfile = " + records + "\nmax_pga = 2\n";
}

std::size_t file_index(const st::CaseSpec& c) {
    const std::vector<std::string> stems = {"taft", "elcentro9", "yermo", "parkfield"};
    for (std::size_t i = 0; i < stems.size(); ++i)
        if (c.file.find(stems[i]) != std::string::npos) return i;
    return 0;
}

// The reference (whole-mechanism) collapses at 0.5, 0.7, 0.9 g and stands to max_pga under the fourth record; Eq.
// (19) at 0.4, 0.65, 1.1, 1.3 g. Overturned: at or above those PGAs; peaks 0.1 + pga (Eq. 19: x 1.2).
st::ResultRow value_row(const st::CaseSpec& c, const st::RunSpec& run, std::size_t run_index, std::size_t metric,
                        const std::string& name) {
    const bool eq19 = st::to_text(run.assumptions[1]) == "eq19";
    const std::size_t f = file_index(c);
    const double collapse = eq19 ? std::vector<double>{0.4, 0.65, 1.1, 1.3}[f]
                                 : std::vector<double>{0.5, 0.7, 0.9, NAN}[f];
    st::ResultRow row{c.id, run_index, metric, NAN, "ok", ""};
    if (name == "collapse_pga" || name == "collapse_scale") {
        row.value = collapse;
        if (std::isnan(collapse)) row.status = "failed: does not overturn up to a PGA of 2 g (the last run below max_pga 2.1 g)";
    } else if (name == "overturned") {
        row.value = c.pga_g >= collapse ? 1.0 : 0.0;
    } else {
        row.value = (0.1 + c.pga_g) * (eq19 ? 1.2 : 1.0);
    }
    return row;
}

void write_study(const fs::path& dir, const st::Grid& grid, st::Shard shard = {}) {
    fs::create_directories(dir);
    std::vector<st::ResultRow> rows;
    long tasks = 0;
    for (const int id : grid.shard_case_ids(shard.k, shard.n)) {
        const st::CaseSpec c = grid.make_case(id);
        for (std::size_t r = 0; r < grid.runs().size(); ++r) {
            if (!grid.run_applies(grid.runs()[r], c)) continue;
            ++tasks;
            const std::vector<std::string>& part_metrics = grid.spec().parts[c.part].metrics;
            for (std::size_t m = 0; m < grid.spec().metrics.size(); ++m) {
                const std::string& name = grid.spec().metrics[m];
                if (std::find(part_metrics.begin(), part_metrics.end(), name) == part_metrics.end()) continue;
                rows.push_back(value_row(c, grid.runs()[r], r, m, name));
            }
        }
    }
    {
        std::ofstream out(dir / st::kResultsCsv);
        st::write_results_csv(out, grid, rows);
    }
    st::StudyMeta meta;
    meta.commit = "abc1234";
    meta.date = "2025-01-01T00:00:00Z";
    meta.shard = shard;
    meta.tasks_run = tasks;
    meta.engines.push_back({"analytic", "analytic (test)"});
    std::ofstream(dir / st::kManifestFile) << st::manifest_json(grid, meta).dump(2) << '\n';
}

using Table = std::vector<std::map<std::string, std::string>>;
Table read_table(const fs::path& path) {
    std::istringstream in(read(path));
    std::vector<std::string> header, fields;
    Table rows;
    vssw::io::read_csv_record(in, header);
    while (vssw::io::read_csv_record(in, fields)) {
        if (fields.size() != header.size()) continue;
        std::map<std::string, std::string> row;
        for (std::size_t i = 0; i < header.size(); ++i) row[header[i]] = fields[i];
        rows.push_back(row);
    }
    return rows;
}

class EnsembleStudy : public ::testing::Test {
protected:
    void SetUp() override {  // plots: scripts and data only (gnuplot not run), as without gnuplot
        std::ofstream(dir_.path / "s.toml") << study_toml();
        grid_ = std::make_unique<st::Grid>(st::read_study_file((dir_.path / "s.toml").string()));
        write_study(out(), *grid_);
        st::write_study_outputs(out(), {true, "/nonexistent/gnuplot"});
    }
    fs::path out() const { return dir_.path / "single"; }
    TempDir dir_{TempDir::test_name()};
    std::unique_ptr<st::Grid> grid_;
};

TEST_F(EnsembleStudy, FragilityIsTheLogMomentsOfTheCollapsePgas) {
    std::vector<double> logs;  // Eq. 19's collapse PGAs from results.csv (none censored)
    for (const auto& r : read_table(out() / st::kResultsCsv))
        if (r.at("metric") == "collapse_pga" && r.at("impact") == "eq19") logs.push_back(std::log(std::stod(r.at("value"))));
    ASSERT_EQ(logs.size(), 4u);
    double mean = 0.0, ss = 0.0;
    for (double l : logs) mean += l / static_cast<double>(logs.size());
    for (double l : logs) ss += (l - mean) * (l - mean);
    const double beta = std::sqrt(ss / static_cast<double>(logs.size() - 1));
    const Table fragility = read_table(out() / st::kFragilityCsv);
    ASSERT_EQ(fragility.size(), 2u);
    bool seen_eq19 = false, seen_reference = false;
    for (const auto& row : fragility) {
        EXPECT_EQ(row.at("intensity"), "pga_ida");
        EXPECT_EQ(row.at("seed"), std::to_string(st::kEnsembleSeed));
        EXPECT_EQ(row.at("records"), "4");
        if (row.at("assumptions").find("eq19") != std::string::npos) {
            seen_eq19 = true;
            EXPECT_NEAR(std::stod(row.at("median")), std::exp(mean), kRoundOff * std::exp(mean));
            EXPECT_NEAR(std::stod(row.at("beta")), beta, kRoundOff * beta);
            EXPECT_EQ(row.at("collapsed"), "4");
            EXPECT_FALSE(row.at("median_ratio").empty());
            EXPECT_LE(std::stod(row.at("median_lo")), std::stod(row.at("median")));
            EXPECT_GE(std::stod(row.at("median_hi")), std::stod(row.at("median")));
        } else {
            seen_reference = true;
            EXPECT_EQ(row.at("collapsed"), "3") << "the fourth record stood to max_pga: censored";
            EXPECT_TRUE(row.at("median_ratio").empty());
        }
    }
    EXPECT_TRUE(seen_eq19 && seen_reference);
}

// A stripes-only study at two levels (0.6 and 0.8 g): the maximum likelihood fit passes through both shares
// overturned (1 of 4, then 2 of 4, for both impact laws), ln(x_j / theta) / beta = Phi^-1(share_j), solved here.
TEST(EnsembleStripes, FragilityPassesThroughTheTwoStripesShares) {
    constexpr double kNewtonRoundOff = 1e-9;  // the fit's Newton stops at a log-likelihood gain of 1e-12
    const TempDir dir{TempDir::test_name()};
    std::string toml = study_toml();
    toml = toml.substr(0, toml.find("[[part]]", toml.find("[[part]]") + 1));  // the stripe part alone
    toml.replace(toml.find("pga = [0.2, 0.4, 0.6]"), 21, "pga = [0.6, 0.8]");
    std::ofstream(dir.path / "s.toml") << toml;
    const st::Grid grid(st::read_study_file((dir.path / "s.toml").string()));
    write_study(dir.path / "out", grid);
    st::write_study_outputs(dir.path / "out", {true, "/nonexistent/gnuplot"});
    const double u1 = vssw::compare::normal_quantile(0.25), u2 = vssw::compare::normal_quantile(0.5);
    const double beta = std::log(0.8 / 0.6) / (u2 - u1), median = 0.6 * std::exp(-beta * u1);
    const Table fragility = read_table(dir.path / "out" / st::kFragilityCsv);
    ASSERT_EQ(fragility.size(), 2u);
    for (const auto& row : fragility) {
        EXPECT_EQ(row.at("intensity"), "pga_stripes");
        EXPECT_EQ(row.at("records"), "4");
        EXPECT_EQ(row.at("collapsed"), "3");  // runs overturned over both stripes
        EXPECT_NEAR(std::stod(row.at("median")), median, kNewtonRoundOff);
        EXPECT_NEAR(std::stod(row.at("beta")), beta, kNewtonRoundOff);
        if (!row.at("median_ratio").empty()) {
            EXPECT_EQ(std::stod(row.at("median_ratio")), 1.0);  // the same shares
        }
    }
}

TEST_F(EnsembleStudy, OverturningAgreementIsTheCountWithItsWilsonInterval) {
    std::map<std::tuple<std::string, std::string>, std::map<std::string, std::string>> overturned;
    for (const auto& r : read_table(out() / st::kResultsCsv))
        if (r.at("metric") == "overturned") overturned[{r.at("file"), r.at("pga")}][r.at("impact")] = r.at("value");
    long n = 0, k = 0;
    for (const auto& [key, by_impact] : overturned) {
        ++n;
        k += by_impact.at("eq19") == by_impact.at("whole-mechanism") ? 1 : 0;
    }
    ASSERT_EQ(n, 12);
    const double p = static_cast<double>(k) / static_cast<double>(n), nn = static_cast<double>(n);
    const double centre = (p + kZ95 * kZ95 / (2 * nn)) / (1 + kZ95 * kZ95 / nn);
    const double half = kZ95 / (1 + kZ95 * kZ95 / nn) * std::sqrt(p * (1 - p) / nn + kZ95 * kZ95 / (4 * nn * nn));
    bool seen = false;
    for (const auto& row : read_table(out() / st::kAgreementCsv)) {
        if (row.at("measure") != "overturning_agreement") continue;
        seen = true;
        EXPECT_NE(row.at("assumptions").find("eq19"), std::string::npos) << "the reference is not compared";
        EXPECT_NE(row.at("reference").find("whole-mechanism"), std::string::npos);
        EXPECT_EQ(row.at("n"), std::to_string(n));
        EXPECT_NEAR(std::stod(row.at("value")), p, kRoundOff);
        EXPECT_NEAR(std::stod(row.at("lo")), centre - half, kRoundOff);
        EXPECT_NEAR(std::stod(row.at("hi")), centre + half, kRoundOff);
    }
    EXPECT_TRUE(seen);
    EXPECT_NE(read(out() / st::kStudyMarkdown).find("## Ensemble"), std::string::npos);
}

TEST_F(EnsembleStudy, FilesAreTheSameBytesRewrittenAndMerged) {
    const std::string fragility = read(out() / st::kFragilityCsv), agreement = read(out() / st::kAgreementCsv);
    const std::string dat = read(out() / st::kPlotsDir / "fragility.dat");
    st::write_study_outputs(out(), {true, "/nonexistent/gnuplot"});
    EXPECT_EQ(read(out() / st::kFragilityCsv), fragility);
    EXPECT_EQ(read(out() / st::kAgreementCsv), agreement);
    EXPECT_EQ(read(out() / st::kPlotsDir / "fragility.dat"), dat);
    for (int k = 1; k <= 2; ++k) write_study(dir_.path / ("shard" + std::to_string(k)), *grid_, {k, 2});
    st::merge_studies({dir_.path / "shard1", dir_.path / "shard2"}, dir_.path / "merged");
    st::write_study_outputs(dir_.path / "merged", {true, "/nonexistent/gnuplot"});
    EXPECT_EQ(read(dir_.path / "merged" / st::kFragilityCsv), fragility);
    EXPECT_EQ(read(dir_.path / "merged" / st::kAgreementCsv), agreement);
    EXPECT_EQ(read(dir_.path / "merged" / st::kPlotsDir / "fragility.dat"), dat);
}

}  // namespace
