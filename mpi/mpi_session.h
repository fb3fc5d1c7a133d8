// The MPI job this process is a rank of, for `mpirun -np K ensil preprocess`. MPI is started
// only when mpirun started the process (so the workbench and a plain `ensil` never touch it),
// and ended when the Session goes. Main thread only (MPI_THREAD_FUNNELED: oneTBB's workers never
// call MPI).
#pragma once

#include <string>

namespace ensil::mpi {

// True when mpirun (or another launcher setting OpenMPI's or PMI's variables) started this
// process.
bool launchedByMpirun();

class Session {
public:
    Session();   // MPI_Init_thread; throws std::runtime_error when MPI cannot start
    ~Session();  // MPI_Finalize
    Session(const Session&) = delete;
    Session& operator=(const Session&) = delete;

    [[nodiscard]] int rank() const { return m_rank; }
    [[nodiscard]] int size() const { return m_size; }

    // Ends every rank of the job (MPI_Abort) after printing `message` on this rank's stderr
    // ("ensil preprocess: rank 2 of 4: ..."), so that no rank waits forever for one that failed.
    [[noreturn]] void abort(const std::string& message, int exitCode) const;

private:
    int m_rank = 0;
    int m_size = 1;
};

}  // namespace ensil::mpi
