// Work-precision (validation/work_precision.hpp, validation/bench_files.hpp, `vssw bench`): the order fitted from a sweep on
// integrators of known order, the Pareto front and the cheapest settings on hand-made points, and the command's
// files from a quick sweep.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <algorithm>
#include <functional>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "compare/targets.hpp"
#include "validation/bench_spec.hpp"
#include "validation/work_precision.hpp"
#include "validation/bench_files.hpp"
#include "io/csv.hpp"
#include "temp_files.hpp"

namespace vssw {
namespace {

using validation::BenchPoint;
using validation::CpuTiming;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// The fitted order may differ from the nominal one by the next term of the error's expansion: at the steps below
// (h <= 0.1 on y' = -y over one time constant) that term changes the log-log slope by less than 0.1.
constexpr double kOrderTolerance = 0.15;

// y' = -y from y(0) = 1 to t = 1 in n fixed steps of a one-step method; the error against exp(-1).
double euler_error(int n) {
    const double h = 1.0 / n;
    double y = 1.0;
    for (int i = 0; i < n; ++i) y += h * -y;
    return std::abs(y - std::exp(-1.0));
}

double rk4_error(int n) {
    const double h = 1.0 / n;
    double y = 1.0;
    for (int i = 0; i < n; ++i) {
        const double k1 = -y, k2 = -(y + 0.5 * h * k1), k3 = -(y + 0.5 * h * k2), k4 = -(y + h * k3);
        y += h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
    return std::abs(y - std::exp(-1.0));
}

// Least-squares slope of log(y) on log(x) over the points where both are finite and > 0 (NaN with fewer than two):
// the order of convergence when x is the step and y the error (only the tests fit one; `vssw bench` draws the
// diagram).
double loglog_slope(const std::vector<double>& x, const std::vector<double>& y) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int n = 0;
    for (std::size_t i = 0; i < std::min(x.size(), y.size()); ++i) {
        if (!(std::isfinite(x[i]) && std::isfinite(y[i]) && x[i] > 0.0 && y[i] > 0.0)) continue;
        const double lx = std::log(x[i]), ly = std::log(y[i]);
        sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
        ++n;
    }
    const double d = n * sxx - sx * sx;
    if (n < 2 || d == 0.0) return kNaN;
    return (n * sxy - sx * sy) / d;
}

// A sweep over the step as `vssw bench` makes one: each point timed by time_cpu, its error kept; the order fitted on
// error against step.
double fitted_order(const std::function<double(int)>& error_of) {
    std::vector<double> steps, errors;
    for (int n : {10, 20, 40, 80, 160}) {
        double error = kNaN;
        const CpuTiming t = validation::time_cpu([&] { error = error_of(n); }, 3);
        EXPECT_EQ(t.repeats.size(), 3u);
        steps.push_back(1.0 / n);
        errors.push_back(error);
    }
    return loglog_slope(steps, errors);
}

TEST(WorkPrecision, ErrorFallsWithTheStepAtTheFittedOrder) {
    EXPECT_NEAR(fitted_order(euler_error), 1.0, kOrderTolerance);
    EXPECT_NEAR(fitted_order(rk4_error), 4.0, kOrderTolerance);
}

TEST(WorkPrecision, SlopeNeedsTwoUsablePoints) {
    EXPECT_TRUE(std::isnan(loglog_slope({1e-3}, {1e-6})));
    // Zero and NaN errors are left out (a log-log fit cannot use them); the two others give slope 2.
    EXPECT_DOUBLE_EQ(loglog_slope({1.0, 2.0, 3.0, 4.0}, {1.0, 4.0, 0.0, kNaN}), 2.0);
}

TEST(WorkPrecision, MedianOfRepeats) {
    EXPECT_DOUBLE_EQ(validation::median_of({3.0, 1.0, 2.0}), 2.0);
    EXPECT_DOUBLE_EQ(validation::median_of({4.0, 1.0, 2.0, 3.0}), 2.5);
    EXPECT_TRUE(std::isnan(validation::median_of({})));
}

TEST(WorkPrecision, ParetoFrontOnHandMadePoints) {
    //                       0    1    2    3    4    5     6
    const std::vector<double> cost = {1.0, 2.0, 3.0, 0.5, 2.0, 1.0, 4.0};
    const std::vector<double> error = {1.0, 0.5, 0.6, 2.0, 0.5, 1.5, kNaN};
    const std::vector<bool> front = validation::pareto_front(cost, error);
    // 2 is beaten by 1 on both; 5 by 0 on error at equal cost; 6 has no error. 1 and 4 tie: neither dominates.
    EXPECT_EQ(front, (std::vector<bool>{true, true, false, true, true, false, false}));
}

BenchPoint point(std::string engine, std::string problem, std::string metric, std::string setting, double cpu,
                 double error) {
    BenchPoint p;
    p.engine = std::move(engine), p.problem = std::move(problem), p.metric = std::move(metric);
    p.setting = std::move(setting);
    p.cpu.median = cpu;
    p.cpu.repeats = {cpu};
    p.value = 1.0 + error, p.reference = 1.0, p.error = error;
    return p;
}

TEST(WorkPrecision, CheapestSettingMeetsEveryTarget) {
    const double period_ok = compare::kPeriodTarget / 2, period_off = compare::kPeriodTarget * 2;
    const double rest_ok = compare::kRestitutionTarget / 2, rest_off = compare::kRestitutionTarget * 2;
    // "fast" misses the restitution target, "mid" meets both, "slow" meets both at more cost; the peak has no target.
    const std::vector<BenchPoint> points = {
        point("e", "fig6-free", "period", "fast", 1.0, period_ok),
        point("e", "fig6-free", "restitution", "fast", 1.0, rest_off),
        point("e", "fig6-free", "period", "mid", 2.0, period_ok),
        point("e", "fig6-free", "restitution", "mid", 2.0, rest_ok),
        point("e", "record", "peak", "mid", 5.0, 0.3),
        point("e", "fig6-free", "period", "slow", 3.0, period_off / 4),
        point("e", "fig6-free", "restitution", "slow", 3.0, rest_ok),
        point("e", "record", "peak", "slow", 5.0, 0.1),
        point("f", "fig6-free", "period", "only", 1.0, period_off),
        point("f", "fig6-free", "restitution", "only", 1.0, rest_ok),
    };
    const std::vector<validation::Cheapest> c = validation::cheapest_within_targets(points, {"e", "f"});
    ASSERT_EQ(c.size(), 2u);
    ASSERT_TRUE(c[0].setting.has_value());
    EXPECT_EQ(*c[0].setting, "mid");
    EXPECT_DOUBLE_EQ(c[0].cpu_s, 2.0 + 5.0);  // each problem's run counted once
    ASSERT_EQ(c[0].per_metric.size(), 2u);
    EXPECT_EQ(points[*c[0].per_metric[0].second].setting, "fast");  // period alone: the fast one meets it
    EXPECT_EQ(points[*c[0].per_metric[1].second].setting, "mid");
    EXPECT_FALSE(c[1].setting.has_value());
    EXPECT_FALSE(c[1].per_metric[0].second.has_value());  // f's period misses
}

TEST(WorkPrecision, FailedPointIsNeverCheapest) {
    BenchPoint failed = point("e", "fig6-free", "period", "cheap", 0.1, kNaN);
    failed.failure = "blew up";
    const std::vector<BenchPoint> points = {failed, point("e", "fig6-free", "period", "dear", 1.0, 0.0)};
    const std::vector<validation::Cheapest> c = validation::cheapest_within_targets(points, {"e"});
    ASSERT_TRUE(c[0].setting.has_value());
    EXPECT_EQ(*c[0].setting, "dear");
}

// The command end to end ----------------------------------------------------------------------------------------

std::vector<std::vector<std::string>> read_csv(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::vector<std::vector<std::string>> rows;
    std::vector<std::string> fields;
    while (io::read_csv_record(in, fields)) rows.push_back(fields);
    return rows;
}

// A reference the analytic model could not measure used to leave its problem's points without errors, exit 0.
TEST(WorkPrecision, AnUnmeasuredReferenceIsAFailureNamingTheProblemAndMetric) {
    EXPECT_NO_THROW(validation::require_measured_references("fig6-free", {{"period", 1.67}, {"restitution", 0.95}}));
    try {
        validation::require_measured_references("fig6-free", {{"period", 1.67}, {"restitution", std::nan("")}});
        ADD_FAILURE() << "a NaN reference was accepted";
    } catch (const multibody::EngineFailure& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("fig6-free"), std::string::npos) << what;
        EXPECT_NE(what.find("restitution"), std::string::npos) << what;
    }
}

// An engine folder's BENCH text: the first axis outermost, each setting applied to the defaults, the label's {NAME}
// filled from the settings (an axis or a default), groups one after the other.
TEST(BenchSpec, EveryCombinationOfTheAxesOnTheDefaultsLabelledByItsValues) {
    multibody::EngineSettings defaults;
    defaults.dt = 2e-3;
    defaults.knobs["erp"] = 0.2;
    const std::vector<validation::BenchSetting> sweep = validation::expand_bench_spec(
        defaults, "dt={dt} it={iterations}: dt 1e-3 2.5e-4, iterations 4 8|q={quickstep} at {dt}: quickstep 1");
    const std::vector<std::string> labels = {"dt=1e-03 it=4", "dt=1e-03 it=8", "dt=2.5e-04 it=4", "dt=2.5e-04 it=8",
                                             "q=1e+00 at 2e-03"};
    ASSERT_EQ(sweep.size(), labels.size());
    for (std::size_t i = 0; i < labels.size(); ++i) {
        EXPECT_EQ(sweep[i].label, labels[i]);
        EXPECT_EQ(sweep[i].settings.knobs.at("erp"), 0.2) << "a default the text does not name is kept";
    }
    EXPECT_EQ(sweep[2].settings.dt, 2.5e-4);
    EXPECT_EQ(sweep[2].settings.iterations, 4);
    EXPECT_EQ(sweep[4].settings.dt, 2e-3);
    EXPECT_EQ(sweep[4].settings.knobs.at("quickstep"), 1.0);
    EXPECT_TRUE(validation::expand_bench_spec(defaults, "").empty());
}

// A text that does not read as a sweep is the build's fault and is named, not swept as something else.
TEST(BenchSpec, ATextThatIsNotASweepIsRefusedNamingIt) {
    const multibody::EngineSettings defaults;
    for (const char* text : {"dt 1e-3", "dt={dt}: dt 1e-3 fast", "dt={dt}: dt", "a={accuracy}: dt 1e-3", "dt={dt: dt 1"}) {
        try {
            (void)validation::expand_bench_spec(defaults, text);
            ADD_FAILURE() << "accepted: " << text;
        } catch (const std::logic_error& e) {
            EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
        }
    }
}

TEST(BenchCli, QuickSweepWritesFinitePoints) {
    testing::TempDir dir;
    const auto r = testing::run_cli({"bench", "--quick", "--repeats", "1", "--out", dir.path.string()});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("Cheapest settings"), std::string::npos);

    const auto rows = read_csv(dir / "bench.csv");
    ASSERT_GE(rows.size(), 2u);
    const std::vector<std::string> columns = validation::bench_csv_columns();
    ASSERT_EQ(rows[0], columns);
    auto col = [&](const std::string& name) {
        return static_cast<std::size_t>(std::find(columns.begin(), columns.end(), name) - columns.begin());
    };
    for (std::size_t i = 1; i < rows.size(); ++i) {
        const auto& row = rows[i];
        ASSERT_EQ(row.size(), columns.size());
        SCOPED_TRACE(row[col("engine")] + " " + row[col("problem")] + " " + row[col("metric")]);
        ASSERT_FALSE(row[col("error")].empty()) << row[col("failure")];
        const double error = std::stod(row[col("error")]), cpu = std::stod(row[col("cpu_s")]);
        EXPECT_TRUE(std::isfinite(error) && error >= 0.0);
        EXPECT_GT(cpu, 0.0);
        // The analytic model against its own converged run and Eq. (19) / Housner: within every target.
        if (row[col("engine")] == "analytic") {
            const auto target = validation::bench_target(row[col("metric")]);
            ASSERT_TRUE(target.has_value());
            EXPECT_LE(error, *target);
        }
    }

    std::ifstream json_in(dir / "bench.json");
    const nlohmann::json j = nlohmann::json::parse(json_in);
    EXPECT_EQ(j.at("points").size(), rows.size() - 1);
    EXPECT_EQ(j.at("cheapest").size(), j.at("engines").size());
    EXPECT_EQ(j.at("cheapest").at(0).at("engine"), "analytic");
    EXPECT_FALSE(j.at("cheapest").at(0).at("setting").is_null());  // the analytic model meets its targets
    EXPECT_TRUE(std::filesystem::is_regular_file(dir / "bench.md"));
}

TEST(BenchCli, BadInputExitsTwoNamingTheValue) {
    testing::TempDir dir;
    const std::string out = dir.path.string();
    auto r = testing::run_cli({"bench", "--quick", "--out", out, "--repeats", "0"});
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("--repeats"), std::string::npos) << r.err;
    r = testing::run_cli({"bench", "--quick", "--out", out, "--problems", "fig7"});
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("'fig7'"), std::string::npos) << r.err;
    r = testing::run_cli({"bench", "--quick", "--out", out, "--engines", "havok"});
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("'havok'"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "bench.csv"));  // refused before anything ran
}

}  // namespace
}  // namespace vssw

namespace vssw {
namespace {

TEST(BenchCli, ReportIncludesAFinishedBenchFolder) {
    testing::TempDir bench, report;
    auto r = testing::run_cli({"bench", "--quick", "--repeats", "1", "--engines", "analytic", "--problems",
                               "fig6-free", "--out", bench.path.string()});
    ASSERT_EQ(r.code, 0) << r.err;
    r = testing::run_cli({"report", "--engines", "ode", "--cases", "fig6-vssw/r0.5", "--no-plots", "--bench",
                          bench.path.string(), "--out", report.path.string()});
    ASSERT_EQ(r.code, 0) << r.err;
    std::ifstream in(report / "report.md");
    const std::string md((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(md.find("Work-precision (vssw bench)"), std::string::npos);
    EXPECT_NE(md.find("rtol="), std::string::npos);  // the analytic model's cheapest setting, from bench.json
}

TEST(BenchCli, ReportRefusesAFolderWithoutBenchJson) {
    testing::TempDir empty, report;
    const auto r = testing::run_cli({"report", "--engines", "ode", "--cases", "fig6-vssw/r0.5", "--no-plots",
                                     "--bench", empty.path.string(), "--out", report.path.string()});
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("bench.json"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace vssw
