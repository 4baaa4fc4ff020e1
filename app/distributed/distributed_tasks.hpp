// SPDX-License-Identifier: BSD-3-Clause
// Numbered tasks shared among the processes of a run: the MPI ranks when the program was
// started by mpirun/srun in a build with MPI, else this one process (app/distributed/README.md).
// Rank 0 hands out the tasks, computes some itself and receives every result.
#pragma once

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace lc::dist {

// The processes of this run: the MPI ranks when launched by mpirun/srun in an MPI build, else one
// process. Construct one in main() before anything else reads argv; it lives until main returns.
class Processes {
public:
    // MPI_Init_thread (MPI_THREAD_FUNNELED) only when the environment shows a launcher
    // (OMPI_COMM_WORLD_SIZE, PMIX_RANK, PMI_RANK, PMI_SIZE); otherwise no MPI call at all (a
    // singleton MPI_Init is slow, and unsafe in some containers).
    Processes(int& argc, char**& argv);
    ~Processes();  // MPI_Finalize if this object initialised MPI
    Processes(const Processes&) = delete;
    Processes& operator=(const Processes&) = delete;

    int rank() const { return rank_; }
    int size() const { return size_; }
    bool root() const { return rank() == 0; }
    bool distributed() const { return size() > 1; }

    // The one constructed in main (a single-process default if none was).
    static const Processes& current();
    static bool builtWithMpi();
    // Ends every rank of a distributed run at once (MPI_Abort) with exit code `code`: for a
    // failure on some ranks only, outside runTasks, where the others would wait for them forever.
    // Does nothing in a single process.
    void abortRun(int code) const;

private:
    Processes() = default;  // the single-process default of current()
    friend struct ProcessesAccess;
    int rank_ = 0;
    int size_ = 1;
    bool initialisedMpi_ = false;
    void* comm_ = nullptr;       // the MPI communicator of runTasks (a duplicate of MPI_COMM_WORLD)
    mutable unsigned runs_ = 0;  // runTasks calls so far: each call has its own message tags
    const Processes* previous_ = nullptr;
};

// Static: task k runs on rank k % size (to measure the imbalance that Dynamic removes).
enum class Schedule { Dynamic, Static };

struct RankReport {
    int tasks = 0;                // tasks this rank computed
    double busySeconds = 0;       // time inside work()
    std::uint64_t bytesSent = 0;  // result bytes sent to rank 0 (0 for rank 0 itself)
};
// Complete on rank 0; on another rank only its own entry of `ranks` is filled.
struct TaskReport {
    std::vector<RankReport> ranks;
    double seconds = 0;             // wall time of runTasks
    std::uint64_t bytesToRoot = 0;  // result bytes that travelled to rank 0
};

// A task threw: "rank R, task K: <what() of the original exception>", thrown on every rank.
struct TaskFailed : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Runs tasks 0..count-1 on all processes; every rank calls it with the same count and schedule.
// work(k) returns task k's result as bytes (any size, 0 included). On rank 0, deliver(k, bytes)
// receives every result exactly once, in completion order, always on the calling thread; on other
// ranks deliver is never called. Rank 0 computes too, on a std::thread, while its calling thread
// serves the other ranks (MPI calls only from that thread). Dynamic: a rank asks for the next task
// when it has finished one. When a task throws on any rank no further tasks are handed out, rank 0
// delivers nothing more, and every rank throws TaskFailed once the tasks still running have ended.
// An exception from deliver stops the run the same way; rank 0 rethrows it unchanged, the others
// throw TaskFailed ("rank 0, task K: delivering the result failed: ..."). With one process: work
// then deliver, task after task, on the calling thread, work's exceptions as TaskFailed.
TaskReport runTasks(int count, const std::function<std::string(int)>& work,
                    const std::function<void(int, std::string&&)>& deliver, Schedule schedule = Schedule::Dynamic);

}  // namespace lc::dist
