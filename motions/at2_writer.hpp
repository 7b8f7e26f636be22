#pragma once
// PEER AT2 files as the NGA-West2 database writes them: 4 header lines (title, description, units, counts), then the
// accelerations in g, five a line, each "%15.7E" (8 significant digits: 5e-8 relative, far below any record's
// noise). read_peer_at2 (analytic/ground_motion.hpp) reads them back.
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace vssw::motions {

// Writes accelerations [m/s^2] sampled every dt [s] from t = 0, converted to g with g0 = 9.80665. Line 2 holds
// `description` (one line: line breaks become blanks). Line 4: "NPTS= N, DT= 0.0050 SEC" (DT with 4 decimals when
// that is exact, else in full).
void write_at2(std::ostream& out, const std::vector<double>& accel_m_s2, double dt, const std::string& description);
// The same into a file, atomically (io/atomic_file.hpp; InputError naming the file when it cannot be written).
void write_at2_file(const std::filesystem::path& path, const std::vector<double>& accel_m_s2, double dt,
                    const std::string& description);

}  // namespace vssw::motions
