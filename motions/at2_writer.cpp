#include "motions/at2_writer.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "analytic/ground_motion.hpp"
#include "io/atomic_file.hpp"

namespace vssw::motions {
namespace {

constexpr int kValuesPerLine = 5;
// Values below 1e-99 g are written as 0: a three-digit exponent would fill all 15 columns of "%15.7E" and run into
// the value before it. The gamma modulation starts from q(0) = 0 and its first samples can be that small; no
// instrument, integrator or wall tells 1e-99 g from 0.
constexpr double kSmallestWritten = 1e-99;

std::string dt_text(double dt) {
    const std::string fixed = fmt::format("{:.4f}", dt);
    return std::stod(fixed) == dt ? fixed : fmt::format("{}", dt);
}

}  // namespace

void write_at2(std::ostream& out, const std::vector<double>& accel_m_s2, double dt, const std::string& description) {
    std::string line2 = description;
    std::replace(line2.begin(), line2.end(), '\n', ' ');
    std::replace(line2.begin(), line2.end(), '\r', ' ');
    out << "PEER NGA STRONG MOTION DATABASE RECORD (SYNTHETIC: VSSW MOTIONS GENERATE)\n"
        << line2 << '\n'
        << "ACCELERATION TIME SERIES IN UNITS OF G\n"
        << fmt::format("NPTS= {}, DT= {} SEC\n", accel_m_s2.size(), dt_text(dt));
    std::string line;
    for (std::size_t i = 0; i < accel_m_s2.size(); ++i) {
        const double g = accel_m_s2[i] / kStandardGravity;
        line += fmt::format("{:15.7E}", std::fabs(g) < kSmallestWritten ? 0.0 : g);
        if ((i + 1) % kValuesPerLine == 0 || i + 1 == accel_m_s2.size()) {
            out << line << '\n';
            line.clear();
        }
    }
}

void write_at2_file(const std::filesystem::path& path, const std::vector<double>& accel_m_s2, double dt,
                    const std::string& description) {
    io::write_file(path, [&](std::ostream& out) { write_at2(out, accel_m_s2, dt, description); });
}

}  // namespace vssw::motions
