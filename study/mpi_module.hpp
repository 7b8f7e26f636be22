#pragma once
// The MPI module, vssw_mpi.so (study/mpi_module.cpp): the few MPI calls a study makes, behind a table of functions.
// study/mpi.cpp opens it (multibody/host/plugin_loader.hpp) only in a process started by mpirun, so that no other process
// loads libmpi and the libraries it brings (hwloc, libevent, ...; a plain `vssw free` started in tens of ms instead of
// a few before). The protocol (who sends what, when) stays in study/mpi.cpp; the module only moves bytes.
//
// Plain C types only, every message to or from one rank over MPI_COMM_WORLD. The module exports one symbol,
// kMpiModuleEntry, with C linkage, returning this table; `abi` and `build_id` come first and are checked before
// anything else is read (a module of another build is refused).
#include <cstdint>

namespace vssw::study {

// Raise it (and the 1 in the entry point's name) when the table's layout changes.
inline constexpr std::uint32_t kMpiModuleAbi = 1;
inline constexpr const char* kMpiModuleEntry = "vssw_mpi_module_v1";
inline constexpr const char* kMpiModuleStem = "vssw_mpi";

struct MpiModule {
    std::uint32_t abi;     // kMpiModuleAbi of the module's build
    const char* build_id;  // VSSW_BUILD_ID of the module's build
    // MPI_Init_thread(MPI_THREAD_FUNNELED), then this process's rank and the number of processes.
    void (*start)(int* rank, int* size);
    void (*finish)();  // MPI_Finalize
    // The smallest of every process's `value` (MPI_Allreduce with MPI_MIN): a collective.
    int (*all_min)(int value);
    // Rank 0's `count` longs to every process (MPI_Bcast): a collective.
    void (*broadcast_longs)(long* values, int count);
    void (*send_text)(const char* text, int size, int to, int tag);
    void (*send_long)(long value, int to, int tag);
    // Blocks for one long from rank `from` with `tag`.
    long (*receive_long)(int from, int tag);
    // Whether a message from any rank, of any tag, is waiting (MPI_Iprobe): then its sender, tag and size in chars.
    int (*poll)(int* from, int* tag, int* size);
    // The message poll found: `size` chars from `from` with `tag` into `text`.
    void (*receive_text)(char* text, int size, int from, int tag);
    // MPI_Abort(MPI_COMM_WORLD, code): ends every process.
    void (*abort_all)(int code);
};

}  // namespace vssw::study
