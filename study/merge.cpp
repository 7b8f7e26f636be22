#include "study/merge.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <memory>
#include <set>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "analytic/input_file.hpp"
#include "io/atomic_file.hpp"
#include "io/csv.hpp"
#include "io/json.hpp"
#include "study/ida_curves.hpp"
#include "study/outputs.hpp"
#include "study/results_files.hpp"
#include "study/runner.hpp"

namespace vssw::study {
namespace fs = std::filesystem;
namespace {

using Json = nlohmann::ordered_json;

// One shard's results.csv, read a case's block at a time.
struct ShardReader {
    fs::path path;
    std::ifstream in;
    std::vector<std::string> header, next;  // `next`: the first row not yet taken (empty at the end)
    long case_id = -1;
    long rows = 0;  // rows read so far
    // The current case's rows by what identifies them (every column but the value and what describes it): a row
    // given twice is refused.
    std::set<std::vector<std::string>> case_keys;
    std::vector<std::size_t> key_columns;

    explicit ShardReader(const fs::path& p)
        : path(p), in(open_input_file(p, "study merge: the shard's results", kMaxResultsBytes)) {
        if (!io::read_csv_record(in, header) || header.empty() || header.front() != "case_id")
            throw InputError(fmt::format("'{}' is not a study's results.csv", path.string()));
        for (std::size_t i = 0; i < header.size(); ++i)
            if (header[i] != "value" && header[i] != "unit" && header[i] != "status" && header[i] != "warnings")
                key_columns.push_back(i);
        advance();
    }
    void advance() {
        next.clear();
        case_id = -1;
        if (!io::read_csv_record(in, next)) return;
        if (next.size() != header.size())
            throw InputError(fmt::format("'{}': a row with {} fields, the header has {}", path.string(), next.size(),
                                         header.size()));
        char* end = nullptr;
        case_id = std::strtol(next[0].c_str(), &end, 10);
        if (next[0].empty() || *end != '\0')
            throw InputError(fmt::format("'{}': case_id '{}' is not a number", path.string(), next[0]));
        ++rows;
        std::vector<std::string> key;
        for (const std::size_t i : key_columns) key.push_back(next[i]);
        if (!case_keys.empty() && key.front() != case_keys.begin()->front()) case_keys.clear();
        if (!case_keys.insert(std::move(key)).second)
            throw InputError(fmt::format("study merge: '{}' repeats a row at line {} (case {}): a damaged shard; run "
                                         "it again",
                                         path.string(), rows + 1, next[0]));
    }
};

// Refuses a shard folder that cannot take part: it is --out itself, unfinished, of another study, split or engine
// versions than the first, or its results.csv is not the one its manifest records.
void check_shard(const fs::path& d, const Json& m, const Json& first, const fs::path& first_dir, const fs::path& out) {
    std::error_code ec;
    if (fs::equivalent(d, out, ec))  // the merged files would replace this shard's own
        throw InputError(fmt::format("study merge: --out '{}' is the shard folder '{}': merge into another folder",
                                     out.string(), d.string()));
    if (m.at("study").at("identity") != first.at("study").at("identity"))
        throw InputError(fmt::format("study merge: '{}' holds another study ({}) than '{}' ({})", d.string(),
                                     m["study"]["name"].get<std::string>(), first_dir.string(),
                                     first["study"]["name"].get<std::string>()));
    if (m.at("shard").at("n") != first.at("shard").at("n"))
        throw InputError(fmt::format("study merge: '{}' is shard {}/{}, '{}' of a split into {}", d.string(),
                                     m["shard"]["k"].get<int>(), m["shard"]["n"].get<int>(), first_dir.string(),
                                     first["shard"]["n"].get<int>()));
    if (m.at("engines") != first.at("engines"))
        throw InputError(fmt::format("study merge: '{}' was run by other engine versions than '{}' ({} against {})",
                                     d.string(), first_dir.string(), io::dump_json(m["engines"]), io::dump_json(first["engines"])));
    // The file the shard's run wrote: its rows (each once), then byte for byte (a manifest of an older vssw records
    // no "results": its rows are still checked for repeats while merging).
    if (!m.contains("results")) return;
    ShardReader reader(d / kResultsCsv);
    while (reader.case_id >= 0) reader.advance();
    const long rows = m["results"].value("rows", -1L);
    if (reader.rows != rows)
        throw InputError(fmt::format("study merge: '{}' holds {} rows, its manifest.json records {}: a damaged shard; "
                                     "run it again",
                                     reader.path.string(), reader.rows, rows));
    const std::string recorded = m["results"].value("fnv1a64", "");
    const std::string now = file_fnv1a(d / kResultsCsv);
    if (now != recorded)
        throw InputError(fmt::format("study merge: '{}' is not the results.csv its manifest records (FNV-1a {}, "
                                     "recorded {}): it was changed after the run; run the shard again",
                                     (d / kResultsCsv).string(), now, recorded));
}

// The shards' manifests, each shard checked, every shard of the split given once and all the study's cases held.
std::vector<Json> read_shards(const std::vector<fs::path>& dirs, const fs::path& out) {
    if (dirs.empty()) throw InputError("study merge: name the shards' folders");
    std::vector<Json> manifests;
    std::set<int> ks;
    for (const fs::path& d : dirs) {
        std::error_code ec;
        if (fs::exists(d / kJournalFile, ec))
            throw InputError(fmt::format("study merge: '{}' holds an unfinished shard ({}): finish it with --resume",
                                         d.string(), kJournalFile));
        manifests.push_back(read_manifest(d));
        check_shard(d, manifests.back(), manifests.front(), dirs.front(), out);
        const int k = manifests.back()["shard"]["k"].get<int>();
        if (!ks.insert(k).second)
            throw InputError(fmt::format("study merge: shard {} is given twice ('{}')", k, d.string()));
    }
    const int n = manifests.front()["shard"]["n"].get<int>();
    std::vector<int> missing;
    for (int k = 1; k <= n; ++k)
        if (!ks.count(k)) missing.push_back(k);
    if (!missing.empty())
        throw InputError(fmt::format("study merge: shard{} {} of {} missing", missing.size() == 1 ? "" : "s",
                                     fmt::join(missing, ", "), n));
    long shard_cases = 0;
    for (const Json& m : manifests) shard_cases += m["cases"]["run"].get<long>();
    const Json& cases_of = manifests.front()["cases"];
    if (cases_of.contains("total") && shard_cases != cases_of["total"].get<long>())
        throw InputError(fmt::format("study merge: the shards hold {} cases, the study {}", shard_cases,
                                     cases_of["total"].get<long>()));
    return manifests;
}

// results.csv: the shards' case blocks in case order (each shard's file is in case order already); counts the rows
// and the failed ones into `result`.
void write_merged_results(const std::vector<fs::path>& dirs, const fs::path& file, MergeResult& result) {
    std::vector<std::unique_ptr<ShardReader>> readers;
    for (const fs::path& d : dirs) {
        readers.push_back(std::make_unique<ShardReader>(d / kResultsCsv));
        if (readers.back()->header != readers.front()->header)
            throw InputError(fmt::format("study merge: '{}' has other columns than '{}'", readers.back()->path.string(),
                                         readers.front()->path.string()));
    }
    const std::vector<std::string>& header = readers.front()->header;
    const std::size_t status =
        static_cast<std::size_t>(std::find(header.begin(), header.end(), "status") - header.begin());
    io::AtomicFile csv(file);
    for (std::size_t i = 0; i < header.size(); ++i) csv.stream() << (i ? "," : "") << io::csv_field(header[i]);
    csv.stream() << '\n';
    for (;;) {
        ShardReader* pick = nullptr;
        for (const auto& r : readers)
            if (r->case_id >= 0 && (!pick || r->case_id < pick->case_id)) pick = r.get();
        if (!pick) break;
        const long id = pick->case_id;
        for (const auto& r : readers)
            if (r.get() != pick && r->case_id == id)
                throw InputError(fmt::format("study merge: case {} is in two shards", id));
        while (pick->case_id == id) {
            for (std::size_t i = 0; i < pick->next.size(); ++i)
                csv.stream() << (i ? "," : "") << io::csv_field(pick->next[i]);
            csv.stream() << '\n';
            ++result.rows;
            if (status < pick->next.size() && pick->next[status] != "ok") ++result.failed_rows;
            pick->advance();
        }
    }
    csv.commit();
}

// The manifest of the whole study: the shards' run times side by side, the longest as the study's (shards run in
// parallel), the tasks summed.
void write_merged_manifest(const std::vector<Json>& manifests, const fs::path& dest, const MergeResult& result) {
    Json merged = manifests.front();
    merged["shard"] = {{"k", 1}, {"n", 1}};
    Json shards = Json::array();
    double longest = 0.0;
    long run = 0, resumed = 0, cases = 0;
    for (const Json& m : manifests) {
        cases += m["cases"]["run"].get<long>();
        shards.push_back({{"k", m["shard"]["k"]}, {"wall_time_s", m["wall_time_s"]}, {"threads", m["threads"]},
                          {"processes", m["processes"]}, {"date", m["date"]}});
        longest = std::max(longest, m["wall_time_s"].get<double>());
        run += m["tasks"]["run"].get<long>();
        resumed += m["tasks"]["resumed"].get<long>();
    }
    std::sort(shards.begin(), shards.end(), [](const Json& a, const Json& b) { return a["k"] < b["k"]; });
    merged["merged_from"] = shards;
    merged["tasks"] = {{"run", run}, {"resumed", resumed}};
    merged["cases"]["run"] = cases;
    merged["wall_time_s"] = longest;
    merged["results"] = {{"rows", result.rows}, {"fnv1a64", file_fnv1a(dest / kResultsCsv)}};
    io::AtomicFile manifest(dest / kManifestFile);
    manifest.stream() << io::dump_json(merged, 2) << '\n';
    manifest.commit();
}

}  // namespace

MergeResult merge_studies(const std::vector<fs::path>& dirs, const fs::path& out, const fs::path& write_to) {
    const fs::path dest = write_to.empty() ? out : write_to;
    const std::vector<Json> manifests = read_shards(dirs, out);
    std::error_code ec;
    fs::create_directories(dest, ec);
    if (ec) throw InputError(fmt::format("cannot create the output folder '{}': {}", dest.string(), ec.message()));
    MergeResult result;
    result.shards = manifests.front()["shard"]["n"].get<int>();
    write_merged_results(dirs, dest / kResultsCsv, result);
    merge_ida_csv(dirs, dest);
    write_merged_manifest(manifests, dest, result);
    return result;
}

}  // namespace vssw::study
