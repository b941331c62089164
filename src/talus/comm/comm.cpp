#include "talus/comm/comm.hpp"

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <stdexcept>

#ifdef TALUS_WITH_MPI
#include <mpi.h>
#endif

namespace talus::comm {

namespace {
Comm world_comm;
bool started = false;

// mpirun (OpenMPI), hydra (MPICH) and PMIx launchers announce themselves in
// the environment; a plain `talus run` then never touches MPI (its start-up
// costs a fraction of a second and may warn in containers).
bool launched_by_mpi() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(v)) return true;
  return false;
}

#ifdef TALUS_WITH_MPI
// MPI counts are ints: a block larger than that is sent in pieces.
constexpr std::size_t kMaxCount = std::numeric_limits<int>::max() / 2;
#endif
}  // namespace

bool Comm::built_with_mpi() {
#ifdef TALUS_WITH_MPI
  return true;
#else
  return false;
#endif
}

int Comm::launched_processes() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
    if (const char* n = std::getenv(v)) return std::max(1, std::atoi(n));
  return 1;
}

void Comm::init(int* argc, char*** argv) {
#ifdef TALUS_WITH_MPI
  if (started || !launched_by_mpi()) return;
  int provided = 0;
  // Only the main thread calls MPI; OpenMP threads work inside a rank.
  MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
  started = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &world_comm.rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &world_comm.size_);
  world_comm.mpi_ = true;
#else
  (void)argc, (void)argv;
#endif
}

void Comm::finalize() {
#ifdef TALUS_WITH_MPI
  if (started) MPI_Finalize();
  started = false;
#endif
}

const Comm& Comm::world() { return world_comm; }

double Comm::max(double x) const {
#ifdef TALUS_WITH_MPI
  if (mpi_ && size_ > 1) MPI_Allreduce(MPI_IN_PLACE, &x, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
#endif
  return x;
}

bool Comm::any(bool b) const {
#ifdef TALUS_WITH_MPI
  if (mpi_ && size_ > 1) {
    int v = b ? 1 : 0;
    MPI_Allreduce(MPI_IN_PLACE, &v, 1, MPI_INT, MPI_LOR, MPI_COMM_WORLD);
    return v != 0;
  }
#endif
  return b;
}

void Comm::shift(const double* send, int to, double* recv, int from, std::size_t count) const {
#ifdef TALUS_WITH_MPI
  if (mpi_ && size_ > 1) {
    for (std::size_t done = 0; done < count; done += kMaxCount) {
      const int n = static_cast<int>(std::min(kMaxCount, count - done));
      MPI_Sendrecv(send + done, to >= 0 ? n : 0, MPI_DOUBLE, to >= 0 ? to : MPI_PROC_NULL, 0,
                   recv + done, from >= 0 ? n : 0, MPI_DOUBLE, from >= 0 ? from : MPI_PROC_NULL, 0,
                   MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    }
    return;
  }
#endif
  if (to >= 0 || from >= 0)
    throw std::logic_error("Comm::shift: one rank has no neighbour to send to");
  (void)send, (void)recv, (void)count;
}

void Comm::all_gather(double* data, const std::vector<std::size_t>& counts,
                      const std::vector<std::size_t>& offsets) const {
#ifdef TALUS_WITH_MPI
  if (mpi_ && size_ > 1) {
    // Each rank's block is broadcast by its owner: blocks may exceed an int
    // count, which MPI_Allgatherv could not take.
    for (int r = 0; r < size_; ++r)
      for (std::size_t done = 0; done < counts[r]; done += kMaxCount) {
        const int n = static_cast<int>(std::min(kMaxCount, counts[r] - done));
        MPI_Bcast(data + offsets[r] + done, n, MPI_DOUBLE, r, MPI_COMM_WORLD);
      }
    return;
  }
#endif
  (void)data, (void)counts, (void)offsets;
}

void Comm::abort(int code) const {
#ifdef TALUS_WITH_MPI
  if (mpi_ && size_ > 1) MPI_Abort(MPI_COMM_WORLD, code);
#endif
  (void)code;
}

}  // namespace talus::comm
