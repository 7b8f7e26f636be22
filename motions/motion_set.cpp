#include "motions/motion_set.hpp"

#include <algorithm>
#include <ostream>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "analytic/ground_motion.hpp"
#include "io/atomic_file.hpp"
#include "io/csv.hpp"
#include "io/folder_swap.hpp"
#include "motions/at2_writer.hpp"

namespace vssw::motions {

GeneratedMotion generate_motion(std::uint64_t seed, std::uint64_t number, const DrawSettings& draws,
                                const SimulationSettings& simulation) {
    RandomStream random(seed, number);
    GeneratedMotion m;
    m.target = draw_parameters(draws, random);
    m.accel_m_s2 = simulate(m.target, simulation, random);
    return m;
}

std::string motion_file_name(int number, int count) {
    const int width = std::max(3, static_cast<int>(fmt::format("{}", count).size()));
    return fmt::format("motion-{:0{}}.at2", number, width);
}

std::string motions_csv_header() {
    return "file,pga_g,arias_m_s,d5_95_s,mid_frequency_hz,target_arias_m_s,target_d5_95_s,target_t_mid_s,"
           "target_mid_frequency_hz,frequency_slope_hz_per_s,damping";
}

std::string motions_csv_row(const MotionRow& r) {
    using io::csv_number;
    return fmt::format("{},{},{},{},{},{},{},{},{},{},{}", io::csv_field(r.file), csv_number(r.measured.pga_g),
                       csv_number(r.measured.arias_m_s), csv_number(r.measured.d5_95_s),
                       csv_number(r.measured.mid_frequency_hz), csv_number(r.target.arias_m_s),
                       csv_number(r.target.d5_95_s), csv_number(r.target.t_mid_s),
                       csv_number(r.target.mid_frequency_hz), csv_number(r.target.slope_hz_per_s),
                       csv_number(r.target.damping));
}

std::vector<MotionRow> write_motion_set(const MotionSetRequest& request, const std::function<void(int, int)>& progress) {
    if (request.count < 1 || request.count > kMaxMotions)
        throw InputError(fmt::format("--count must be an integer from 1 to {}, got {}", kMaxMotions, request.count));
    check_draw_settings(request.draws);
    check_settings(request.simulation);
    // The record's length and the filter's cost, for the median motion, before anything is written (each drawn motion
    // is checked again as it is made).
    (void)record_samples(median_parameters(request.draws), request.simulation, "the median motion");
    const io::FolderLock lock = io::check_out_folder(request.out, io::OutKind::motions);
    io::StagedFolder staged(request.out, io::OutKind::motions);
    staged.create();
    std::vector<MotionRow> rows;
    for (int k = 1; k <= request.count; ++k) {
        const GeneratedMotion m =
            generate_motion(request.seed, static_cast<std::uint64_t>(k), request.draws, request.simulation);
        MotionRow row{motion_file_name(k, request.count), {}, m.target};
        const std::filesystem::path file = staged.path() / row.file;
        write_at2_file(file, m.accel_m_s2, request.simulation.dt,
                       fmt::format("{}: seed {}, motion {}; Rezaeian & Der Kiureghian model, Ia {:.6g} m/s, D5-95 "
                                   "{:.6g} s, t_mid {:.6g} s, f_mid {:.6g} Hz, f' {:.6g} Hz/s, zeta_f {:.6g}",
                                   row.file, request.seed, k, m.target.arias_m_s, m.target.d5_95_s, m.target.t_mid_s,
                                   m.target.mid_frequency_hz, m.target.slope_hz_per_s, m.target.damping));
        row.measured = measure(read_peer_at2(file.string()));
        rows.push_back(row);
        if (progress) progress(k, request.count);
    }
    io::write_file(staged.path() / "motions.csv", [&](std::ostream& out) {
        out << motions_csv_header() << '\n';
        for (const MotionRow& r : rows) out << motions_csv_row(r) << '\n';
    });
    staged.commit();
    return rows;
}

}  // namespace vssw::motions
