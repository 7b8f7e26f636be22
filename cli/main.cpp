// The `vssw` program: every command is implemented in the vssw_cli library (cli.hpp).
#include <malloc.h>

#include <iostream>

#include "cli/cli.hpp"
#include "cli/signal_cleanup.hpp"

namespace {

// A sampled run's trajectory is megabytes. Above glibc's mmap threshold each one was mapped, page-faulted in and
// unmapped again, run after run: `vssw check` spent 0.45 of its 0.96 s of CPU on 58,000 minor page faults. Taken from
// the heap and kept there when freed, the next run reuses the same pages (docs/measurements/speed.md). On one thread
// the peak resident size is the same (81 against 85 MiB for check): the memory is reused, not added to; on two, each
// thread's heap keeps its own blocks (check --bounds bounds/ci.toml: 140 MiB, 88 MiB with --threads 1). [bytes] above
// the 2^21 samples (144 MiB) a run reserves at its start (analytic/simulate.cpp): a run that outgrows that is mapped as
// before.
constexpr int kMmapThreshold = 256 << 20;
constexpr int kTrimThreshold = 512 << 20;  // [bytes] free memory kept for the next run instead of returned

}  // namespace

int main(int argc, char** argv) {
    mallopt(M_MMAP_THRESHOLD, kMmapThreshold);
    mallopt(M_TRIM_THRESHOLD, kTrimThreshold);
    vssw::cli::install_signal_cleanup();  // the program's alone: the Python module keeps Python's handlers
    return vssw::cli::run(argc, argv, std::cout, std::cerr);
}
