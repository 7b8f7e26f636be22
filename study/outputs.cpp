#include "study/outputs.hpp"

#include <fstream>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "study/atomic_file.hpp"
#include "study/results_files.hpp"
#include "study/runner.hpp"

namespace vssw::study {

nlohmann::ordered_json read_manifest(const std::filesystem::path& dir) {
    const std::filesystem::path path = dir / kManifestFile;
    std::ifstream in(path);
    if (!in) throw InputError(fmt::format("cannot read '{}' (not a study folder?)", path.string()));
    try {
        return nlohmann::ordered_json::parse(in);
    } catch (const std::exception& e) {
        throw InputError(fmt::format("'{}' is not a study manifest: {}", path.string(), e.what()));
    }
}

OutputFiles write_study_outputs(const std::filesystem::path& dir, const OutputOptions& options) {
    OutputFiles files;
    const nlohmann::ordered_json manifest = read_manifest(dir);
    {
        AtomicFile json(dir / kResultsJson);
        write_results_json(json.stream(), manifest, dir / kResultsCsv);
        json.commit();
        files.written.push_back(dir / kResultsJson);
    }
    (void)options;
    return files;
}

}  // namespace vssw::study
