// `vssw motions`: ground motions of our own. `generate` draws a seeded set from the stochastic model of Rezaeian &
// Der Kiureghian (motions/, docs/ground-motions.md); `describe` measures any record the readers accept.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "analytic/error.hpp"
#include "analytic/ground_motion.hpp"
#include "cli/commands.hpp"
#include "cli/option_values.hpp"
#include "cli/progress.hpp"
#include "cli/table.hpp"
#include "io/csv.hpp"
#include "io/json.hpp"
#include "motions/measures.hpp"
#include "motions/motion_set.hpp"

namespace vssw::cli {
namespace {

struct GenerateOptions {
    std::string count_text, seed_text, out;
    std::optional<std::string> mechanism;  // strike-slip when a scenario is given without it
    std::optional<double> magnitude, distance, vs30;
    std::optional<double> arias, d5_95, t_mid, mid_frequency, slope, damping;
    double scatter = 1.0;
    motions::SimulationSettings simulation;
    bool json = false;
};

struct DescribeOptions {
    std::vector<std::string> files;
    std::optional<std::string> units;
    bool csv = false, json = false;
};

std::uint64_t parse_seed(const std::string& text) {
    const bool digits = !text.empty() && text.size() <= 20 && text.find_first_not_of("0123456789") == std::string::npos;
    if (digits) {
        try {
            return std::stoull(text);
        } catch (const std::exception&) {
        }
    }
    throw InputError(fmt::format("--seed must be an integer from 0 to {}, got {}",
                                 std::numeric_limits<std::uint64_t>::max(), text.empty() ? "an empty value" : text));
}

motions::DrawSettings draw_settings(const GenerateOptions& o) {
    motions::DrawSettings d;
    const int given = int(o.magnitude.has_value()) + int(o.distance.has_value()) + int(o.vs30.has_value());
    if (given != 0 && given != 3)
        throw InputError("--magnitude, --distance and --vs30 name a scenario together: give all three or none");
    if (o.mechanism && given == 0)
        throw InputError(fmt::format("--mechanism {} names a scenario's faulting: give it with --magnitude, --distance "
                                     "and --vs30",
                                     *o.mechanism));
    const std::string mechanism = o.mechanism.value_or("strike-slip");
    if (mechanism != "strike-slip" && mechanism != "reverse")
        throw InputError(fmt::format("--mechanism must be strike-slip or reverse, got {}", mechanism));
    if (given == 3) d.scenario = motions::Scenario{*o.magnitude, *o.distance, *o.vs30, mechanism == "reverse"};
    d.medians = {o.arias, o.d5_95, o.t_mid, o.mid_frequency, o.slope, o.damping};
    d.scatter = o.scatter;
    return d;
}

nlohmann::json number_or_null(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

void run_generate(const GenerateOptions& o, std::ostream& out, std::ostream& err) {
    motions::MotionSetRequest request;
    request.count = parse_bounded_int("--count", o.count_text, 1, motions::kMaxMotions);
    request.seed = parse_seed(o.seed_text);
    request.draws = draw_settings(o);
    request.simulation = o.simulation;
    request.out = o.out;
    Progress progress(err);
    const auto start = std::chrono::steady_clock::now();
    const auto rows = motions::write_motion_set(request, [&](int done, int total) {
        if (progress.on()) progress.show(done, total, "motions generated");
    });
    progress.clear();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (o.json) {
        nlohmann::json j = {{"out", o.out}, {"count", rows.size()}, {"seed", request.seed}, {"seconds", seconds}};
        out << io::dump_json(j, 2) << '\n';
        return;
    }
    Table t("Generated motions (Rezaeian & Der Kiureghian model)");
    t.text("folder", o.out);
    t.add("motions", std::to_string(rows.size()));
    t.add("seed", std::to_string(request.seed));
    t.add("time", io::num(seconds), "s");
    t.text("table", (std::filesystem::path(o.out) / "motions.csv").string());
    t.print(out);
}

std::vector<std::pair<std::string, motions::Measures>> measure_files(const DescribeOptions& o) {
    std::optional<AccelUnits> units;
    if (o.units) units = parse_units(*o.units);
    std::vector<std::pair<std::string, motions::Measures>> rows;
    for (const std::string& file : o.files) {
        const GroundMotion record = read_record(file, units ? &*units : nullptr);
        rows.emplace_back(file, motions::measure(record));
    }
    return rows;
}

void run_describe(const DescribeOptions& o, std::ostream& out) {
    if (o.csv && o.json) throw InputError("--csv and --json: choose one");
    const auto rows = measure_files(o);
    if (o.csv) {
        out << "file,pga_g,pgv_m_s,arias_m_s,d5_95_s,t_mid_s,mid_frequency_hz,duration_s,dt_s\n";
        for (const auto& [file, m] : rows)
            out << fmt::format("{},{},{},{},{},{},{},{},{}\n", io::csv_field(file), io::csv_number(m.pga_g),
                               io::csv_number(m.pgv_m_s), io::csv_number(m.arias_m_s),
                               io::csv_number(m.d5_95_s), io::csv_number(m.t_mid_s),
                               io::csv_number(m.mid_frequency_hz), io::csv_number(m.duration_s),
                               io::csv_number(m.dt_s));
        return;
    }
    if (o.json) {
        nlohmann::json list = nlohmann::json::array();
        for (const auto& [file, m] : rows)
            list.push_back({{"file", file}, {"pga_g", number_or_null(m.pga_g)}, {"pgv_m_s", number_or_null(m.pgv_m_s)},
                            {"arias_m_s", number_or_null(m.arias_m_s)}, {"d5_95_s", number_or_null(m.d5_95_s)},
                            {"t_mid_s", number_or_null(m.t_mid_s)},
                            {"mid_frequency_hz", number_or_null(m.mid_frequency_hz)},
                            {"duration_s", number_or_null(m.duration_s)}, {"dt_s", number_or_null(m.dt_s)}});
        out << io::dump_json(list, 2) << '\n';
        return;
    }
    std::size_t width = 4;  // the file column fits the longest name given (at least "file")
    for (const auto& row : rows) width = std::max(width, row.first.size());
    out << fmt::format("{:<{}} {:>10} {:>10} {:>10} {:>10} {:>10} {:>10} {:>10}\n", "file", width, "PGA [g]",
                       "PGV [m/s]", "Ia [m/s]", "D5-95 [s]", "f_mid [Hz]", "length [s]", "dt [s]");
    for (const auto& [file, m] : rows)
        out << fmt::format("{:<{}} {:>10} {:>10} {:>10} {:>10} {:>10} {:>10} {:>10}\n", file, width, io::num(m.pga_g),
                           io::num(m.pgv_m_s), io::num(m.arias_m_s), num_or(m.d5_95_s, "none"),
                           num_or(m.mid_frequency_hz, "none"), io::num(m.duration_s), num_or(m.dt_s, "uneven"));
}

void add_generate_options(CLI::App& gen, GenerateOptions& o) {
    gen.add_option("--count", o.count_text, fmt::format("how many motions, 1 to {} (required)", motions::kMaxMotions))
        ->required();
    gen.add_option("--seed", o.seed_text,
                   "seed, an integer from 0 to 2^64-1 (required): motion k depends on (seed, k) only")
        ->required();
    gen.add_option("--out", o.out, "folder to write into, replaced whole (required)")->required();
    gen.add_option("--magnitude", o.magnitude, "scenario: moment magnitude, 5 to 8 (with --distance and --vs30)");
    gen.add_option("--distance", o.distance, "scenario: closest distance to the rupture [km], 1 to 200");
    gen.add_option("--vs30", o.vs30, "scenario: the site's Vs30 [m/s], 150 to 2000");
    gen.add_option("--mechanism", o.mechanism, "scenario: strike-slip (default) or reverse faulting");
    // Each median's range as check_draw_settings refuses it (motions::median_range).
    const auto median = [&](const char* name, std::optional<double>& target, const char* what, motions::Parameter j) {
        gen.add_option(name, target, fmt::format("{}, {}", what, motions::median_range_text(j)));
    };
    median("--arias", o.arias, "median Arias intensity [m/s]", motions::kArias);
    median("--d5-95", o.d5_95, "median significant duration D5-95 [s]", motions::kD595);
    median("--t-mid", o.t_mid, "median t_mid, the time at 45 % of the Arias intensity [s]", motions::kTmid);
    median("--mid-frequency", o.mid_frequency, "median filter frequency at t_mid, w_mid/2pi [Hz]",
           motions::kMidFrequency);
    median("--frequency-slope", o.slope, "median slope of the filter frequency, w'/2pi [Hz/s]", motions::kSlope);
    median("--damping", o.damping, "median filter damping zeta_f", motions::kDamping);
    gen.add_option("--scatter", o.scatter,
                   "factor on the parameters' scatter, 0 to 2 (default 1; 0: every motion has the medians)");
    gen.add_option("--dt", o.simulation.dt, fmt::format("sample step [s], at most 0.1 (default {})", o.simulation.dt));
    gen.add_option("--duration", o.simulation.duration,
                   "record length [s] (default: to 99.9 % of the modulation's energy, then 12/w_c for the high-pass "
                   "filter to rest)");
    gen.add_option("--corner", o.simulation.corner_hz,
                   fmt::format("corner of the high-pass filter [Hz] (default {})", o.simulation.corner_hz));
    gen.add_flag("--json", o.json, "print a JSON summary instead of a table");
    gen.footer(
        "Writes OUT/motion-001.at2 ... (PEER AT2, in g) and OUT/motions.csv: file, pga_g, arias_m_s, d5_95_s,\n"
        "mid_frequency_hz (measured on the written motion), then the parameters drawn: target_arias_m_s,\n"
        "target_d5_95_s, target_t_mid_s, target_mid_frequency_hz, frequency_slope_hz_per_s, damping.\n"
        "Parameters: without options, the fitted distributions of Rezaeian & Der Kiureghian (2010); with\n"
        "--magnitude/--distance/--vs30, the RZZ (2015) predictive equations; a median option fixes that parameter's\n"
        "median (docs/ground-motions.md). The folder is replaced as a whole or not at all.");
}

}  // namespace

Command add_motions_command(CLI::App& root) {
    auto g = std::make_shared<GenerateOptions>();
    auto d = std::make_shared<DescribeOptions>();
    CLI::App* cmd = root.add_subcommand("motions", "Generate stochastic ground motions, or measure records");
    cmd->require_subcommand(1);
    CLI::App* gen = cmd->add_subcommand("generate", "Draw a seeded set of stochastic ground motions (AT2 files)");
    add_generate_options(*gen, *g);
    CLI::App* desc = cmd->add_subcommand("describe", "Measure records: PGA, PGV, Arias intensity, D5-95, mid frequency");
    desc->add_option("FILE", d->files, "records (PEER AT2, or two columns time and acceleration)")->required();
    desc->add_option("--units", d->units, "units of a record that is not AT2, or overriding an AT2 header: g (default), m/s2, cm/s2");
    desc->add_flag("--csv", d->csv, "print CSV instead of a table");
    desc->add_flag("--json", d->json, "print JSON instead of a table");
    desc->footer(
        "PGA in g; PGV [m/s] integrated from the acceleration as recorded (no baseline correction); Arias\n"
        "intensity pi/(2g) * integral a^2 dt [m/s]; D5-95 between 5 % and 95 % of it; mid frequency: the rate of\n"
        "zero-level up-crossings within D5-95/4 of t_mid (45 % of it) [Hz]; length and sample step [s].\n"
        "CSV and JSON also give t_mid_s; a measure that does not exist is empty (CSV) or null (JSON).");
    return {cmd, {}, [g, d, gen](std::ostream& out, std::ostream& err) {
                if (gen->parsed()) run_generate(*g, out, err);
                else run_describe(*d, out);
            }};
}

}  // namespace vssw::cli
