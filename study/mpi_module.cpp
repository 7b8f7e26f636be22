// The MPI module, vssw_mpi.so (mpi_module.hpp): the only code of the program that calls MPI, so that libmpi is loaded
// only by the processes that mpirun starts.
#include "study/mpi_module.hpp"

#include <mpi.h>

#include "vssw_build_id.hpp"  // VSSW_BUILD_ID (cmake/plugins.cmake)

namespace {

void start(int* rank, int* size) {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, rank);
    MPI_Comm_size(MPI_COMM_WORLD, size);
}

void finish() { MPI_Finalize(); }

int all_min(int value) {
    int all = 0;
    MPI_Allreduce(&value, &all, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    return all;
}

void broadcast_longs(long* values, int count) { MPI_Bcast(values, count, MPI_LONG, 0, MPI_COMM_WORLD); }

void send_text(const char* text, int size, int to, int tag) {
    MPI_Send(text, size, MPI_CHAR, to, tag, MPI_COMM_WORLD);
}

void send_long(long value, int to, int tag) { MPI_Send(&value, 1, MPI_LONG, to, tag, MPI_COMM_WORLD); }

long receive_long(int from, int tag) {
    long value = 0;
    MPI_Recv(&value, 1, MPI_LONG, from, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    return value;
}

int poll(int* from, int* tag, int* size) {
    int waiting = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &waiting, &status);
    if (!waiting) return 0;
    *from = status.MPI_SOURCE;
    *tag = status.MPI_TAG;
    MPI_Get_count(&status, MPI_CHAR, size);
    return 1;
}

void receive_text(char* text, int size, int from, int tag) {
    MPI_Recv(text, size, MPI_CHAR, from, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
}

void abort_all(int code) { MPI_Abort(MPI_COMM_WORLD, code); }

}  // namespace

extern "C" __attribute__((visibility("default"))) const vssw::study::MpiModule* vssw_mpi_module_v1() {
    static const vssw::study::MpiModule module{vssw::study::kMpiModuleAbi,
                                               VSSW_BUILD_ID,
                                               &start,
                                               &finish,
                                               &all_min,
                                               &broadcast_longs,
                                               &send_text,
                                               &send_long,
                                               &receive_long,
                                               &poll,
                                               &receive_text,
                                               &abort_all};
    return &module;
}
