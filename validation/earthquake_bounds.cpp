#include "validation/earthquake_bounds.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <system_error>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "io/temp_registry.hpp"
#include "multibody/engine.hpp"
#include "validation/earthquake.hpp"

namespace vssw::validation {
namespace {

namespace fs = std::filesystem;

// A folder of its own under the system's temporary folder, registered (a signal removes it) and removed at the end.
class ScratchFolder {
public:
    ScratchFolder() {
        std::string pattern = (fs::temp_directory_path() / "vssw-check-earthquake-XXXXXX").string();
        if (mkdtemp(pattern.data()) == nullptr)
            throw InputError(fmt::format("cannot create a temporary folder in {}", fs::temp_directory_path().string()));
        path_ = pattern;
        registration_.emplace(path_);
    }
    ~ScratchFolder() {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    ScratchFolder(const ScratchFolder&) = delete;
    ScratchFolder& operator=(const ScratchFolder&) = delete;
    const fs::path& path() const { return path_; }

private:
    fs::path path_;
    std::optional<io::TempRegistration> registration_;
};

// Each ensemble once, for the engines its bounds name.
std::map<std::string, std::vector<std::string>> engines_by_study(const std::vector<EarthquakeBound>& bounds) {
    std::map<std::string, std::vector<std::string>> out;
    for (const EarthquakeBound& b : bounds) {
        std::vector<std::string>& e = out[b.study];
        if (std::find(e.begin(), e.end(), b.engine) == e.end()) e.push_back(b.engine);
    }
    return out;
}

double measure_of(const EarthquakeVerdict& v, const std::string& measure) {
    if (measure == "overturning_agreement") return v.agreement.value;
    if (measure == "fragility_median_ratio") return v.median_ratio.value;
    if (measure == "peak_ratio_median") return v.peak_ratio.median;
    if (measure == "inside_band")
        return v.band_runs > 0 ? static_cast<double>(v.inside) / static_cast<double>(v.band_runs) : NAN;
    return NAN;
}

}  // namespace

void plan_earthquake_bounds(const std::vector<EarthquakeBound>& bounds, const std::string& path) {
    const std::vector<std::string> available = multibody::available_engines();
    for (const EarthquakeBound& b : bounds)
        if (std::find(available.begin(), available.end(), b.engine) == available.end())
            throw InputError(fmt::format("bounds file {}: earthquake bound: engine '{}' is not in this build", path,
                                         b.engine));
    for (const auto& [study_name, engines] : engines_by_study(bounds)) try {
            (void)earthquake_study_file(study_name, engines);
        } catch (const InputError& e) {
            throw InputError(fmt::format("bounds file {}: earthquake bound: {}", path, e.what()));
        }
}

std::vector<BoundVerdict> check_earthquake_bounds(const std::vector<EarthquakeBound>& bounds,
                                                           int threads) {
    std::map<std::string, EarthquakePart> parts;
    for (const auto& [study_name, engines] : engines_by_study(bounds)) {
        const ScratchFolder scratch;
        EarthquakeRunOptions o;
        o.threads = threads;
        o.plots = false;
        parts.emplace(study_name, run_earthquake_part(earthquake_study_file(study_name, engines), engines,
                                                             scratch.path() / "earthquake", o));
    }
    std::vector<BoundVerdict> out;
    for (const EarthquakeBound& b : bounds) {
        const EarthquakePart& part = parts.at(b.study);
        BoundVerdict v{b.engine, part.study_name, b.measure, NAN, b.min, b.max, false, "", "", "", true};
        for (const EarthquakeVerdict& e : part.engines)
            if (e.engine == b.engine) {
                v.value = measure_of(e, b.measure);
                if (b.measure == "fragility_median_ratio" && !e.fit_note.empty()) v.note = e.fit_note;
            }
        v.held = v.value >= b.min && v.value <= b.max;  // NaN: does not hold
        if (std::isnan(v.value) && v.note.empty()) v.note = "not measured";
        out.push_back(v);
    }
    return out;
}

}  // namespace vssw::validation
