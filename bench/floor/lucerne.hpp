#pragma once
// The record both the floor's and the engines' benchmarks run under, so that their costs under a record pair: the
// Landers 1992 Lucerne record (data/records/, SOURCES.md) scaled to a peak `pga_g` [g]. On the Fig. 6 VSSW (threshold
// 0.286 g, Eq. 12) 0.2 g leaves the wall at rest with every contact closed; 1.0 g rocks it to 0.05-0.11 alpha1 (by
// backend: the analytic model 0.11, ODE 0.055, the floor 0.051) and it stands, at rest most of the time: a record
// run of the report's kind. The benchmarks run its first kRecordWindow seconds, which hold its strong motion (the
// whole record is 80 s: too long a benchmark for simbody-rigid, at about 0.3 s of CPU per simulated second).
#include <string>

#include "analytic/ground_motion.hpp"
#include "analytic/wall.hpp"  // kDefaultGravity, the scenes' g

namespace vssw::yardstick {

constexpr double kRecordWindow = 20.0;  // [s]

inline GroundMotion lucerne(const std::string& data_dir, double pga_g) {
    return read_record(data_dir + "/records/landers1992-lucerne-ns.at2").scaled_to_pga(pga_g * kDefaultGravity);
}

}  // namespace vssw::yardstick
