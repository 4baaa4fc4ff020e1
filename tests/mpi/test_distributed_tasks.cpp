// SPDX-License-Identifier: BSD-3-Clause
// lc::dist::runTasks (app/distributed) on however many processes run this executable: alone,
// and under `mpirun -np 2` and `-np 3` (ctest registers all three). Every rank runs every test;
// each runTasks call is made by all ranks, and the checks come after it, so that one rank's
// failed check never leaves the others waiting. Rank 0 prints gtest's usual output, the other
// ranks only their failures; every rank exits nonzero when one of its checks failed.
#include "app/distributed/distributed_tasks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <mutex>
#include <regex>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace {

using lc::dist::Processes;
using lc::dist::runTasks;
using lc::dist::Schedule;
using lc::dist::TaskFailed;
using lc::dist::TaskReport;

const Processes& processes() { return Processes::current(); }
int rank() { return processes().rank(); }
int ranks() { return processes().size(); }

// Task k's bytes: a size that varies with k (task 5 empty, task 17 just over 16 MiB), content
// that depends on k and on the position, so a swapped, cut or shifted result is seen.
std::size_t sizeOf(int k) {
    if (k == 5) return 0;
    if (k == 17) return (std::size_t(16) << 20) + 4099;
    return static_cast<std::size_t>(k) * 997 + static_cast<std::size_t>(k % 7) * 13 + 1;
}
std::string bytesOf(int k) {
    std::string s(sizeOf(k), '\0');
    for (std::size_t i = 0; i < s.size(); ++i)
        s[i] = static_cast<char>((i * 131 + static_cast<std::size_t>(k) * 7) % 251);
    return s;
}

// A result that says which rank made it: "<rank>|<payload>".
std::string stamped(const std::string& payload) { return std::to_string(rank()) + "|" + payload; }
int rankOf(const std::string& result) { return std::stoi(result.substr(0, result.find('|'))); }
std::string payloadOf(const std::string& result) { return result.substr(result.find('|') + 1); }

void sleepMs(int ms) { std::this_thread::sleep_for(std::chrono::milliseconds(ms)); }

struct Delivered {
    std::map<int, std::string> results;  // task -> bytes
    int calls = 0;
    bool offMainThread = false;
};

// A run of `count` tasks whose results are recorded on rank 0.
TaskReport runRecording(int count, const std::function<std::string(int)>& work, Delivered& out,
                        Schedule schedule = Schedule::Dynamic) {
    const std::thread::id caller = std::this_thread::get_id();
    return runTasks(
        count, work,
        [&](int k, std::string&& bytes) {
            ++out.calls;
            if (std::this_thread::get_id() != caller) out.offMainThread = true;
            out.results[k] = std::move(bytes);
        },
        schedule);
}

// After a failed run, the processes still work together: a fresh run delivers everything.
void expectUsable() {
    Delivered d;
    runRecording(
        2 * ranks() + 1, [](int k) { return stamped(std::to_string(k)); }, d);
    if (!processes().root()) return;
    EXPECT_EQ(d.calls, 2 * ranks() + 1);
    for (int k = 0; k < 2 * ranks() + 1; ++k) EXPECT_EQ(payloadOf(d.results[k]), std::to_string(k));
}

TEST(Processes, MatchTheLauncher) {
    const char* size = std::getenv("OMPI_COMM_WORLD_SIZE");
    const char* own = std::getenv("OMPI_COMM_WORLD_RANK");
    if (Processes::builtWithMpi() && size && own) {
        EXPECT_EQ(ranks(), std::atoi(size));
        EXPECT_EQ(rank(), std::atoi(own));
    } else if (!std::getenv("PMIX_RANK") && !std::getenv("PMI_RANK")) {
        EXPECT_EQ(ranks(), 1);
        EXPECT_EQ(rank(), 0);
    }
    EXPECT_EQ(processes().distributed(), ranks() > 1);
    EXPECT_EQ(processes().root(), rank() == 0);
}

TEST(DistributedTasks, DeliverEveryResultOnceWithItsBytes) {
    const int count = 40;
    std::atomic<int> computedHere{0};
    Delivered d;
    const TaskReport report = runRecording(
        count,
        [&](int k) {
            ++computedHere;
            return stamped(bytesOf(k));
        },
        d);
    EXPECT_EQ(report.ranks.size(), static_cast<std::size_t>(ranks()));
    EXPECT_EQ(report.ranks[static_cast<std::size_t>(rank())].tasks, computedHere.load());
    if (!processes().root()) {
        EXPECT_EQ(d.calls, 0) << "deliver is called on rank 0 only";
        return;
    }
    EXPECT_FALSE(d.offMainThread) << "deliver must run on the thread that called runTasks";
    EXPECT_EQ(d.calls, count);
    ASSERT_EQ(d.results.size(), static_cast<std::size_t>(count));
    int tasks = 0;
    std::uint64_t sent = 0, expectedToRoot = 0;
    for (int k = 0; k < count; ++k) {
        const std::string& result = d.results[k];
        const int by = rankOf(result);
        EXPECT_TRUE(by >= 0 && by < ranks()) << "task " << k;
        EXPECT_TRUE(payloadOf(result) == bytesOf(k)) << "task " << k << ": " << result.size() << " bytes";
        if (by != 0) expectedToRoot += result.size();
    }
    for (const lc::dist::RankReport& r : report.ranks) {
        tasks += r.tasks;
        sent += r.bytesSent;
    }
    EXPECT_EQ(tasks, count);
    EXPECT_EQ(report.ranks[0].bytesSent, 0u);
    EXPECT_EQ(sent, expectedToRoot);
    EXPECT_EQ(report.bytesToRoot, expectedToRoot);
    EXPECT_GT(report.seconds, 0.0);
}

TEST(DistributedTasks, NoTasks) {
    for (Schedule schedule : {Schedule::Dynamic, Schedule::Static}) {
        int computed = 0;
        Delivered d;
        const TaskReport report = runRecording(
            0,
            [&](int) {
                ++computed;
                return std::string("x");
            },
            d, schedule);
        EXPECT_EQ(computed, 0);
        EXPECT_EQ(d.calls, 0);
        EXPECT_EQ(report.ranks.size(), static_cast<std::size_t>(ranks()));
        for (const lc::dist::RankReport& r : report.ranks) EXPECT_EQ(r.tasks, 0);
        EXPECT_EQ(report.bytesToRoot, 0u);
    }
}

TEST(DistributedTasks, FewerTasksThanRanks) {
    const int count = std::max(1, ranks() - 1);
    for (Schedule schedule : {Schedule::Dynamic, Schedule::Static}) {
        Delivered d;
        runRecording(
            count, [](int k) { return stamped("task " + std::to_string(k)); }, d, schedule);
        if (!processes().root()) continue;
        EXPECT_EQ(d.calls, count);
        for (int k = 0; k < count; ++k) EXPECT_EQ(payloadOf(d.results[k]), "task " + std::to_string(k));
    }
}

TEST(DistributedTasks, StaticScheduleRunsTaskKOnRankKModSize) {
    const int count = 3 * ranks() + 1;
    Delivered d;
    const TaskReport report = runRecording(
        count, [](int k) { return stamped(std::to_string(k)); }, d, Schedule::Static);
    if (!processes().root()) return;
    ASSERT_EQ(d.calls, count);
    std::vector<int> expected(static_cast<std::size_t>(ranks()), 0);
    for (int k = 0; k < count; ++k) {
        EXPECT_EQ(rankOf(d.results[k]), k % ranks()) << "task " << k;
        EXPECT_EQ(payloadOf(d.results[k]), std::to_string(k));
        ++expected[static_cast<std::size_t>(k % ranks())];
    }
    for (int r = 0; r < ranks(); ++r) EXPECT_EQ(report.ranks[static_cast<std::size_t>(r)].tasks, expected[r]);
}

// One task of 800 ms and 40 of 20 ms: dynamically, the rank that has the slow task does few
// others while the rest share them; statically rank 0 does its 14 or 21 tasks after the slow one.
TEST(DistributedTasks, DynamicScheduleBalancesUnequalTasks) {
    const int count = 41, slow = 0;
    auto work = [&](int k) {
        sleepMs(k == slow ? 800 : 20);
        return stamped(std::to_string(k));
    };
    Delivered dynamic, fixed;
    const TaskReport balanced = runRecording(count, work, dynamic, Schedule::Dynamic);
    const TaskReport imbalanced = runRecording(count, work, fixed, Schedule::Static);
    if (!processes().root()) return;
    ASSERT_EQ(dynamic.calls, count);
    ASSERT_EQ(fixed.calls, count);
    if (ranks() == 1) return;
    const int slowRank = rankOf(dynamic.results[slow]);
    const int slowRankTasks = balanced.ranks[static_cast<std::size_t>(slowRank)].tasks;
    for (int r = 0; r < ranks(); ++r) {
        if (r == slowRank) continue;
        EXPECT_LT(slowRankTasks, balanced.ranks[static_cast<std::size_t>(r)].tasks)
            << "rank " << slowRank << " had the slow task, rank " << r << " did not";
    }
    EXPECT_LE(slowRankTasks, count / 4) << "(1 or 2 alone, up to 7 beside two busy loops)";
    std::printf("[ balance  ] %d ranks: dynamic %.3f s (the slow task's rank did %d of %d tasks), static %.3f s\n",
                ranks(), balanced.seconds, slowRankTasks, count, imbalanced.seconds);
    EXPECT_LT(balanced.seconds + 0.1, imbalanced.seconds);
    EXPECT_GE(balanced.seconds, 0.8);
}

// A failed task's message, as every rank must see it.
void expectNamed(const std::string& what, int failedRank, int failedTask) {
    const std::string prefix = "rank " + std::to_string(failedRank) + ", task " + std::to_string(failedTask) + ": ";
    EXPECT_EQ(what, prefix + "injected failure in task " + std::to_string(failedTask)) << "on rank " << rank();
}

// Static schedule, so that the failing task runs where the test wants it: its rank's third.
void failOnRank(int failing) {
    const int perRank = 30, count = perRank * ranks(), failingTask = failing + 2 * ranks();
    int computed = 0;
    Delivered d;
    std::string what;
    try {
        runRecording(
            count,
            [&](int k) {
                ++computed;
                if (k == failingTask) throw std::runtime_error("injected failure in task " + std::to_string(k));
                sleepMs(20);
                return stamped(std::to_string(k));
            },
            d, Schedule::Static);
    } catch (const TaskFailed& e) {
        what = e.what();
    }
    expectNamed(what, failing, failingTask);
    EXPECT_LT(computed, perRank / 3) << "tasks must stop being handed out after the failure (rank " << rank() << ")";
    EXPECT_LT(d.calls, count);
    EXPECT_EQ(d.results.count(failingTask), 0u);
    expectUsable();
}

TEST(DistributedTasks, FailureOnAnotherRankReachesEveryRank) { failOnRank(ranks() - 1); }

TEST(DistributedTasks, FailureOnRankZeroReachesEveryRank) { failOnRank(0); }

// Dynamic schedule: every task on the last rank throws; whichever it got first is named.
TEST(DistributedTasks, FailureUnderDynamicScheduleNamesRankAndTask) {
    const int failing = ranks() - 1;
    std::string what;
    Delivered d;
    try {
        runRecording(
            50,
            [&](int k) -> std::string {
                if (rank() == failing) throw std::runtime_error("injected failure in task " + std::to_string(k));
                sleepMs(5);
                return stamped(std::to_string(k));
            },
            d);
    } catch (const TaskFailed& e) {
        what = e.what();
    }
    std::smatch m;
    const std::string expected =
        "rank " + std::to_string(failing) + ", task ([0-9]+): injected failure in task ([0-9]+)";
    ASSERT_TRUE(std::regex_match(what, m, std::regex(expected))) << what << " (rank " << rank() << ")";
    EXPECT_EQ(m[1], m[2]);
    EXPECT_EQ(d.results.count(std::stoi(m[1])), 0u);
    expectUsable();
}

// rank 0's deliver throws: rank 0 gets its own exception back, the others TaskFailed naming it.
TEST(DistributedTasks, DeliverErrorStopsEveryRank) {
    const int count = 20 * ranks(), failingTask = 3;
    int computed = 0, delivered = 0;
    std::string what;
    bool own = false;
    try {
        runTasks(
            count,
            [&](int k) {
                ++computed;
                sleepMs(10);
                return std::to_string(k);
            },
            [&](int k, std::string&&) {
                ++delivered;
                if (k == failingTask) throw std::logic_error("disk full at task " + std::to_string(k));
            },
            Schedule::Static);
    } catch (const TaskFailed& e) {
        what = e.what();
    } catch (const std::logic_error& e) {
        own = true;
        what = e.what();
    }
    if (processes().root()) {
        EXPECT_TRUE(own) << what;
        EXPECT_EQ(what, "disk full at task 3");
        EXPECT_LT(delivered, count);
    } else {
        EXPECT_FALSE(own);
        EXPECT_EQ(what, "rank 0, task 3: delivering the result failed: disk full at task 3");
        EXPECT_EQ(delivered, 0);
    }
    EXPECT_LT(computed, 15);
    expectUsable();
}

// With one process: work then deliver, task after task, on the calling thread.
TEST(DistributedTasks, OneProcessWorksThenDeliversInOrder) {
    if (ranks() > 1) GTEST_SKIP() << "for one process";
    std::vector<std::string> events;
    const std::thread::id caller = std::this_thread::get_id();
    bool otherThread = false;
    auto work = [&](int k) {
        otherThread |= std::this_thread::get_id() != caller;
        events.push_back("w" + std::to_string(k));
        return std::to_string(k * k);
    };
    auto deliver = [&](int k, std::string&& bytes) {
        otherThread |= std::this_thread::get_id() != caller;
        events.push_back("d" + std::to_string(k) + "=" + bytes);
    };
    const TaskReport report = runTasks(4, work, deliver, Schedule::Dynamic);
    EXPECT_EQ(events, (std::vector<std::string>{"w0", "d0=0", "w1", "d1=1", "w2", "d2=4", "w3", "d3=9"}));
    EXPECT_FALSE(otherThread);
    EXPECT_EQ(report.ranks.size(), 1u);
    EXPECT_EQ(report.ranks[0].tasks, 4);
    std::string what;
    try {
        runTasks(
            3, [](int k) -> std::string { throw std::runtime_error("injected failure in task " + std::to_string(k)); },
            [](int, std::string&&) {});
    } catch (const TaskFailed& e) {
        what = e.what();
    }
    expectNamed(what, 0, 0);
}

// While the other ranks compute, rank 0 (its thread sleeps here too) polls with sleeps: the
// processes use a small part of one core, not one core each (OpenMPI's blocking calls would).
TEST(DistributedTasks, WaitingDoesNotBurnACore) {
    const std::clock_t cpu = std::clock();
    const TaskReport report = runTasks(
        2 * ranks(),
        [](int) {
            sleepMs(300);
            return std::string(1000, 'x');
        },
        [](int, std::string&&) {}, Schedule::Static);
    const double share = (static_cast<double>(std::clock() - cpu) / CLOCKS_PER_SEC) / report.seconds;
    if (processes().root()) std::printf("[ cpu      ] %d ranks: rank 0 used %.1f %% of a core\n", ranks(), 100 * share);
    EXPECT_GE(report.seconds, 0.6);
    EXPECT_LT(share, 0.2) << "rank " << rank() << " used " << 100 * share << " % of a core while waiting";
}

// The cost of one task that does nothing: a rank's request, rank 0's reply and the (empty)
// result, back to back (both sides still spinning). Static, so that every rank does its share
// (dynamically rank 0's thread would take most).
TEST(DistributedTasks, EmptyTaskRoundTrip) {
    const int perRank = 500;
    const TaskReport report = runTasks(
        perRank * ranks(), [](int) { return std::string(); }, [](int, std::string&&) {}, Schedule::Static);
    const double perTask = report.seconds / perRank;
    if (processes().root())
        std::printf("[ overhead ] %d ranks: %d empty tasks in %.3f s, %.1f us per task and rank\n", ranks(),
                    perRank * ranks(), report.seconds, perTask * 1e6);
    EXPECT_LT(perTask, 0.05) << "(2 cores, 3 ranks and 2 busy loops beside them: 6 ms)";
}

// The same with tasks of 2 ms (a sleep, which itself overruns by about 0.1 ms): rank 0 sleeps
// between probes by then, so a request waits up to one of its sleeps.
TEST(DistributedTasks, ShortTaskRoundTrip) {
    const int perRank = 200;
    const TaskReport report = runTasks(
        perRank * ranks(),
        [](int) {
            sleepMs(2);
            return std::string();
        },
        [](int, std::string&&) {}, Schedule::Static);
    const double perTask = report.seconds / perRank - 0.002;
    if (processes().root())
        std::printf("[ overhead ] %d ranks: %d tasks of 2 ms in %.3f s, %.1f us more per task and rank\n", ranks(),
                    perRank * ranks(), report.seconds, perTask * 1e6);
    EXPECT_LT(perTask, 0.05);
}

// Only rank 0 prints gtest's output; the others print their failures, named by rank. (The test's
// name is kept from OnTestStart: UnitTest::current_test_info() here would wait for the lock that
// gtest holds while it reports a result.)
class RankFailurePrinter : public testing::EmptyTestEventListener {
public:
    explicit RankFailurePrinter(int r) : rank_(r) {}
    void OnTestStart(const testing::TestInfo& test) override {
        test_ = std::string(test.test_suite_name()) + "." + test.name();
    }
    void OnTestPartResult(const testing::TestPartResult& result) override {
        if (!result.failed()) return;
        std::fprintf(stderr, "[rank %d] %s failed at %s:%d\n%s\n", rank_, test_.c_str(),
                     result.file_name() ? result.file_name() : "?", result.line_number(), result.message());
    }

private:
    int rank_;
    std::string test_;
};

}  // namespace

int main(int argc, char** argv) {
    const Processes processes(argc, argv);  // before gtest: MPI_Init may take its own arguments
    testing::InitGoogleTest(&argc, argv);
    if (!processes.root()) {
        testing::TestEventListeners& listeners = testing::UnitTest::GetInstance()->listeners();
        delete listeners.Release(listeners.default_result_printer());
        listeners.Append(new RankFailurePrinter(processes.rank()));
    }
    return RUN_ALL_TESTS();
}
