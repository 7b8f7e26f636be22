#include "validation/study_engines.hpp"

#include <algorithm>

#include <nlohmann/json.hpp>

#include "io/json.hpp"

namespace vssw::validation {

study::StudySpec with_engines(const std::string& file, const std::vector<std::string>& engines) {
    const study::StudySpec read = study::read_study_file(file);
    io::Json doc = read.as_read;
    io::Json names = io::Json::array({"analytic"});
    for (const std::string& e : engines)
        if (e != "analytic") names.push_back(e);
    doc["engines"] = names;
    const auto prune = [&names](io::Json& table) {
        if (!table.contains("settings") || !table["settings"].is_object()) return;
        for (auto it = table["settings"].begin(); it != table["settings"].end();)
            it = std::find(names.begin(), names.end(), it.key()) == names.end() ? table["settings"].erase(it)
                                                                                 : std::next(it);
    };
    prune(doc);
    if (doc.contains("part") && doc["part"].is_array())
        for (io::Json& part : doc["part"]) prune(part);
    study::StudySpec spec = study::study_from_json(nlohmann::json::parse(io::dump_json(doc)), file, read.base_dir);
    spec.path = read.path;
    return spec;
}

study::StudyRunOptions study_run_options(const PartRunOptions& options) {
    study::StudyRunOptions run;
    run.threads = options.threads;
    run.commit = options.commit;
    run.progress = options.progress;
    run.task_cpu = options.task_cpu;
    return run;
}

StudyPartRun study_part_run(const std::string& file, const study::StudySpec& spec, const std::filesystem::path& dir,
                            const study::StudyRunResult& result) {
    return {file, spec.name, spec.description, dir, result.rows, result.failed_rows, result.meta.wall_time_s};
}

}  // namespace vssw::validation
