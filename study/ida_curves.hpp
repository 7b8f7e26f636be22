#pragma once
// Incremental dynamic analysis curves (Vamvatsikos & Cornell 2002, Earthquake Engng Struct. Dyn. 31:491-514): every
// run of a study's scale-to-collapse searches as a point (intensity, peak |theta1| / alpha1) of its record's curve.
//
//   ida.csv        one row per run of a search, tasks in case then run order, each task's runs in the order run:
//                  case_id, engine, assumptions, settings, record, scale, measure (pga, pgv, sa, arias: the part's
//                  ensemble intensity, else pga), intensity (the record's measure at that scale, in intensity_unit),
//                  intensity_unit, peak_over_alpha1 (the collapse angle's when it overturned), overturned (0 or 1).
//                  Written by the runner from the journal (study/journal.hpp), since results.csv keeps only each
//                  search's answer; `vssw study merge` joins the shards' files.
//   plots/ida.svg  a panel per wall: each record's curve (its points sorted by intensity, a resurrection, a larger
//                  intensity that stands after one that overturned, kept), per series the 16, 50 and 84 % fractiles
//                  of the intensity given the peak (the capacity view: at each peak y, each record's lowest intensity
//                  whose curve, linear between its runs from (0, 0), reaches y; a record whose curve never does counts
//                  as infinite, so an upper fractile beyond the searches is not drawn).
#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "study/ensemble_measures.hpp"
#include "study/grid.hpp"
#include "study/journal.hpp"
#include "study/study_data.hpp"
#include "study/study_plots.hpp"

namespace vssw::study {

constexpr const char* kIdaCsv = "ida.csv";
extern const char* const kIdaSection;

// ida.csv from the journal's IDA points (stable-sorted by case id and run, each task's points in the order run).
void write_ida_csv(std::ostream& out, const Grid& grid, std::vector<IdaRow> rows);
// The shards' ida.csv (those that have one) as one, in case order, into dest; nothing when none has one.
void merge_ida_csv(const std::vector<std::filesystem::path>& shard_dirs, const std::filesystem::path& dest);

// A record's curve under one series, as ida.csv holds it.
struct IdaCurve {
    int case_id = 0;
    std::string engine, assumptions, settings, record, measure, unit;
    std::vector<double> intensity, peak;  // sorted by intensity
    std::vector<bool> overturned;
};
// ida.csv's curves, in the file's order of their first row. InputError naming the file when it is malformed.
std::vector<IdaCurve> read_ida_csv(const std::filesystem::path& path);

// The lowest intensity at which the curve, linear between its points from (0, 0), reaches a peak of y; +infinity when
// it never does.
double intensity_reaching(const IdaCurve& curve, double y);
// The q-quantile (0..1) of the values, linear between order statistics (Hyndman & Fan's type 7); +infinity where it
// falls on or next to an infinite value.
double fractile(std::vector<double> values, double q);

// plots/ida.svg's script (nothing when there are no curves).
void add_ida_plot(const StudyData& d, const EnsembleMeasures& e, const std::vector<IdaCurve>& curves, StudyPlots& out);

}  // namespace vssw::study
