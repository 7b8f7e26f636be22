#pragma once
// `vssw motions generate`: a folder of generated motions, DIR/motion-001.at2 ... and DIR/motions.csv, replaced whole
// or not at all (io/folder_swap.hpp).
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "motions/measures.hpp"
#include "motions/parameter_draws.hpp"
#include "motions/stochastic.hpp"

namespace vssw::motions {

// The most motions one run writes: 100,000 files of ~0.5 MB is 50 GB, more than any study wants.
constexpr int kMaxMotions = 100000;

struct GeneratedMotion {
    ModelParameters target;           // the parameters drawn
    std::vector<double> accel_m_s2;   // at t_i = i dt
};

// Motion `number` (1, 2, ...) of a run seeded with `seed`: its parameters and samples depend on (seed, number) only.
GeneratedMotion generate_motion(std::uint64_t seed, std::uint64_t number, const DrawSettings& draws,
                                const SimulationSettings& simulation);

struct MotionSetRequest {
    int count = 0;
    std::uint64_t seed = 0;
    DrawSettings draws;
    SimulationSettings simulation;
    std::filesystem::path out;
};

struct MotionRow {
    std::string file;        // "motion-001.at2"
    Measures measured;       // of the motion as written (read back from its AT2 file)
    ModelParameters target;
};

// "motion-001.at2" for number 1 of `count` (at least 3 digits, more when count needs them).
std::string motion_file_name(int number, int count);
// Checks the request (InputError naming the option), writes every motion and motions.csv into a staging folder and
// swaps it in; `progress(done, count)` after each motion.
std::vector<MotionRow> write_motion_set(const MotionSetRequest& request,
                                        const std::function<void(int, int)>& progress = {});
// motions.csv's header and one row (full precision; empty for a measure that does not exist).
std::string motions_csv_header();
std::string motions_csv_row(const MotionRow& row);

}  // namespace vssw::motions
