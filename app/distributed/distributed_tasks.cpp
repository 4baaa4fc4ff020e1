// SPDX-License-Identifier: BSD-3-Clause
// Processes and runTasks (distributed_tasks.hpp). The protocol (README.md): a rank other than 0
// sends a header {kind, task, size, busy ns} to rank 0 and waits for one reply {code, task}; after
// any reply but Abort it sends the result's bytes (size first in the header, then the bytes in
// chunks of at most 1 GiB); Assign gives it its next task, Stop and Abort end its part of the run.
// Each runTasks call has its own tags, so a rank that has finished may start the next call while
// rank 0 still serves the last one.
#include "app/distributed/distributed_tasks.hpp"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <exception>
#include <initializer_list>
#include <mutex>
#include <thread>
#include <utility>

#ifdef LIGHTCONE_WITH_MPI
#include <mpi.h>
#endif

namespace lc::dist {

namespace {

const Processes* g_current = nullptr;

const char* launcherVariable() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
        if (std::getenv(name)) return name;
    return nullptr;
}

#ifndef LIGHTCONE_WITH_MPI
int fromEnvironment(std::initializer_list<const char*> names, int otherwise) {
    for (const char* name : names)
        if (const char* value = std::getenv(name)) return std::atoi(value);
    return otherwise;
}
#endif

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string messageOf(const std::exception_ptr& e) {
    try {
        std::rethrow_exception(e);
    } catch (const std::exception& x) {
        return x.what();
    } catch (...) {
        return "an exception that is not a std::exception";
    }
}

std::string failureText(int rank, int task, const std::string& what) {
    return "rank " + std::to_string(rank) + ", task " + std::to_string(task) + ": " + what;
}

TaskReport singleProcess(int count, const std::function<std::string(int)>& work,
                         const std::function<void(int, std::string&&)>& deliver) {
    const auto start = std::chrono::steady_clock::now();
    TaskReport report;
    report.ranks.resize(1);
    for (int k = 0; k < count; ++k) {
        const auto begin = std::chrono::steady_clock::now();
        std::string bytes;
        try {
            bytes = work(k);
        } catch (...) {
            throw TaskFailed(failureText(0, k, messageOf(std::current_exception())));
        }
        report.ranks[0].busySeconds += secondsSince(begin);
        ++report.ranks[0].tasks;
        deliver(k, std::move(bytes));
    }
    report.seconds = secondsSince(start);
    return report;
}

}  // namespace

#ifdef LIGHTCONE_WITH_MPI
struct ProcessesAccess {
    static MPI_Comm comm(const Processes& p) { return *static_cast<MPI_Comm*>(p.comm_); }
    static unsigned nextRun(const Processes& p) { return p.runs_++; }
};
#endif

Processes::Processes(int& argc, char**& argv) {
    previous_ = g_current;
    g_current = this;
    const char* launcher = launcherVariable();
#ifdef LIGHTCONE_WITH_MPI
    if (!launcher) return;
    int initialised = 0;
    MPI_Initialized(&initialised);
    if (!initialised) {
        int provided = 0;
        MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
        initialisedMpi_ = true;
        if (provided < MPI_THREAD_FUNNELED)
            std::fprintf(stderr,
                         "lightcone: this MPI offers no MPI_THREAD_FUNNELED; rank 0 computes on a thread anyway\n");
    }
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
    auto* comm = new MPI_Comm;
    MPI_Comm_dup(MPI_COMM_WORLD, comm);
    comm_ = comm;
#else
    (void)argc;
    (void)argv;
    // mpirun started several copies of a build without MPI: each would do all the work.
    const int launched = fromEnvironment({"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}, 1);
    if (launcher && launched > 1 && fromEnvironment({"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK"}, 0) == 0)
        std::fprintf(stderr, "lightcone: started as one of %d processes, but this build has no MPI: each works alone\n",
                     launched);
#endif
}

Processes::~Processes() {
#ifdef LIGHTCONE_WITH_MPI
    if (comm_) {
        auto* comm = static_cast<MPI_Comm*>(comm_);
        int finalised = 0;
        MPI_Finalized(&finalised);
        if (!finalised) MPI_Comm_free(comm);
        delete comm;
    }
    if (initialisedMpi_) {
        int finalised = 0;
        MPI_Finalized(&finalised);
        if (!finalised) MPI_Finalize();
    }
#endif
    if (g_current == this) g_current = previous_;
}

const Processes& Processes::current() {
    static const Processes single;
    return g_current ? *g_current : single;
}

void Processes::abortRun(int code) const {
#ifdef LIGHTCONE_WITH_MPI
    if (initialisedMpi_ && distributed()) {
        std::fflush(nullptr);
        MPI_Abort(MPI_COMM_WORLD, code);
    }
#endif
    (void)code;
}

bool Processes::builtWithMpi() {
#ifdef LIGHTCONE_WITH_MPI
    return true;
#else
    return false;
#endif
}

#ifdef LIGHTCONE_WITH_MPI
namespace {

// What a rank tells rank 0 (header) and what rank 0 answers (reply).
enum Kind : std::int64_t { Ready = 0, Result = 1, Failed = 2 };
enum Code : std::int64_t { Assign = 0, Stop = 1, Abort = 2 };
constexpr int kHeaderLength = 4;  // kind, task, size, busy nanoseconds
constexpr int kReplyLength = 3;   // code, task (Assign) or failed task (Abort), failed rank (Abort)
constexpr std::size_t kChunk = std::size_t(1) << 30;

// Tags of one runTasks call: header, reply, result bytes, failure text.
struct Tags {
    int header, reply, bytes, text;
    explicit Tags(unsigned run) {
        const int base = 16 + 4 * static_cast<int>(run % 4096u);  // MPI guarantees tags up to 32767
        header = base;
        reply = base + 1;
        bytes = base + 2;
        text = base + 3;
    }
};

// MPI_Iprobe, twice when the first says no: OpenMPI's first call makes progress (reads what has
// arrived) only after it has looked, so a rank waking from a sleep would otherwise see a
// message only one sleep later (measured: 1.05 ms instead of 0.48 ms of waiting per task).
bool arrived(MPI_Comm comm, int source, int tag, MPI_Status* status) {
    MPI_Status ignored;
    int flag = 0;
    for (int i = 0; i < 2 && !flag; ++i) MPI_Iprobe(source, tag, comm, &flag, status ? status : &ignored);
    return flag != 0;
}

// Waiting without burning a core: OpenMPI's blocking calls busy-poll, so a rank that waits
// probes, yields for a moment after the last message (rank 0: 200 us, more may come; another
// rank: 1 ms, rank 0 answers within one of its sleeps), then sleeps 250 us between probes, and
// 1 ms once nothing has come for 20 ms (tasks are long then; a probe costs OpenMPI ~30 us: rank 0
// used 9 % of a core waiting with 250 us sleeps, 3 % with this).
constexpr auto kRootSpin = std::chrono::microseconds(200);
constexpr auto kWorkerSpin = std::chrono::microseconds(1000);
constexpr auto kSleep = std::chrono::microseconds(250);
constexpr auto kLongIdle = std::chrono::milliseconds(20);
constexpr auto kLongSleep = std::chrono::microseconds(1000);

class Idle {
public:
    explicit Idle(std::chrono::microseconds spin) : spin_(spin) {}
    void reset() { since_ = std::chrono::steady_clock::now(); }
    void wait() {
        const auto idle = std::chrono::steady_clock::now() - since_;
        if (idle < spin_)
            std::this_thread::yield();
        else
            std::this_thread::sleep_for(idle < kLongIdle ? kSleep : kLongSleep);
    }
    // Waits for a message from `source` with `tag`.
    void probe(MPI_Comm comm, int source, int tag) {
        reset();
        while (!arrived(comm, source, tag, nullptr)) wait();
    }

private:
    std::chrono::microseconds spin_;
    std::chrono::steady_clock::time_point since_ = std::chrono::steady_clock::now();
};

void sendBytes(const std::string& bytes, int dest, int tag, MPI_Comm comm) {
    for (std::size_t at = 0; at < bytes.size(); at += kChunk) {
        const std::size_t n = std::min(kChunk, bytes.size() - at);
        MPI_Send(bytes.data() + at, static_cast<int>(n), MPI_BYTE, dest, tag, comm);
    }
}

// A short text (a failure's message) as one message, empty or not.
void sendText(const std::string& text, int dest, int tag, MPI_Comm comm) {
    const std::size_t n = std::min<std::size_t>(text.size(), 1 << 16);
    MPI_Send(text.data(), static_cast<int>(n), MPI_BYTE, dest, tag, comm);
}

std::string receiveText(int source, int tag, MPI_Comm comm) {
    MPI_Status status;
    MPI_Probe(source, tag, comm, &status);  // sent together with what announced it: no wait
    int n = 0;
    MPI_Get_count(&status, MPI_BYTE, &n);
    std::string text(static_cast<std::size_t>(n), '\0');
    MPI_Recv(&text[0], n, MPI_BYTE, source, tag, comm, MPI_STATUS_IGNORE);
    return text;
}

std::string receiveBytes(std::size_t size, int source, int tag, MPI_Comm comm) {
    std::string bytes(size, '\0');
    for (std::size_t at = 0; at < size; at += kChunk) {
        const std::size_t n = std::min(kChunk, size - at);
        MPI_Recv(&bytes[at], static_cast<int>(n), MPI_BYTE, source, tag, comm, MPI_STATUS_IGNORE);
    }
    return bytes;
}

// Which task each rank gets next; shared by rank 0's two threads.
class Dispenser {
public:
    Dispenser(int count, int ranks, Schedule schedule) : count_(count), ranks_(ranks), schedule_(schedule) {
        for (int r = 0; r < ranks; ++r) nextOf_.push_back(r);
    }
    // The next task for `rank`, or -1 when there is none (all handed out, or stopped).
    int next(int rank) {
        std::lock_guard<std::mutex> lock(mutex_);
        if (stopped_) return -1;
        if (schedule_ == Schedule::Dynamic) return next_ < count_ ? next_++ : -1;
        int& k = nextOf_[static_cast<std::size_t>(rank)];
        if (k >= count_) return -1;
        const int task = k;
        k += ranks_;
        return task;
    }
    void stop() {
        std::lock_guard<std::mutex> lock(mutex_);
        stopped_ = true;
    }

private:
    std::mutex mutex_;
    const int count_, ranks_;
    const Schedule schedule_;
    int next_ = 0;
    std::vector<int> nextOf_;
    bool stopped_ = false;
};

// The first failure of a run: who, which task, what.
struct Failure {
    int rank = -1, task = -1;
    std::string what;
    std::exception_ptr deliverError;  // set when rank 0's deliver threw (rethrown unchanged there)
    bool happened() const { return rank >= 0; }
    std::string text() const { return failureText(rank, task, what); }
};

// Rank 0's own computing thread: takes tasks like any rank and queues its results for the
// calling thread to deliver (at most two waiting, so memory stays bounded).
class LocalWorker {
public:
    LocalWorker(Dispenser& tasks, const std::function<std::string(int)>& work) : tasks_(tasks), work_(work) {
        thread_ = std::thread([this] { run(); });
    }
    ~LocalWorker() { finish(); }
    LocalWorker(const LocalWorker&) = delete;
    LocalWorker& operator=(const LocalWorker&) = delete;

    struct Done {
        int task;
        std::string bytes;
    };
    // Waits up to `timeout` for a result or the end; takes the results so far (and a failure).
    std::deque<Done> take(std::chrono::microseconds timeout) {
        std::unique_lock<std::mutex> lock(mutex_);
        if (done_.empty() && running_) ready_.wait_for(lock, timeout);
        std::deque<Done> out;
        out.swap(done_);
        room_.notify_all();
        return out;
    }
    bool running() {
        std::lock_guard<std::mutex> lock(mutex_);
        return running_ || !done_.empty();
    }
    // The failure of rank 0's own task, if one threw (valid once running() is false).
    Failure failure() {
        std::lock_guard<std::mutex> lock(mutex_);
        return failure_;
    }
    RankReport report() {
        std::lock_guard<std::mutex> lock(mutex_);
        return report_;
    }
    void finish() {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            discard_ = true;
            done_.clear();
        }
        room_.notify_all();
        if (thread_.joinable()) thread_.join();
    }

private:
    void run() {
        for (;;) {
            const int k = tasks_.next(0);
            if (k < 0) break;
            const auto begin = std::chrono::steady_clock::now();
            std::string bytes;
            try {
                bytes = work_(k);
            } catch (...) {
                const std::string what = messageOf(std::current_exception());
                std::lock_guard<std::mutex> lock(mutex_);
                failure_.rank = 0;
                failure_.task = k;
                failure_.what = what;
                break;
            }
            std::unique_lock<std::mutex> lock(mutex_);
            report_.busySeconds += secondsSince(begin);
            ++report_.tasks;
            room_.wait(lock, [this] { return discard_ || done_.size() < 2; });
            if (discard_) break;
            done_.push_back({k, std::move(bytes)});
            ready_.notify_all();
        }
        std::lock_guard<std::mutex> lock(mutex_);
        running_ = false;
        ready_.notify_all();
    }

    Dispenser& tasks_;
    const std::function<std::string(int)>& work_;
    std::mutex mutex_;
    std::condition_variable ready_, room_;
    std::deque<Done> done_;
    bool running_ = true, discard_ = false;
    Failure failure_;
    RankReport report_;
    std::thread thread_;
};

// Rank 0 serves the other ranks (tasks out, results in) while its own thread computes tasks too;
// the first failure anywhere aborts every rank.
class RootServer {
public:
    RootServer(int count, const std::function<std::string(int)>& work,
               const std::function<void(int, std::string&&)>& deliver, Schedule schedule, int size, MPI_Comm comm,
               const Tags& tags)
        : deliver_(deliver),
          tasks_(count, size, schedule),
          local_(tasks_, work),
          serving_(size - 1),
          comm_(comm),
          tags_(tags) {
        report_.ranks.resize(static_cast<std::size_t>(size));
    }

    TaskReport serve() {
        Idle idle(kRootSpin);
        // Only an error of rank 0's own (out of memory receiving a result) gets out of this loop;
        // the other ranks would wait for their next reply for ever, so the whole run ends here.
        try {
            while (serving_ > 0 || local_.running()) {
                const bool anyRank = serving_ > 0;
                // Rank 0's own results first (the wait is the idle pause when no rank has written).
                const bool delivered = deliverLocalResults(anyRank ? 0 : 100000);
                if (delivered) idle.reset();
                if (!anyRank) continue;
                MPI_Status status;
                if (!arrived(comm_, MPI_ANY_SOURCE, tags_.header, &status)) {
                    if (!delivered) idle.wait();
                    continue;
                }
                idle.reset();
                answer(status.MPI_SOURCE);
            }
        } catch (...) {
            std::fprintf(stderr, "lightcone: rank 0 cannot serve the other ranks any more: %s\n",
                         messageOf(std::current_exception()).c_str());
            MPI_Abort(comm_, 1);
        }
        local_.finish();
        report_.ranks[0] = local_.report();
        if (!failure_.happened() && local_.failure().happened()) fail(local_.failure());
        report_.seconds = secondsSince(start_);
        if (failure_.deliverError) std::rethrow_exception(failure_.deliverError);
        if (failure_.happened()) throw TaskFailed(failure_.text());
        return report_;
    }

private:
    void fail(Failure f) {
        if (failure_.happened()) return;
        failure_ = std::move(f);
        tasks_.stop();
    }

    void deliverSafely(int task, std::string&& bytes) {
        if (failure_.happened()) return;
        try {
            deliver_(task, std::move(bytes));
        } catch (...) {
            Failure f;
            f.rank = 0;
            f.task = task;
            f.what = "delivering the result failed: " + messageOf(std::current_exception());
            f.deliverError = std::current_exception();
            fail(std::move(f));
        }
    }

    // Rank 0's own results, waiting up to `microseconds` for one; true if any was delivered.
    bool deliverLocalResults(long microseconds) {
        std::deque<LocalWorker::Done> mine = local_.take(std::chrono::microseconds(microseconds));
        for (LocalWorker::Done& d : mine) deliverSafely(d.task, std::move(d.bytes));
        if (!failure_.happened() && !local_.running() && local_.failure().happened()) fail(local_.failure());
        return !mine.empty();
    }

    // One message of rank `from` (ready, a result or a failure): the reply first (the next task,
    // Stop or Abort), so that the rank sends its result while rank 0 receives it.
    void answer(int from) {
        std::int64_t header[kHeaderLength];
        MPI_Recv(header, kHeaderLength, MPI_INT64_T, from, tags_.header, comm_, MPI_STATUS_IGNORE);
        const auto kind = header[0];
        const int task = static_cast<int>(header[1]);
        const auto bytes = static_cast<std::size_t>(header[2]);
        RankReport& their = report_.ranks[static_cast<std::size_t>(from)];
        if (kind != Ready) their.busySeconds += static_cast<double>(header[3]) * 1e-9;
        if (kind == Failed) {
            Failure f;
            f.rank = from;
            f.task = task;
            f.what = receiveText(from, tags_.text, comm_);
            fail(std::move(f));
        }
        std::int64_t reply[kReplyLength] = {Stop, -1, -1};
        if (failure_.happened()) {
            reply[0] = Abort;
            reply[1] = failure_.task;
            reply[2] = failure_.rank;
        } else if (const int next = tasks_.next(from); next >= 0) {
            reply[0] = Assign;
            reply[1] = next;
        }
        MPI_Send(reply, kReplyLength, MPI_INT64_T, from, tags_.reply, comm_);
        if (reply[0] == Abort) sendText(failure_.what, from, tags_.text, comm_);
        if (kind == Result && reply[0] != Abort) {
            std::string result = receiveBytes(bytes, from, tags_.bytes, comm_);
            ++their.tasks;
            their.bytesSent += bytes;
            report_.bytesToRoot += bytes;
            deliverSafely(task, std::move(result));
        }
        if (reply[0] != Assign) --serving_;
    }

    const std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();  // before any task
    const std::function<void(int, std::string&&)>& deliver_;
    TaskReport report_;
    Dispenser tasks_;
    Failure failure_;
    LocalWorker local_;
    int serving_;  // ranks that have not had their Stop or Abort yet
    MPI_Comm comm_;
    const Tags& tags_;
};

TaskReport serveAsRoot(int count, const std::function<std::string(int)>& work,
                       const std::function<void(int, std::string&&)>& deliver, Schedule schedule, int size,
                       MPI_Comm comm, const Tags& tags) {
    return RootServer(count, work, deliver, schedule, size, comm, tags).serve();
}

TaskReport serveAsWorker(const std::function<std::string(int)>& work, int rank, int size, MPI_Comm comm,
                         const Tags& tags) {
    const auto start = std::chrono::steady_clock::now();
    TaskReport report;
    report.ranks.resize(static_cast<std::size_t>(size));
    RankReport& mine = report.ranks[static_cast<std::size_t>(rank)];
    Idle idle(kWorkerSpin);
    std::int64_t header[kHeaderLength] = {Ready, -1, 0, 0};
    std::string result, error;
    for (;;) {
        MPI_Send(header, kHeaderLength, MPI_INT64_T, 0, tags.header, comm);
        if (header[0] == Failed) sendText(error, 0, tags.text, comm);
        idle.probe(comm, 0, tags.reply);
        std::int64_t reply[kReplyLength];
        MPI_Recv(reply, kReplyLength, MPI_INT64_T, 0, tags.reply, comm, MPI_STATUS_IGNORE);
        if (reply[0] == Abort) {
            const std::string what = receiveText(0, tags.text, comm);
            throw TaskFailed(failureText(static_cast<int>(reply[2]), static_cast<int>(reply[1]), what));
        }
        if (header[0] == Result) {
            sendBytes(result, 0, tags.bytes, comm);
            mine.bytesSent += result.size();
            report.bytesToRoot += result.size();
            std::string().swap(result);  // a frame may be 100 MB: not kept during the next task
        }
        if (reply[0] == Stop) break;
        const int task = static_cast<int>(reply[1]);
        const auto begin = std::chrono::steady_clock::now();
        try {
            result = work(task);
            header[0] = Result;
            header[2] = static_cast<std::int64_t>(result.size());
            ++mine.tasks;
        } catch (...) {
            result.clear();
            error = messageOf(std::current_exception());
            header[0] = Failed;
            header[2] = 0;
        }
        const double busy = secondsSince(begin);
        mine.busySeconds += busy;
        header[1] = task;
        header[3] = static_cast<std::int64_t>(busy * 1e9);
    }
    report.seconds = secondsSince(start);
    return report;
}

}  // namespace
#endif

TaskReport runTasks(int count, const std::function<std::string(int)>& work,
                    const std::function<void(int, std::string&&)>& deliver, Schedule schedule) {
    if (count < 0) throw std::invalid_argument("runTasks: negative task count " + std::to_string(count));
    const Processes& processes = Processes::current();
#ifdef LIGHTCONE_WITH_MPI
    if (processes.distributed()) {
        const MPI_Comm comm = ProcessesAccess::comm(processes);
        const Tags tags(ProcessesAccess::nextRun(processes));
        if (processes.root()) return serveAsRoot(count, work, deliver, schedule, processes.size(), comm, tags);
        return serveAsWorker(work, processes.rank(), processes.size(), comm, tags);
    }
#endif
    (void)schedule;
    (void)processes;
    return singleProcess(count, work, deliver);
}

}  // namespace lc::dist
