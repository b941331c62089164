#pragma once
// The ranks a run is spread over: all the processes of an MPI job started by
// `mpirun`, or one rank alone (no MPI, or a solver that is not distributed).
// The methods talk to other ranks only through this class, so that they
// build and run the same without MPI (then every collective is a no-op).
#include <cstddef>
#include <string>
#include <vector>

namespace talus::comm {

class Comm {
 public:
  // One rank, exchanging nothing.
  Comm() = default;

  // Starts MPI when this process was launched by an MPI launcher (mpirun
  // sets OMPI_COMM_WORLD_SIZE, PMI_SIZE or PMIX_RANK) and talus was built
  // with MPI; otherwise does nothing. Call once, first thing in main().
  static void init(int* argc, char*** argv);
  // Ends MPI if init() started it. Call last, on every rank.
  static void finalize();
  // Every rank of the job (one rank when MPI was not started).
  static const Comm& world();
  // Whether this talus was built with MPI.
  static bool built_with_mpi();
  // The number of processes an MPI launcher started (1 without one), read
  // from its environment: a talus built without MPI under `mpirun -n 4`
  // must refuse rather than run four copies.
  static int launched_processes();

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool root() const { return rank_ == 0; }

  // Reductions over all ranks; each rank gets the result. Exact (max, or,
  // and): the same bits whatever the number of ranks.
  double max(double x) const;
  bool any(bool b) const;
  bool all(bool b) const { return !any(!b); }

  // Sends `count` doubles from `send` to rank `to` and receives `count` into
  // `recv` from rank `from`, at once (no deadlock between neighbours); -1
  // for either: nothing that way.
  void shift(const double* send, int to, double* recv, int from, std::size_t count) const;

  // Rank r holds data[offsets[r], offsets[r] + counts[r]); afterwards every
  // rank holds all of it. counts and offsets have size() entries.
  void all_gather(double* data, const std::vector<std::size_t>& counts,
                  const std::vector<std::size_t>& offsets) const;

  // Ends every rank of the job at once (an error on one rank must not leave
  // the others waiting in a collective); with one rank, returns.
  void abort(int code) const;

 private:
  int rank_ = 0, size_ = 1;
  bool mpi_ = false;  // the world of a started MPI job
};

}  // namespace talus::comm
