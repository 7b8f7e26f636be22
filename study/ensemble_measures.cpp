#include "study/ensemble_measures.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <tuple>

#include <fmt/format.h>

#include "analytic/intensity_measures.hpp"
#include "compare/stripe_fragility.hpp"
#include "study/overturned_runs.hpp"
#include "study/plot_panels.hpp"
#include "study/spec.hpp"

namespace vssw::study {
namespace {

using compare::IdaRecord;
using Key = std::vector<std::uint32_t>;  // a run's levels with engine, settings, assumptions, perturbation cleared

// The assumption set the engines share (their impact is the whole mechanism's, their roller unilateral).
const std::vector<std::string> kPreferredReference = {"exact", "whole-mechanism", "unilateral"};
// The status of an IDA record that stood up to the search's ceiling (study/measure.cpp, collapse_row): "... up to a PGA
// of X g (...)", "... a PGV of X m/s ...", X the last value run in the row's measure.
constexpr const char* kCensoredStatus = "failed: does not overturn up to a";
constexpr const char* kCensoredValue = " of ";
// The status of an IDA record that overturned at the first scale tried, with that PGA in parentheses ("(0.12 g)"), and
// in another measure after it ("(0.12 g; 0.034 m/s in PGV)").
constexpr const char* kAtThresholdStatus = "failed: overturns at the scale where the record's PGA equals the rest";

// What one series ran, keyed by run.
struct SeriesRuns {
    std::map<Key, double> peak, overturned;
    std::map<Key, IdaRecord> ida;
    std::map<Key, std::vector<double>> perturbed_peak;  // the reference's perturbed repeats
    std::map<Key, long> ida_failed;  // collapse_pga rows that failed otherwise than censored
};

struct Columns {
    std::size_t file, pga, perturbation, max_pga;
    std::vector<std::size_t> cleared, wall;
    std::size_t peak_metric, overturned_metric, collapse_metric;
    std::size_t scale = std::string::npos;
    std::vector<std::uint32_t> pga_stripe{};  // each pga level's stripe (nominal_pga), empty without a pga column
    bool is_stripe(std::uint32_t l) const { return l < pga_stripe.size() && pga_stripe[l] == l && l != kEmptyLevel; }
};

std::size_t metric_index(const StudyData& d, const std::string& name) {
    for (std::size_t m = 0; m < d.metrics.size(); ++m)
        if (d.metrics[m].name == name) return m;
    return std::string::npos;
}

// The intensity measure of the study's ensemble: the `intensity` column's first word other than pga, else the first of
// pgv, sa, arias that is a column (stripes) or whose collapse metric the study reports (IDA), else the PGA.
std::string ensemble_intensity(const StudyData& d) {
    // The ensemble's own word, when results.csv names it (a part in another measure than the PGA).
    if (const std::size_t col = d.column("intensity"); col != std::string::npos)
        for (std::uint32_t l : d.columns[col].order)
            if (!d.columns[col].texts[l].empty() && d.columns[col].texts[l] != "pga") return d.columns[col].texts[l];
    for (const char* m : {"pgv", "sa", "arias"})
        if (d.column(m) != std::string::npos || metric_index(d, std::string("collapse_") + m) != std::string::npos)
            return m;
    return "pga";
}

Columns columns_of(const StudyData& d) {
    const std::string im = ensemble_intensity(d);
    Columns c{d.column("file"), d.column(im), d.column("perturbation"), d.column("max_pga"), {0, d.columns.size() - 1},
              {}, metric_index(d, "peak_rotation"), metric_index(d, "overturned"), metric_index(d, "collapse_" + im)};
    for (std::size_t a : d.assumption_columns)
        if (a != std::string::npos) c.cleared.push_back(a);
    // Records scaled to another measure's level: their PGA follows from the file and the level, as the scale does.
    if (im != "pga" && d.column("pga") != std::string::npos) c.cleared.push_back(d.column("pga"));
    if (c.perturbation != std::string::npos) c.cleared.push_back(c.perturbation);
    // The scale follows from the file and the pga (and differs on a perturbed repeat): not part of a run's key.
    c.scale = d.column("scale");
    if (c.scale != std::string::npos) c.cleared.push_back(c.scale);
    for (std::size_t i = 0; i < d.columns.size(); ++i)
        if (std::find(kWallKeys.begin(), kWallKeys.end(), d.columns[i].key) != kWallKeys.end()) c.wall.push_back(i);
    return c;
}

bool nominal(const StudyData& d, const Columns& c, const StudyRow& r) {
    if (c.perturbation == std::string::npos) return true;
    const std::string& p = d.text(r, c.perturbation);
    return p.empty() || p == "none";
}

// Each PGA level as the level of the stripe it belongs to: a nominal run's as the first nominal level within round-off
// of it (a record scaled to 0.85 g can read 0.8500000000000001 or ...02 in results.csv, the record's PGA times the
// scale), a perturbed run's as the nearest nominal one (a perturbation shifts the level by kBandIntensityStep, 1e-2, or not at all).
std::vector<std::uint32_t> nominal_pga(const StudyData& d, const Columns& c) {
    constexpr double kSameLevel = 1e-9;  // relative: round-off of a product, far below kBandIntensityStep
    if (c.pga == std::string::npos) return {};
    const ColumnLevels& col = d.columns[c.pga];
    std::vector<bool> is_nominal(col.texts.size(), false);
    for (const StudyRow& r : d.rows)
        if (nominal(d, c, r)) is_nominal[r.levels[c.pga]] = true;
    std::vector<std::uint32_t> stripe(col.texts.size(), kEmptyLevel);
    std::vector<std::uint32_t> stripes;  // the first level of each stripe, in the study's order
    for (std::uint32_t l : col.order) {
        if (!is_nominal[l]) continue;
        stripe[l] = l;
        for (std::uint32_t s : stripes)
            if (std::abs(col.values[l] - col.values[s]) <= kSameLevel * std::abs(col.values[s])) stripe[l] = s;
        if (stripe[l] == l) stripes.push_back(l);
    }
    std::vector<std::uint32_t> map(col.texts.size());
    for (std::uint32_t l = 0; l < col.texts.size(); ++l) {
        map[l] = l;
        double best = INFINITY;
        for (std::uint32_t s : stripes)
            if (std::abs(col.values[s] - col.values[l]) < best) {
                best = std::abs(col.values[s] - col.values[l]);
                map[l] = s;
            }
    }
    return map;
}

// An IDA row as a record: collapsed at its value, right-censored at the ceiling, or nothing (another failure).
std::optional<IdaRecord> ida_record(const StudyData& d, const Columns& c, const StudyRow& r) {
    (void)c;
    if (std::isfinite(r.value) && r.value > 0.0) return IdaRecord{r.value, true};
    const std::string& status = d.statuses[r.status];
    // Stood up to the last PGA run below max_pga: right-censored there.
    if (status.rfind(kCensoredStatus, 0) == 0) {
        const std::size_t of = status.find(kCensoredValue);
        const double cap = of == std::string::npos ? NAN : std::strtod(status.c_str() + of + std::strlen(kCensoredValue), nullptr);
        if (std::isfinite(cap) && cap > 0.0) return IdaRecord{cap, false};
        return std::nullopt;
    }
    // Overturned already at the first scale tried (the record's PGA at the wall's rest threshold): its collapse PGA
    // is at most that; taken as collapsing there (an upper bound of a record with the lowest capacity, which leaving it
    // out would bias the median up far more).
    if (status.rfind(kAtThresholdStatus, 0) == 0) {
        std::size_t open = status.rfind('(');
        if (const std::size_t other = status.find("; ", open); open != std::string::npos && other != std::string::npos)
            open = other + 1;
        const double at = open == std::string::npos ? NAN : std::strtod(status.c_str() + open + 1, nullptr);
        if (std::isfinite(at) && at > 0.0) return IdaRecord{at, true};
    }
    return std::nullopt;
}

std::vector<SeriesRuns> collect(const StudyData& d, const Columns& c) {
    std::vector<SeriesRuns> runs(d.series.size());
    for (const StudyRow& r : d.rows) {
        Key key = r.levels;
        for (std::size_t col : c.cleared) key[col] = kEmptyLevel;
        if (c.pga != std::string::npos) key[c.pga] = c.pga_stripe[key[c.pga]];
        const bool nominal_run = nominal(d, c, r);
        for (std::size_t s = 0; s < d.series.size(); ++s) {
            if (!d.in_series(r, d.series[s])) continue;
            SeriesRuns& sr = runs[s];
            if (r.metric == c.peak_metric) {
                if (nominal_run) sr.peak[key] = r.value;
                else if (std::isfinite(r.value)) sr.perturbed_peak[key].push_back(r.value);
            } else if (r.metric == c.overturned_metric && nominal_run) {
                sr.overturned[key] = r.value;
            } else if (r.metric == c.collapse_metric && nominal_run) {
                if (const auto rec = ida_record(d, c, r)) sr.ida[key] = *rec;
                else ++sr.ida_failed[key];
            }
        }
    }
    return runs;
}

std::size_t choose_reference(const StudyData& d, bool& preferred) {
    std::size_t first = std::string::npos;
    for (std::size_t s = 0; s < d.series.size(); ++s) {
        if (!d.series[s].analytic()) continue;
        if (first == std::string::npos) first = s;
        if (d.series[s].assumptions == kPreferredReference) {
            preferred = true;
            return s;
        }
    }
    preferred = false;
    return first;
}

Key wall_of(const Columns& c, const Key& key) {
    Key w;
    for (std::size_t col : c.wall) w.push_back(key[col]);
    return w;
}

compare::BootstrapOptions bootstrap_options() {
    compare::BootstrapOptions o;
    o.replicates = kEnsembleReplicates;
    o.confidence = kEnsembleConfidence;
    o.seed = kEnsembleSeed;
    return o;
}

void measure_ida(SeriesMeasures& m, const SeriesRuns& runs, const SeriesRuns* reference, const Key& wall,
                 const Columns& c, const std::string& intensity) {
    std::vector<IdaRecord> engine, ref;
    for (const auto& [key, rec] : runs.ida) {
        if (wall_of(c, key) != wall) continue;
        m.records.push_back(rec);
        if (!reference) continue;
        const auto it = reference->ida.find(key);
        if (it == reference->ida.end()) continue;
        engine.push_back(rec);
        ref.push_back(it->second);
    }
    for (const auto& [key, n] : runs.ida_failed)
        if (wall_of(c, key) == wall) m.left_out += n;
    m.ida = !m.records.empty() || m.left_out > 0;
    if (!m.ida) return;
    m.intensity = intensity + "_ida";
    m.fit = compare::bootstrap_fit(m.records, bootstrap_options());
    m.paired = static_cast<long>(engine.size());
    m.ratio.ratio = {NAN, NAN, NAN, 0};
    if (reference && !engine.empty()) m.ratio = compare::bootstrap_median_ratio(engine, ref, bootstrap_options());
}

// A run's record: its key without the level.
Key record_of(const Columns& c, Key key) {
    if (c.pga != std::string::npos) key[c.pga] = kEmptyLevel;
    return key;
}

// Each record's overturning at each nominal PGA level of the wall (1, 0, or -1 for no result), keyed by the run with
// its pga cleared.
std::map<Key, compare::StripeOutcomes> stripe_outcomes(const SeriesRuns& runs, const Key& wall,
                                                       const std::vector<std::uint32_t>& levels, const Columns& c) {
    std::map<Key, compare::StripeOutcomes> out;
    for (const auto& [key, over] : runs.overturned) {
        if (wall_of(c, key) != wall) continue;
        compare::StripeOutcomes& o = out.try_emplace(record_of(c, key), levels.size(), -1).first->second;
        const auto at = std::find(levels.begin(), levels.end(), key[c.pga]);
        if (at != levels.end() && std::isfinite(over)) o[static_cast<std::size_t>(at - levels.begin())] = over > 0.5;
    }
    return out;
}

// The stripes' lognormal fit and, against the reference, the paired ratio of medians over the records both ran.
void fit_stripes(SeriesMeasures& m, const SeriesRuns& runs, const SeriesRuns* reference, const Key& wall,
                 const StudyData& d, const Columns& c, const std::string& intensity) {
    const std::vector<std::uint32_t>& order = d.columns[c.pga].order;
    std::vector<std::uint32_t> levels;
    std::vector<double> pga;
    for (std::uint32_t l : order)
        if (c.is_stripe(l) && std::isfinite(d.columns[c.pga].values[l]) && d.columns[c.pga].values[l] > 0.0) {
            levels.push_back(l);
            pga.push_back(d.columns[c.pga].values[l]);
        }
    const auto own = stripe_outcomes(runs, wall, levels, c);
    std::vector<compare::StripeOutcomes> records, engine, ref;
    const auto theirs = reference ? stripe_outcomes(*reference, wall, levels, c) : decltype(own){};
    for (const auto& [key, o] : own) {
        records.push_back(o);
        const auto it = theirs.find(key);
        if (it == theirs.end()) continue;
        engine.push_back(o);
        ref.push_back(it->second);
    }
    if (records.empty() || pga.size() < 2) return;
    m.intensity = intensity + "_stripes";
    m.fit = compare::bootstrap_stripes(pga, records, bootstrap_options());
    m.paired = static_cast<long>(engine.size());
    m.ratio.ratio = {NAN, NAN, NAN, 0};
    if (reference && !engine.empty())
        m.ratio = compare::bootstrap_stripe_median_ratio(pga, engine, ref, bootstrap_options());
}

// A run as a reader finds it: the record's file name and the level ("rinaldi-228.at2 at 0.55 g", "... at 0.4 m/s").
std::string run_name(const StudyData& d, const Columns& c, const Key& key, const std::string& unit) {
    const std::string file = std::filesystem::path(d.columns[c.file].texts[key[c.file]]).filename().string();
    return c.pga == std::string::npos ? file
                                      : fmt::format("{} at {:g} {}", file, d.columns[c.pga].values[key[c.pga]], unit);
}

// One run against the reference's result (finite): discordant either way, or failed where the reference has one.
void count_discordant(SeriesMeasures& m, double over, double reference_over) {
    if (!std::isfinite(over)) ++m.failed_paired;
    else if (over > 0.5 && reference_over < 0.5) ++m.overturned_alone;
    else if (over < 0.5 && reference_over > 0.5) ++m.stood_alone;
}

void measure_stripes(SeriesMeasures& m, const SeriesRuns& runs, const SeriesRuns* reference, const Key& wall,
                     const StudyData& d, const Columns& c, const EnsembleMeasures& e) {
    long agree = 0, both = 0;
    std::vector<double> ratios;
    std::vector<compare::BandRun> band;
    std::vector<Key> band_runs;  // the run of each band entry, to name the ones outside
    std::map<std::uint32_t, std::pair<long, long>> per_level;  // pga level -> (overturned, runs)
    std::map<Key, std::vector<double>> log_ratios;  // by record (the run's key without its level)
    std::vector<double> half_widths;                // the band's 0.5 ln(hi / lo) where both stand
    for (const auto& [key, over] : runs.overturned) {
        if (wall_of(c, key) != wall) continue;
        m.stripes = true;
        // A failed run (no value) is no share of a level, and where the reference has a result it is a run the
        // series does not agree on: an engine does not pass by failing.
        if (!std::isfinite(over)) ++m.failed_runs;
        if (std::isfinite(over)) {
            auto& level = per_level[c.pga == std::string::npos ? kEmptyLevel : key[c.pga]];
            level.first += over > 0.5 ? 1 : 0;
            ++level.second;
        }
        if (!reference) continue;
        const auto peak = runs.peak.find(key);
        const double own_peak = peak == runs.peak.end() ? NAN : peak->second;
        bool both_stand = false;
        const auto ref_over = reference->overturned.find(key);
        const auto ref_peak = reference->peak.find(key);
        PairedRun* paired = nullptr;
        if (ref_over != reference->overturned.end() && std::isfinite(ref_over->second)) {
            m.paired_runs.push_back({run_name(d, c, key, e.unit), own_peak,
                                     ref_peak == reference->peak.end() ? NAN : ref_peak->second, NAN, NAN, over,
                                     ref_over->second});
            paired = &m.paired_runs.back();
            ++both;
            agree += std::isfinite(over) && (over > 0.5) == (ref_over->second > 0.5) ? 1 : 0;
            count_discordant(m, over, ref_over->second);
            if (over < 0.5 && ref_over->second < 0.5 && ref_peak != reference->peak.end() &&
                std::isfinite(ref_peak->second) && ref_peak->second != 0.0 && std::isfinite(own_peak)) {
                ratios.push_back(own_peak / ref_peak->second);
                both_stand = own_peak > 0.0 && ref_peak->second > 0.0;
                if (both_stand) log_ratios[record_of(c, key)].push_back(std::log(own_peak / ref_peak->second));
            }
        }
        const auto repeats = reference->perturbed_peak.find(key);
        if (repeats == reference->perturbed_peak.end() || ref_peak == reference->peak.end() ||
            !std::isfinite(ref_peak->second))
            continue;
        const auto [lo, hi] = std::minmax_element(repeats->second.begin(), repeats->second.end());
        band.push_back({ref_peak->second, std::min(*lo, ref_peak->second), std::max(*hi, ref_peak->second), own_peak});
        band_runs.push_back(key);
        if (paired) {
            paired->band_lo = band.back().lo;
            paired->band_hi = band.back().hi;
        }
        if (both_stand && band.back().lo > 0.0) half_widths.push_back(0.5 * std::log(band.back().hi / band.back().lo));
    }
    if (!m.stripes) return;
    m.overturning = both > 0 ? compare::wilson_interval(agree, both, kEnsembleConfidence)
                             : compare::Interval{NAN, NAN, NAN, 0};
    m.peak_ratio = compare::quartiles(ratios);
    std::vector<std::vector<double>> by_record;
    for (auto& [record, d_values] : log_ratios) by_record.push_back(std::move(d_values));
    m.log_peak_ratio = compare::record_median_interval(by_record, kEnsembleConfidence);
    m.band = !band.empty();
    if (m.band) {
        m.inside = compare::count_inside_band(band);
        m.band_half_width = compare::quantile(half_widths, 0.5);
        for (std::size_t i : m.inside.outside) m.outside_band.push_back(run_name(d, c, band_runs[i], e.unit));
    }
    if (c.pga == std::string::npos) return;
    if (!m.ida) fit_stripes(m, runs, reference, wall, d, c, e.intensity);
    for (std::uint32_t l : d.columns[c.pga].order) {
        if (!c.is_stripe(l)) continue;
        const auto it = per_level.find(l);
        if (it == per_level.end()) continue;
        m.levels.push_back({d.columns[c.pga].values[l],
                            compare::wilson_interval(it->second.first, it->second.second, kEnsembleConfidence)});
    }
}

// The measure's word, unit and axis label; Sa's with its oscillator, from the study's first sa_period and sa_damping.
void describe_intensity(const StudyData& d, EnsembleMeasures& e) {
    Intensity im;
    im.measure = parse_intensity_measure(ensemble_intensity(d));
    const auto first = [&](const char* name, double fallback) {
        const std::size_t col = d.column(name);
        if (col == std::string::npos) return fallback;
        for (std::uint32_t l : d.columns[col].order)
            if (std::isfinite(d.columns[col].values[l])) return d.columns[col].values[l];
        return fallback;
    };
    im.sa_period = first("sa_period", NAN);
    im.sa_damping = first("sa_damping", kDefaultSaDamping);
    e.intensity = to_string(im.measure);
    e.unit = intensity_unit(im.measure);
    e.label = intensity_label(im);
    e.name = e.label.substr(0, e.label.rfind(" ["));
}

}  // namespace

bool repeats_earlier(const StudyData& d, std::size_t s) {
    for (std::size_t t = 0; t < s; ++t)
        if (d.series[t].engine == d.series[s].engine && d.series[t].settings == d.series[s].settings &&
            d.series[t].assumptions == d.series[s].assumptions)
            return true;
    return false;
}

std::string assumptions_text(const Series& s) {
    std::string out = s.analytic() && !s.set.empty() ? "set=" + s.set : std::string();
    for (std::size_t i = 0; i < kAssumptionKeys.size() && s.analytic(); ++i)
        if (!s.assumptions[i].empty()) out += fmt::format("{}{}={}", out.empty() ? "" : " ", kAssumptionKeys[i],
                                                          s.assumptions[i]);
    return out;
}

EnsembleMeasures ensemble_measures(const StudyData& d) {
    EnsembleMeasures e;
    Columns c = columns_of(d);
    c.pga_stripe = nominal_pga(d, c);
    if (c.file == std::string::npos || d.columns[c.file].order.size() < 2) return e;
    if (c.overturned_metric == std::string::npos && c.collapse_metric == std::string::npos) return e;
    e.applies = true;
    describe_intensity(d, e);
    e.reference = choose_reference(d, e.preferred_reference);
    e.has_reference = e.reference != std::string::npos;
    const std::vector<SeriesRuns> runs = collect(d, c);
    std::map<Key, std::size_t> wall_index;
    std::vector<Key> walls;
    for (const StudyRow& r : d.rows) {
        const Key w = wall_of(c, r.levels);
        const auto [at, added] = wall_index.emplace(w, walls.size());
        if (added) walls.push_back(w);
        e.case_wall[r.case_id] = at->second;
    }
    std::vector<std::size_t> varied_walls;
    for (std::size_t col : c.wall)
        if (d.columns[col].varied) varied_walls.push_back(col);
    for (std::size_t w = 0; w < walls.size(); ++w) {
        Key levels;
        for (std::size_t col : varied_walls)
            levels.push_back(walls[w][static_cast<std::size_t>(std::find(c.wall.begin(), c.wall.end(), col) -
                                                               c.wall.begin())]);
        e.walls.push_back(levels_title(d, varied_walls, levels));
        for (std::size_t s = 0; s < d.series.size(); ++s) {
            if (repeats_earlier(d, s)) continue;
            SeriesMeasures m;
            m.series = s;
            m.wall = w;
            const SeriesRuns* reference = e.has_reference && s != e.reference ? &runs[e.reference] : nullptr;
            measure_ida(m, runs[s], reference, walls[w], c, e.intensity);
            measure_stripes(m, runs[s], reference, walls[w], d, c, e);
            if (m.ida || m.stripes) e.measures.push_back(std::move(m));
        }
    }
    return e;
}

std::vector<RockingCurve> rocking_curves(const StudyData& d) {
    Columns c = columns_of(d);
    c.pga_stripe = nominal_pga(d, c);
    const std::size_t alpha = d.column("alpha"), size = d.column("R");
    if (c.file == std::string::npos || d.columns[c.file].order.size() < 2 || alpha == std::string::npos ||
        !d.columns[alpha].varied || c.peak_metric == std::string::npos)
        return {};
    // (series, R level, stripe) -> alpha level -> peaks and overturned runs over the records; an overturned run's peak
    // counts as the largest (study/overturned_runs.hpp), not as its collapse angle.
    const Overturning over(d);
    using CurveKey = std::tuple<std::size_t, std::uint32_t, std::uint32_t>;
    std::map<CurveKey, std::map<std::uint32_t, std::pair<std::vector<double>, long>>> groups;
    for (const StudyRow& r : d.rows) {
        if (r.metric != c.peak_metric || !nominal(d, c, r)) continue;
        const std::uint32_t stripe = c.pga == std::string::npos ? kEmptyLevel : c.pga_stripe[r.levels[c.pga]];
        const std::uint32_t R = size == std::string::npos ? kEmptyLevel : r.levels[size];
        for (std::size_t s = 0; s < d.series.size(); ++s)
            if (!repeats_earlier(d, s) && d.in_series(r, d.series[s]))
                groups[{s, R, stripe}][r.levels[alpha]].first.push_back(over.overturned(r) ? kOverturnedPeak : r.value);
    }
    for (const StudyRow& r : d.rows) {  // the overturned runs, counted where their peak is
        if (r.metric != c.overturned_metric || !nominal(d, c, r) || !(r.value > 0.5)) continue;
        const std::uint32_t stripe = c.pga == std::string::npos ? kEmptyLevel : c.pga_stripe[r.levels[c.pga]];
        const std::uint32_t R = size == std::string::npos ? kEmptyLevel : r.levels[size];
        for (std::size_t s = 0; s < d.series.size(); ++s)
            if (!repeats_earlier(d, s) && d.in_series(r, d.series[s])) ++groups[{s, R, stripe}][r.levels[alpha]].second;
    }
    std::vector<RockingCurve> out;
    for (const auto& [key, by_alpha] : groups) {
        const auto& [s, R, stripe] = key;
        RockingCurve curve{s, size == std::string::npos ? NAN : d.columns[size].values[R],
                           c.pga == std::string::npos ? NAN : d.columns[c.pga].values[stripe], {}};
        for (std::uint32_t a : d.columns[alpha].order) {
            const auto it = by_alpha.find(a);
            if (it == by_alpha.end()) continue;
            curve.points.push_back({d.columns[alpha].values[a], compare::quartiles(it->second.first),
                                    it->second.second});
        }
        out.push_back(std::move(curve));
    }
    return out;
}

}  // namespace vssw::study
