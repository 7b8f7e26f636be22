#pragma once
// Ensemble measures of a record study (one that varies the record `file` over at least two records): every series (an
// engine with its settings, the analytic model under one assumption set) against a reference series, per wall, from
// the study's results alone (study/study_data.hpp), with the statistics of compare/ensemble_statistics.hpp.
//
//  - The reference: the analytic model under the set mechanism (kinematics=exact, impact=whole-mechanism,
//    roller=unilateral: the assumptions the engines' physics shares) when the study ran it, else the study's first
//    analytic series.
//  - Stripes (kind record, file x pga): overturning agreement with the reference over records x levels (Wilson 95 %),
//    the engine peak / reference peak where both stand (median, quartiles), the runs inside the reference's
//    sensitivity band when the study has a `perturbation` column (rows other than "none" only build the band), and
//    per level the share of runs that overturned (Wilson intervals), and a lognormal fit to those shares with its
//    bootstrap over records and the paired ratio of its median to the reference's (compare/stripe_fragility.hpp).
//  - IDA (kind scale-to-collapse): per record its collapse_pga (collapse_pgv, collapse_sa or collapse_arias when the
//    study reports one: the ensemble's intensity, EnsembleMeasures::intensity; the stripes' level column likewise);
//    a record that did not overturn up to max_pga (status "failed: does not overturn up to a PGA of X g (...)", "a PGV
//    of X m/s", X the last value run in the row's measure, study/measure.cpp) is right-censored at X; one that overturned at the first scale tried counts as collapsing at that PGA (its status gives it, an
//    upper bound). A lognormal fit with bootstrap intervals, and the paired bootstrap
//    ratio of its median to the reference's over the records both have. Other failed rows are left out (counted).
// The bootstrap's seed and replicates are fixed (kEnsembleSeed, kEnsembleReplicates): the outputs are the same bytes
// on every run, resume and merge.
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "compare/ensemble_statistics.hpp"
#include "compare/paired_runs.hpp"
#include "study/study_data.hpp"

namespace vssw::study {

constexpr std::uint64_t kEnsembleSeed = 20150401;  // std::mt19937_64's seed for every bootstrap
constexpr int kEnsembleReplicates = 2000;          // bootstrap resamples
constexpr double kEnsembleConfidence = 0.95;       // of every interval

// A stripe: runs at one level (PGA [g], or the ensemble's measure) and the share of them that overturned (Wilson
// interval; n runs).
struct StripeShare {
    double pga = 0.0;  // the level, in the ensemble's measure
    compare::Interval share;
};

// One run of a series paired with the reference's (stripes, where the reference has a result), for the plots that
// show each run: both peaks, the reference's band [lo, hi] (NaN without perturbed repeats) and whether each
// overturned (1 or 0; NaN for a failed run).
struct PairedRun {
    std::string name;  // "rinaldi-228.at2 at 0.55 g"
    double peak = NAN, reference_peak = NAN, band_lo = NAN, band_hi = NAN;
    double overturned = NAN, reference_overturned = NAN;
};

// One series on one wall.
struct SeriesMeasures {
    std::size_t series = 0;  // in StudyData::series
    std::size_t wall = 0;    // in EnsembleMeasures::walls
    // The fragility fit: "pga_ida" (each record's collapse PGA), "pga_stripes" (the maximum likelihood over the
    // stripes' overturning counts, compare/stripe_fragility.hpp; when the series has no IDA), "" when none was
    // attempted; "pgv_ida", "sa_stripes", ... in another measure (EnsembleMeasures::intensity).
    std::string intensity;
    bool fitted() const { return !intensity.empty(); }
    compare::FitBootstrap fit;
    compare::RatioBootstrap ratio;  // against the reference over the records both have (NaN for the reference)
    long paired = 0;                // those records
    // IDA: one record per (file and the other excitation levels), in the results' order; failed rows left out.
    bool ida = false;
    std::vector<compare::IdaRecord> records;
    long left_out = 0;
    // Stripes.
    bool stripes = false;
    compare::Interval overturning{};  // share of runs where it and the reference agree on overturning (a run of its
                                      // that failed where the reference has a result counts as not agreeing)
    long failed_runs = 0;             // its runs with no overturning value (failed)
    compare::Quartiles peak_ratio{};  // its peak / the reference's where neither overturned
    // Paired with the reference run by run (compare/paired_runs.hpp): ln(its peak / the reference's) where both
    // stand, grouped by record, its median with an interval over records; the discordant runs (it overturned and the
    // reference stood; the reverse) and its failed runs where the reference has a result.
    compare::RecordMedian log_peak_ratio{};
    long overturned_alone = 0, stood_alone = 0, failed_paired = 0;
    bool band = false;                // the reference had perturbed repeats
    compare::BandCount inside;        // its peaks inside the reference's band
    // The band's median half-width in ln, 0.5 ln(hi / lo), over the runs where both stand (NaN without a band): how
    // far the reference's peaks move within what the free-vibration targets allow.
    double band_half_width = NAN;
    std::vector<PairedRun> paired_runs;     // every run paired with the reference's, in the study's order
    std::vector<std::string> outside_band;  // the runs outside it ("file at 0.55 g"), in the study's order
    std::vector<StripeShare> levels;  // by PGA level, in the study's order
};

struct EnsembleMeasures {
    bool applies = false;            // the study varies `file` over >= 2 records and measures overturning or collapse
    // The intensity measure of its levels and collapse intensities: "pga", "pgv", "sa", "arias" (a pgv, sa or arias
    // column, or a collapse_pgv, collapse_sa or collapse_arias metric; else the PGA), its unit and an axis label
    // ("PGV [m/s]").
    std::string intensity = "pga", unit = "g", label = "PGA [g]", name = "PGA";  // name: the label without its unit
    std::size_t reference = 0;       // in StudyData::series (meaningless when !has_reference)
    bool has_reference = false;
    bool preferred_reference = false;  // the exact / whole-mechanism / unilateral set (else the first analytic one)
    std::vector<std::string> walls;  // per wall its varied wall parameters ("height 4, hinge 0.7"; "" for one wall)
    std::map<int, std::size_t> case_wall;  // each case's wall (in walls)
    std::vector<SeriesMeasures> measures;  // wall by wall, series in order
};

EnsembleMeasures ensemble_measures(const StudyData& d);

// The paper's Fig. 10 rocking curves with the ensemble's spread: per series, size R and stripe (PGA level), the peak
// |theta1| / alpha1 over the records at each slenderness alpha of the whole wall (median and quartiles; an overturned
// run counts as the largest, kOverturnedPeak: study/overturned_runs.hpp) and how many of them overturned. Empty
// unless the study varies alpha and the record file (>= 2) and measures peak_rotation; perturbed repeats are left out.
struct RockingPoint {
    double alpha = 0.0;
    compare::Quartiles peak{};
    long overturned = 0;
};
struct RockingCurve {
    std::size_t series = 0;
    double R = 0.0, pga = 0.0;  // NaN when the study does not give them
    std::vector<RockingPoint> points;  // by alpha, in the study's order
};
std::vector<RockingCurve> rocking_curves(const StudyData& d);

// Whether series s repeats an earlier one (the same engine, settings and assumptions): a study of several parts lists
// each part's runs; the measures and plots hold each series once.
bool repeats_earlier(const StudyData& d, std::size_t s);

// The series' label columns: the engine, its assumptions ("set=mechanism kinematics=exact impact=whole-mechanism
// roller=unilateral" for the analytic model: the set's name, custom when the parts are neither set's, then the parts;
// "" for an engine), its settings.
std::string assumptions_text(const Series& s);

}  // namespace vssw::study
