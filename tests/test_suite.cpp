// The validation suite's runner (validation/suite.hpp): what the shipped suites hold, case selection, and run_suite's
// behaviour (analytic reference rows, determinism across threads, failures kept per case, engines that must not run
// concurrently). Physics is checked where the suite states it: thresholds against Eq. (12) / Eq. (17), restitution
// against Eq. (19) and the whole mechanism's plastic impact, records scaled to rock the analytic wall without
// overturning it. Fast: the analytic engine (and fakes built on it), plus two cheap engine cases when compiled in.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "analytic/closed_forms.hpp"
#include "analytic/error.hpp"
#include "analytic/ground_motion.hpp"
#include "compare/experiments.hpp"
#include "validation/suite.hpp"
#include "validation/suite_file.hpp"
#include "compare/targets.hpp"
#include "multibody/host/analytic_engine.hpp"
#include "multibody/engine.hpp"
#include "tests/engine_available.hpp"

namespace vssw::compare {
namespace {

using multibody::AnalyticEngine;
using multibody::EngineFailure;
using multibody::EngineSettings;
using multibody::Excitation;
using multibody::Trajectory;
using multibody::WallScene;

// find_threshold's bracket is 1e-4 wide relative (ThresholdOptions::rel_tol); its mid-point is within half of that
// of the threshold, plus the bias of an undetected excess of at most 1e-5: 1e-4 covers both.
constexpr double kBisectionTol = 1e-4;
// The first-impact ratio read from samples 0.1 ms apart (the analytic engine's default output): the crossing is
// misplaced by up to 0.05 dt and the velocities extrapolated over 3 dt (metrics.hpp); measured scatter on the Fig. 6
// walls is 2e-5 around Eq. (19) and Housner's e. 2e-4 is ten times that.
constexpr double kImpactSamplingTol = 2e-4;
// A record "rocks the wall clearly": its peak is at least this fraction of alpha (the smallest of the four, the
// Fig. 6 VSSW under Rinaldi x 0.45, is 0.27).
constexpr double kClearRocking = 0.1;
// ...and stays below alpha, the rest position's static instability (a PW falls past it; the VSSW's unstable
// equilibrium is at 0.98 alpha1, its collapse angle Eq. 26 at 4.3 alpha1): the largest of the four is 0.47.
constexpr double kBelowInstability = 1.0;
// The project's targets, as the cross-engine suite asserts them (compare/targets.hpp).
using vssw::compare::kPeriodTarget;
using vssw::compare::kRestitutionTarget;
// A trace holds at most this many points (suite.cpp decimates to 2000 for the plots).
constexpr std::size_t kMaxTracePoints = 2000;

validation::Suite default_suite() { return vssw::validation::read_suite("default", VSSW_DATA_DIR); }

using vssw::testing::engine_available;

const validation::MetricRow* find_row(const validation::SuiteResults& r, const std::string& case_id, const std::string& engine,
                          const std::string& metric) {
    for (const validation::MetricRow& row : r.rows)
        if (row.case_id == case_id && row.engine == engine && row.metric == metric) return &row;
    return nullptr;
}

bool same_number(double a, double b) { return (std::isnan(a) && std::isnan(b)) || a == b; }

// The analytic model under another name: its rows must equal the reference's exactly (same runs, same sampling).
// `fail_parapet`: an EngineFailure on every parapet scene. `exclusive`: runs_concurrently() false, and it counts
// how many of its simulate() calls overlap.
class FakeEngine final : public multibody::Engine {
public:
    double cost_per_simulated_second() const override { return 1e-3; }  // a test double: never timed
    FakeEngine(std::string name, bool fail_parapet, bool exclusive)
        : name_(std::move(name)), fail_parapet_(fail_parapet), exclusive_(exclusive) {}
    std::string name() const override { return name_; }
    std::string version() const override { return "fake 1.0"; }
    multibody::EngineSettings default_settings() const override { return analytic_.default_settings(); }
    std::vector<multibody::SettingDescription> setting_descriptions() const override { return {}; }
    void check_settings(const multibody::EngineSettings& s) const override { analytic_.check_settings(s); }
    bool runs_concurrently() const override { return !exclusive_; }
    multibody::Trajectory simulate(const multibody::WallScene& scene, const Excitation& ex, const multibody::EngineSettings& s) const override {
        const int now = ++running_;
        int seen = max_running_.load();
        while (now > seen && !max_running_.compare_exchange_weak(seen, now)) {
        }
        struct Leave {
            std::atomic<int>& n;
            ~Leave() { --n; }
        } leave{running_};
        if (fail_parapet_ && scene.parapet) throw EngineFailure(name_ + ": no parapets here");
        if (exclusive_) std::this_thread::sleep_for(std::chrono::milliseconds(2));  // widen any overlap
        return analytic_.simulate(scene, ex, s);
    }
    int max_running() const { return max_running_.load(); }

private:
    std::string name_;
    bool fail_parapet_, exclusive_;
    AnalyticEngine analytic_;
    mutable std::atomic<int> running_{0}, max_running_{0};
};

// An engine whose runs are bad input: InputError must leave run_suite, not become a CaseFailure.
class BadInputEngine final : public multibody::Engine {
public:
    double cost_per_simulated_second() const override { return 1e-3; }  // a test double: never timed
    std::string name() const override { return "bad-input"; }
    std::string version() const override { return "0"; }
    multibody::EngineSettings default_settings() const override { return {}; }
    std::vector<multibody::SettingDescription> setting_descriptions() const override { return {}; }
    void check_settings(const multibody::EngineSettings&) const override {}  // no knobs
    multibody::Trajectory simulate(const multibody::WallScene&, const Excitation&, const multibody::EngineSettings&) const override {
        throw InputError("bad-input: a setting is wrong");
    }
};

// The suites ----------------------------------------------------------------------------------------------------

TEST(Suite, DefaultCasesAreUniqueAndEveryWallAndRecordExists) {
    const validation::Suite s = default_suite();
    EXPECT_EQ(s.name, "default");
    std::set<std::string> ids, walls;
    for (const validation::SuiteWall& w : s.walls) EXPECT_TRUE(walls.insert(w.id).second) << "duplicate wall " << w.id;
    for (const validation::SuiteCase& c : s.cases) {
        EXPECT_TRUE(ids.insert(c.id).second) << "duplicate case " << c.id;
        EXPECT_NO_THROW((void)s.wall(c.wall_id)) << c.id;
        EXPECT_EQ(c.id.rfind(c.wall_id, 0), 0u) << c.id << " does not start with its wall";
        if (c.kind == validation::CaseKind::history) {
            ASSERT_NO_THROW((void)s.record(c.record_id)) << c.id;
            EXPECT_TRUE(std::filesystem::exists(s.record(c.record_id).path)) << s.record(c.record_id).path;
        }
        if (c.kind == validation::CaseKind::step) {
            ASSERT_TRUE(c.dt.has_value()) << c.id;
            EXPECT_FALSE(c.engine.empty()) << c.id;
            const std::string suffix = "/" + c.engine;
            EXPECT_TRUE(c.id.size() > suffix.size() && c.id.compare(c.id.size() - suffix.size(), suffix.size(), suffix) == 0)
                << c.id;
            const auto& dts = s.step_study.at(c.engine);
            EXPECT_NE(std::find(dts.begin(), dts.end(), *c.dt), dts.end()) << c.id;
        } else {
            EXPECT_TRUE(c.engine.empty()) << c.id;
        }
    }
    // The reference walls: Fig. 6 VSSW and PW, Table 1 #1, #7, #15 at xi 0, 0.1, 0.5; one threshold case each.
    EXPECT_EQ(s.walls.size(), 11u);
    for (const char* id : {"fig6-vssw", "fig6-pw", "t1-01-xi0", "t1-07-xi0.1", "t1-15-xi0.5"})
        EXPECT_TRUE(walls.count(id)) << id;
    EXPECT_TRUE(s.wall("fig6-pw").scene.parapet.has_value());
    EXPECT_NEAR(s.wall("t1-07-xi0.1").scene.vssw->xi, 0.1, 1e-15);
    EXPECT_NEAR(s.wall("t1-07-xi0.1").scene.vssw->hinge_ratio(), 0.5, 1e-12);
    for (const validation::SuiteWall& w : s.walls) EXPECT_TRUE(ids.count(w.id)) << "no threshold case for " << w.id;
    for (const char* id : {"fig6-vssw/r0.2", "fig6-pw/r0.8", "t1-15-xi0.5/r0.5", "fig6-vssw/r0.5/dt0.0005/ode"})
        EXPECT_TRUE(ids.count(id)) << id;
    // Every engine's step study has four steps, each a case on the Fig. 6 VSSW.
    for (const auto& [engine, dts] : s.step_study) EXPECT_EQ(dts.size(), 4u) << engine;
    EXPECT_EQ(validation::to_string(validation::CaseKind::threshold), std::string("threshold"));
    EXPECT_EQ(validation::to_string(validation::CaseKind::step), std::string("step"));
}

TEST(Suite, FullHoldsEveryTable1SpecimenWithDataAtEveryRelease) {
    const validation::Suite s = vssw::validation::read_suite("full", VSSW_DATA_DIR);
    std::set<std::string> ids;
    for (const validation::SuiteCase& c : s.cases) EXPECT_TRUE(ids.insert(c.id).second) << "duplicate case " << c.id;
    EXPECT_EQ(s.walls.size(), 2u + 16u * 3u);  // 18 specimens less the two discarded (4, 12), three xi each
    EXPECT_THROW((void)s.wall("t1-04-xi0"), InputError);
    EXPECT_THROW((void)s.wall("t1-12-xi0"), InputError);
    for (const char* id : {"t1-09-xi0.5/r0.2", "t1-18-xi0.1/r0.8", "fig6-pw/r0.5/dt0.0005/ode"})
        EXPECT_TRUE(ids.count(id)) << id;
}

TEST(Suite, UnknownNameIsAnInputErrorNamingTheValidOnes) {
    try {
        (void)vssw::validation::read_suite("quick", VSSW_DATA_DIR);
        FAIL() << "no error";
    } catch (const InputError& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("quick"), std::string::npos) << m;
        EXPECT_NE(m.find("default"), std::string::npos) << m;
        EXPECT_NE(m.find("full"), std::string::npos) << m;
    }
}

TEST(Suite, SelectKeepsOnlyTheNamedCasesAndWhatTheyNeed) {
    const validation::Suite s = validation::select_cases(default_suite(), {"fig6-pw/rinaldi-x0.17", "t1-07-xi0", "fig6-vssw/r0.5/dt0.001/ode"});
    EXPECT_EQ(s.name, "default");  // a selection names the suite its case ids come from
    ASSERT_EQ(s.cases.size(), 3u);
    std::set<std::string> walls;
    for (const validation::SuiteWall& w : s.walls) walls.insert(w.id);
    EXPECT_EQ(walls, (std::set<std::string>{"fig6-pw", "t1-07-xi0", "fig6-vssw"}));
    ASSERT_EQ(s.records.size(), 1u);
    EXPECT_EQ(s.records.front().id, "rinaldi-x0.17");
    ASSERT_EQ(s.step_study.size(), 1u);
    EXPECT_EQ(s.step_study.at("ode"), std::vector<double>{1e-3});

    try {
        (void)validation::select_cases(default_suite(), {"t1-07-xi0", "fig6-vssw/r0.3"});
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("fig6-vssw/r0.3"), std::string::npos) << e.what();
    }
}

// Running ----------------------------------------------------------------------------------------------------------

TEST(RunSuite, AnalyticRowsAreTheClosedFormsWithZeroError) {
    const validation::Suite suite = default_suite();
    const validation::Suite s = validation::select_cases(suite, {"fig6-vssw", "fig6-pw", "t1-07-xi0.5", "fig6-vssw/r0.5", "fig6-pw/r0.5"});
    validation::RunOptions o;
    o.threads = 2;
    const validation::SuiteResults r = validation::run_suite(s, {"analytic"}, o);
    EXPECT_TRUE(r.failures.empty());
    ASSERT_EQ(r.engines.size(), 1u);
    EXPECT_EQ(r.engines.front().name, "analytic");
    EXPECT_FALSE(r.engines.front().version.empty());
    for (const validation::MetricRow& row : r.rows) {
        EXPECT_EQ(row.engine, "analytic");
        EXPECT_EQ(row.analytic, row.engine_value) << row.case_id << " " << row.metric;
        EXPECT_EQ(row.rel_error, 0.0) << row.case_id << " " << row.metric;
    }
    for (const char* wall : {"fig6-vssw", "t1-07-xi0.5"}) {
        const VsswGeometry& w = *suite.wall(wall).scene.vssw;
        const validation::MetricRow* t = find_row(r, wall, "analytic", "threshold_g");
        ASSERT_NE(t, nullptr) << wall;
        EXPECT_EQ(t->unit, "g");
        EXPECT_NEAR(t->analytic / (eq12_threshold(w) / w.g), 1.0, kBisectionTol) << wall;
    }
    const ParapetGeometry& pw = *suite.wall("fig6-pw").scene.parapet;
    ASSERT_NE(find_row(r, "fig6-pw", "analytic", "threshold_g"), nullptr);
    EXPECT_NEAR(find_row(r, "fig6-pw", "analytic", "threshold_g")->analytic / (eq17_parapet_threshold(pw) / pw.g), 1.0,
                kBisectionTol);

    const VsswGeometry& fig6 = *suite.wall("fig6-vssw").scene.vssw;
    // The reference is the set mechanism: a VSSW's impact is the whole mechanism's plastic impact (0.825 on Fig. 6;
    // Eq. 19, the paper set's, is 0.951 and fails this), a parapet's Housner's.
    const validation::MetricRow* e = find_row(r, "fig6-vssw/r0.5", "analytic", "restitution");
    ASSERT_NE(e, nullptr);
    EXPECT_NEAR(e->analytic / restitution_whole_mechanism(fig6), 1.0, kImpactSamplingTol);
    EXPECT_NEAR(find_row(r, "fig6-pw/r0.5", "analytic", "restitution")->analytic / housner_restitution(pw.alpha), 1.0,
                kImpactSamplingTol);
    EXPECT_GT(find_row(r, "fig6-pw/r0.5", "analytic", "period")->analytic, 0.0);
    // No row against a second impact law: the reference's restitution is the one.
    for (const validation::MetricRow& row : r.rows) EXPECT_EQ(row.metric.find("whole_mechanism"), std::string::npos) << row.metric;

    // Free cases keep decimated analytic traces, starting at the release (theta1 = 0.5 alpha), named by the set.
    ASSERT_EQ(r.traces.size(), 2u);
    for (const validation::Trace& t : r.traces) {
        EXPECT_EQ(t.engine, "analytic");
        ASSERT_FALSE(t.t.empty());
        EXPECT_LE(t.t.size(), kMaxTracePoints);
        EXPECT_EQ(t.t.size(), t.theta1_over_alpha1.size());
        EXPECT_NEAR(t.theta1_over_alpha1.front(), 0.5, 1e-12);
    }
    EXPECT_EQ(r.traces[0].case_id, "fig6-vssw/r0.5");
    EXPECT_EQ(r.traces[0].assumption, "mechanism");
    EXPECT_EQ(r.traces[1].case_id, "fig6-pw/r0.5");
    EXPECT_EQ(r.traces[1].assumption, "mechanism");
}

// Suite::reference chooses the reference: under the set paper a VSSW's restitution is Eq. (19)'s (the mechanism's,
// 0.825 on Fig. 6, fails this), the period Eq. (3)'s, and the traces name the set.
TEST(RunSuite, TheSuitesReferenceSetIsTheAnalyticRowsModel) {
    validation::Suite s = validation::select_cases(default_suite(), {"fig6-vssw/r0.5"});
    s.reference = AssumptionSet::paper;
    const validation::SuiteResults r = validation::run_suite(s, {});
    EXPECT_EQ(r.reference, AssumptionSet::paper);
    const VsswGeometry& fig6 = *s.wall("fig6-vssw").scene.vssw;
    const validation::MetricRow* e = find_row(r, "fig6-vssw/r0.5", "analytic", "restitution");
    ASSERT_NE(e, nullptr);
    EXPECT_NEAR(e->analytic / eq19_restitution(fig6), 1.0, kImpactSamplingTol);
    ASSERT_EQ(r.traces.size(), 1u);
    EXPECT_EQ(r.traces[0].assumption, "paper");
    EXPECT_FALSE(r.other_set.has_value());  // not asked for (RunOptions::other_set)
}

// The analytic model's peak under a record is its located turning point, not its largest sample: the suite samples
// that run every 1 ms (what the RMS difference and the trace need), and the peak is the same as from a run sampled
// ten times as finely. Tolerance: the located turning point is a root of theta1_dot found to about 1e-12 rad; 1e-9
// of the peak is far below what the 1 ms samples would miss (p^2 dt^2 / 8, about 5e-7 of it on the Fig. 6 VSSW).
constexpr double kLocatedPeakTol = 1e-9;

TEST(RunSuite, AnAnalyticRecordPeakDoesNotDependOnItsSampling) {
    const validation::Suite suite = default_suite();
    const std::string id = "fig6-vssw/rinaldi-x0.45";
    const validation::SuiteResults r = validation::run_suite(validation::select_cases(suite, {id}), {"analytic"});
    const validation::MetricRow* peak = find_row(r, id, "analytic", "peak_rotation");
    ASSERT_NE(peak, nullptr);

    const validation::SuiteCase& c = *std::find_if(suite.cases.begin(), suite.cases.end(),
                                       [&](const validation::SuiteCase& x) { return x.id == id; });
    const validation::SuiteRecord& rec = suite.record(c.record_id);
    const multibody::WallScene& scene = suite.wall(c.wall_id).scene;
    Excitation ex;
    ex.horizontal = read_record(rec.path).scaled(rec.scale);
    ex.t_end = ex.horizontal.duration() + c.response_tail;
    ex.stop_at_rest = true;
    const multibody::Trajectory fine = AnalyticEngine().simulate(scene, ex, compare::analytic_reference_settings());  // 1e-4 s
    ASSERT_TRUE(fine.located.has_value());
    double largest_sample = 0.0;
    for (const auto& s : fine.samples) largest_sample = std::max(largest_sample, std::abs(s.theta1));
    const double alpha = scene.alpha();
    EXPECT_NEAR(peak->analytic, fine.located->max_abs_theta1 / alpha, kLocatedPeakTol * peak->analytic);
    // ... and it is a true maximum: no sample of the finer run lies above it.
    EXPECT_GE(peak->analytic * (1.0 + kLocatedPeakTol), largest_sample / alpha);
}

// The records a caller already read (the report reads them up front) are the ones the suite runs: the same rows as
// reading the file, and a different motion given under the record's path moves the peak (the map is used, not the
// file).
TEST(RunSuite, RecordsAlreadyReadAreTheOnesItRuns) {
    const validation::Suite suite = validation::select_cases(default_suite(), {"fig6-vssw/rinaldi-x0.45"});
    const std::string path = suite.records.at(0).path;
    const auto peak_of = [&](const std::map<std::string, vssw::GroundMotion>* records) {
        validation::RunOptions options;
        options.records_read = records;
        const validation::SuiteResults r = validation::run_suite(suite, {"analytic"}, options);
        return find_row(r, suite.cases.at(0).id, "analytic", "peak_rotation")->analytic;
    };
    const std::map<std::string, vssw::GroundMotion> same = {{path, read_record(path)}};
    EXPECT_EQ(peak_of(&same), peak_of(nullptr));
    const std::map<std::string, vssw::GroundMotion> stronger = {{path, read_record(path).scaled(1.5)}};
    EXPECT_NE(peak_of(&stronger), peak_of(nullptr));
}

TEST(RunSuite, RecordsRockTheAnalyticWallsClearlyWithoutOverturning) {
    const validation::Suite suite = default_suite();
    std::vector<std::string> ids;
    for (const validation::SuiteCase& c : suite.cases)
        if (c.kind == validation::CaseKind::history) ids.push_back(c.id);
    ASSERT_EQ(ids.size(), 4u);  // Rinaldi and El Centro on the Fig. 6 VSSW and PW
    const validation::SuiteResults r = validation::run_suite(validation::select_cases(suite, ids), {"analytic"});
    EXPECT_TRUE(r.failures.empty());
    for (const std::string& id : ids) {
        const validation::MetricRow* peak = find_row(r, id, "analytic", "peak_rotation");
        const validation::MetricRow* rms = find_row(r, id, "analytic", "rms_difference");
        const validation::MetricRow* over = find_row(r, id, "analytic", "overturned");
        const validation::MetricRow* when = find_row(r, id, "analytic", "peak_time");
        ASSERT_TRUE(peak && rms && over && when) << id;
        EXPECT_EQ(peak->unit, "alpha1");
        EXPECT_GT(peak->analytic, kClearRocking) << id;
        EXPECT_LT(peak->analytic, kBelowInstability) << id;
        EXPECT_EQ(over->analytic, 0.0) << id;
        EXPECT_EQ(rms->engine_value, 0.0) << id;
        EXPECT_EQ(rms->rel_error, 0.0) << id;
        EXPECT_EQ(rms->analytic, peak->analytic) << id;
        EXPECT_GT(when->analytic, 0.0) << id;
        // One analytic trace per history case, whose largest |value| is the peak (the decimation may miss the
        // sample of the peak itself, never exceed it).
        const auto t = std::find_if(r.traces.begin(), r.traces.end(), [&](const validation::Trace& x) { return x.case_id == id; });
        ASSERT_NE(t, r.traces.end()) << id;
        EXPECT_EQ(t->assumption, "mechanism") << id;
        EXPECT_LE(t->t.size(), kMaxTracePoints);
        double largest = 0.0;
        for (double v : t->theta1_over_alpha1) largest = std::max(largest, std::abs(v));
        EXPECT_LE(largest, peak->analytic) << id;
        EXPECT_GT(largest, 0.5 * peak->analytic) << id;
    }
}

// A selection of every kind the analytic engine runs, run for the analytic model and two fakes on it.
validation::Suite small_selection() {
    return validation::select_cases(default_suite(),
                        {"fig6-vssw", "fig6-pw", "fig6-vssw/r0.2", "fig6-pw/r0.5", "fig6-pw/rinaldi-x0.17"});
}

TEST(RunSuite, OneAndTwoThreadsGiveIdenticalResults) {
    const validation::Suite s = small_selection();
    const FakeEngine fake("fake", /*fail_parapet=*/true, /*exclusive=*/false);
    const FakeEngine other("other", false, false);
    validation::RunOptions one, two;
    one.threads = 1;
    two.threads = 2;
    const validation::SuiteResults a = validation::run_suite_with_engines(s, {&fake, &other}, one);
    const validation::SuiteResults b = validation::run_suite_with_engines(s, {&fake, &other}, two);
    EXPECT_EQ(a.threads, 1);
    EXPECT_EQ(b.threads, 2);
    ASSERT_EQ(a.rows.size(), b.rows.size());
    for (std::size_t i = 0; i < a.rows.size(); ++i) {
        const validation::MetricRow &x = a.rows[i], &y = b.rows[i];
        EXPECT_EQ(x.case_id, y.case_id);
        EXPECT_EQ(x.engine, y.engine);
        EXPECT_EQ(x.metric, y.metric);
        EXPECT_TRUE(same_number(x.analytic, y.analytic)) << x.case_id << " " << x.metric;
        EXPECT_TRUE(same_number(x.engine_value, y.engine_value)) << x.case_id << " " << x.metric;
        EXPECT_TRUE(same_number(x.rel_error, y.rel_error)) << x.case_id << " " << x.metric;
    }
    ASSERT_EQ(a.failures.size(), b.failures.size());
    for (std::size_t i = 0; i < a.failures.size(); ++i) {
        EXPECT_EQ(a.failures[i].case_id, b.failures[i].case_id);
        EXPECT_EQ(a.failures[i].engine, b.failures[i].engine);
    }
    ASSERT_EQ(a.traces.size(), b.traces.size());
    for (std::size_t i = 0; i < a.traces.size(); ++i) {
        EXPECT_EQ(a.traces[i].case_id, b.traces[i].case_id);
        EXPECT_EQ(a.traces[i].engine, b.traces[i].engine);
        EXPECT_EQ(a.traces[i].theta1_over_alpha1, b.traces[i].theta1_over_alpha1);
    }
    // Rows in case order, then engine order (analytic, fake, other).
    auto case_index = [&](const std::string& id) {
        return std::find_if(s.cases.begin(), s.cases.end(), [&](const validation::SuiteCase& c) { return c.id == id; }) -
               s.cases.begin();
    };
    const std::vector<std::string> order = {"analytic", "fake", "other"};
    auto engine_index = [&](const std::string& e) { return std::find(order.begin(), order.end(), e) - order.begin(); };
    for (std::size_t i = 1; i < b.rows.size(); ++i) {
        const auto p = std::make_pair(case_index(b.rows[i - 1].case_id), engine_index(b.rows[i - 1].engine));
        const auto q = std::make_pair(case_index(b.rows[i].case_id), engine_index(b.rows[i].engine));
        EXPECT_LE(p, q) << b.rows[i].case_id << " " << b.rows[i].engine;
    }
}

TEST(RunSuite, AFailingEngineBecomesCaseFailuresAndTheOtherRowsStay) {
    const validation::Suite s = small_selection();
    const FakeEngine fake("fake", /*fail_parapet=*/true, /*exclusive=*/false);
    validation::RunOptions o;
    o.threads = 2;
    const validation::SuiteResults r = validation::run_suite_with_engines(s, {&fake}, o);
    // Every parapet case fails for the fake, with its message, and only those.
    std::set<std::string> failed;
    for (const validation::CaseFailure& f : r.failures) {
        EXPECT_EQ(f.engine, "fake");
        EXPECT_NE(f.message.find("no parapets here"), std::string::npos) << f.message;
        failed.insert(f.case_id);
    }
    EXPECT_EQ(failed, (std::set<std::string>{"fig6-pw", "fig6-pw/r0.5", "fig6-pw/rinaldi-x0.17"}));
    for (const std::string& id : failed)
        for (const validation::MetricRow& row : r.rows)
            if (row.case_id == id) {
                EXPECT_EQ(row.engine, "analytic") << id;
            }
    // The reference rows of the failed cases are still there.
    EXPECT_NE(find_row(r, "fig6-pw", "analytic", "threshold_g"), nullptr);
    EXPECT_NE(find_row(r, "fig6-pw/r0.5", "analytic", "period"), nullptr);
    EXPECT_NE(find_row(r, "fig6-pw/rinaldi-x0.17", "analytic", "peak_rotation"), nullptr);
    // The fake is the analytic model at the same sampling: its VSSW rows equal the reference exactly.
    const validation::MetricRow* t = find_row(r, "fig6-vssw", "fake", "threshold_g");
    ASSERT_NE(t, nullptr);
    EXPECT_EQ(t->rel_error, 0.0);
    for (const char* metric : {"period", "restitution"}) {
        const validation::MetricRow* row = find_row(r, "fig6-vssw/r0.2", "fake", metric);
        ASSERT_NE(row, nullptr) << metric;
        EXPECT_EQ(row->rel_error, 0.0) << metric;
    }
}

// The analytic model under the other set (RunOptions::other_set) is measured as an engine against the reference and
// kept apart: the engines' rows are those of a run without it, its own rows are in other_set only, and its
// restitution against the reference is the ratio of the two sets' impact laws (Eq. 19 over the whole mechanism's,
// closed forms: 0.951 / 0.825 on Fig. 6), its threshold Eq. (12) on both sides.
TEST(RunSuite, TheOtherSetIsMeasuredLikeAnEngineAndKeptApart) {
    const validation::Suite s = validation::select_cases(default_suite(), {"fig6-vssw", "fig6-vssw/r0.5", "fig6-pw/rinaldi-x0.17"});
    const FakeEngine fake("fake", false, false);
    validation::RunOptions with;
    with.other_set = true;
    const validation::SuiteResults plain = validation::run_suite_with_engines(s, {&fake});
    const validation::SuiteResults r = validation::run_suite_with_engines(s, {&fake}, with);
    ASSERT_EQ(r.rows.size(), plain.rows.size());
    for (std::size_t i = 0; i < r.rows.size(); ++i) {
        EXPECT_EQ(r.rows[i].engine, plain.rows[i].engine);
        EXPECT_EQ(r.rows[i].metric, plain.rows[i].metric);
        EXPECT_EQ(r.rows[i].rel_error, plain.rows[i].rel_error) << r.rows[i].case_id << " " << r.rows[i].metric;
    }
    ASSERT_EQ(r.engines.size(), plain.engines.size());  // not one of the engines
    ASSERT_TRUE(r.other_set.has_value());
    EXPECT_EQ(r.other_set->set, AssumptionSet::paper);
    EXPECT_EQ(r.other_set->engine, "paper-model");
    EXPECT_TRUE(r.other_set->failures.empty());
    for (const validation::MetricRow& row : r.other_set->rows) EXPECT_EQ(row.engine, "paper-model");
    const VsswGeometry& fig6 = *s.wall("fig6-vssw").scene.vssw;
    const validation::MetricRow* e = nullptr;
    const validation::MetricRow* peak = nullptr;
    for (const validation::MetricRow& row : r.other_set->rows) {
        if (row.case_id == "fig6-vssw/r0.5" && row.metric == "restitution") e = &row;
        if (row.case_id == "fig6-pw/rinaldi-x0.17" && row.metric == "peak_rotation") peak = &row;
    }
    ASSERT_TRUE(e && peak);
    EXPECT_NEAR(e->rel_error + 1.0, eq19_restitution(fig6) / restitution_whole_mechanism(fig6), 2 * kImpactSamplingTol);
    // A parapet is the same model under either set (one block, no roller): its record run agrees exactly.
    EXPECT_EQ(peak->rel_error, 0.0);
}

TEST(RunSuite, AnEngineThatMustNotRunConcurrentlyRunsOneTaskAtATime) {
    const validation::Suite s = validation::select_cases(default_suite(), {"fig6-vssw", "fig6-pw", "t1-01-xi0", "t1-07-xi0", "fig6-vssw/r0.5",
                                                   "fig6-pw/r0.5", "t1-15-xi0/r0.5", "t1-15-xi0.5/r0.5"});
    const FakeEngine exclusive("exclusive", false, /*exclusive=*/true);
    const FakeEngine free_runner("free-runner", false, false);
    validation::RunOptions o;
    o.threads = 2;
    int calls = 0, last = 0, total = 0;
    bool in_order = true;
    o.progress = [&](int done, int n, const std::string& what) {
        ++calls;
        in_order = in_order && done == last + 1 && !what.empty();
        last = done;
        total = n;
    };
    const validation::SuiteResults r = validation::run_suite_with_engines(s, {&exclusive, &free_runner}, o);
    EXPECT_TRUE(r.failures.empty());
    EXPECT_EQ(exclusive.max_running(), 1);
    // Progress: once per (case, engine) task, counted in order from the serialised callback.
    EXPECT_EQ(total, static_cast<int>(s.cases.size() * 3));
    EXPECT_EQ(calls, total);
    EXPECT_TRUE(in_order);
}

TEST(RunSuite, BadInputPropagatesAndUnknownEnginesAreNamed) {
    const validation::Suite s = small_selection();
    const BadInputEngine bad;
    validation::RunOptions o;
    o.threads = 2;
    EXPECT_THROW((void)validation::run_suite_with_engines(s, {&bad}, o), InputError);
    try {
        (void)validation::run_suite(s, {"analytic", "havok"});
        FAIL() << "no error";
    } catch (const InputError& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("havok"), std::string::npos) << m;
        EXPECT_NE(m.find("analytic"), std::string::npos) << m;  // the available ones are listed
    }
    o.threads = -1;
    EXPECT_THROW((void)validation::run_suite(s, {"analytic"}, o), InputError);
}

// Two cheap real-engine cases: a Bullet free vibration of the Fig. 6 PW and an ODE step case (which must run for
// ODE only).
TEST(RunSuite, EngineRowsOnCheapCases) {
    if (!engine_available("bullet") || !engine_available("ode")) GTEST_SKIP() << "Bullet or ODE not compiled in";
    const validation::Suite s = validation::select_cases(default_suite(), {"fig6-pw/r0.5", "fig6-vssw/r0.5/dt0.001/ode"});
    validation::RunOptions o;
    o.threads = 2;
    const validation::SuiteResults r = validation::run_suite(s, {"bullet", "ode"}, o);
    ASSERT_TRUE(r.failures.empty()) << r.failures.front().message;
    ASSERT_EQ(r.engines.size(), 3u);
    EXPECT_EQ(r.engines[0].name, "analytic");
    EXPECT_EQ(r.engines[1].name, "bullet");
    EXPECT_EQ(r.engines[2].name, "ode");
    EXPECT_EQ(r.engines[1].settings.dt, multibody::make_engine("bullet")->default_settings().dt);

    // The parapet: period and Housner's restitution within the targets (docs/contributing/engines.md: -0.015 % and
    // -0.25 % measured).
    const validation::MetricRow* period = find_row(r, "fig6-pw/r0.5", "bullet", "period");
    const validation::MetricRow* e = find_row(r, "fig6-pw/r0.5", "bullet", "restitution");
    ASSERT_TRUE(period && e);
    EXPECT_LT(std::abs(period->rel_error), kPeriodTarget);
    EXPECT_LT(std::abs(e->rel_error), kRestitutionTarget);
    const auto traces = std::count_if(r.traces.begin(), r.traces.end(),
                                      [](const validation::Trace& t) { return t.case_id == "fig6-pw/r0.5"; });
    EXPECT_EQ(traces, 3);  // analytic, bullet, ode

    // The step case: ODE's rows only (no analytic, no Bullet), at its step; its impact is the whole mechanism's, the
    // reference's.
    for (const validation::MetricRow& row : r.rows)
        if (row.case_id == "fig6-vssw/r0.5/dt0.001/ode") {
            EXPECT_EQ(row.engine, "ode");
        }
    const validation::MetricRow* step_e = find_row(r, "fig6-vssw/r0.5/dt0.001/ode", "ode", "restitution");
    const validation::MetricRow* step_period = find_row(r, "fig6-vssw/r0.5/dt0.001/ode", "ode", "period");
    ASSERT_TRUE(step_e && step_period);
    EXPECT_LT(std::abs(step_e->rel_error), kRestitutionTarget);
    EXPECT_LT(std::abs(step_period->rel_error), kPeriodTarget);
}

}  // namespace
}  // namespace vssw::compare

namespace vssw::compare {
namespace {

// The analytic model's warnings reach the suite's results once per case (from its own run, not once per engine):
// under the set paper, whose bilateral roller can pull, from 0.8 alpha1 at xi 0.5 the roller must pull (Table 1 #7);
// from 0.5 alpha1 it pushes throughout. (The mechanism's roller lets go instead: no warning to carry.)
TEST(RunSuite, TheAnalyticModelsWarningsAreCarriedOncePerCase) {
    validation::Suite s = validation::select_cases(vssw::validation::read_suite("full", VSSW_DATA_DIR), {"t1-07-xi0.5/r0.8", "t1-07-xi0.5/r0.5"});
    s.reference = AssumptionSet::paper;
    const validation::SuiteResults r = validation::run_suite(s, {"analytic"});
    ASSERT_EQ(r.model_warnings.size(), 1u);
    EXPECT_EQ(r.model_warnings[0].case_id, "t1-07-xi0.5/r0.8");
    EXPECT_NE(r.model_warnings[0].message.find("roller would have to pull"), std::string::npos);
}

}  // namespace
}  // namespace vssw::compare
