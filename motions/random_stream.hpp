#pragma once
// The random numbers of one generated motion. Motion k of a run with seed S draws from its own std::mt19937_64,
// seeded with a number derived from (S, k) alone, so that motion k is the same whatever --count and whichever motions
// come before it. The engine's algorithm is fixed by the C++ standard; the uniform and normal transforms below are
// ours (std::normal_distribution's algorithm differs between standard libraries), so the same seed gives the same
// numbers with any of them.
#include <cstdint>
#include <random>

namespace vssw::motions {

class RandomStream {
public:
    RandomStream(std::uint64_t seed, std::uint64_t index);
    // Uniform on [0, 1): the engine's top 53 bits.
    double uniform();
    // Standard normal, by the Box-Muller transform (both values of a pair are used, in turn).
    double normal();

private:
    std::mt19937_64 engine_;
    double spare_ = 0.0;
    bool has_spare_ = false;
};

// SplitMix64's finalizer (Steele, Lea & Flood 2014): a bijection of 64-bit words that spreads every input bit over
// the output, so that neighbouring (seed, index) pairs seed unrelated engines.
std::uint64_t splitmix64(std::uint64_t x);

}  // namespace vssw::motions
