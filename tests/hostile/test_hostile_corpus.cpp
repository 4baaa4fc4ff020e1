// SPDX-License-Identifier: BSD-3-Clause
// Runs `lightcone` on every case of tests/data/bad/cases.json (written by generate_corpus.py)
// as a user would, in a fresh output folder holding an earlier output (old.png, old/), and
// checks what the issue of hostile input asks: no crash (signal), no hang (120 s), the expected
// exit and message, no NaN/inf/null in what it prints, earlier outputs untouched after a
// failure, no temporary or hidden names left, nothing written outside the output folder.
#include <json/json.h>

#include <gtest/gtest.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <poll.h>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

struct Case {
    std::string name;
    std::vector<std::string> args;
    bool mustFail = true;
    std::string text;
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

const fs::path kBad = fs::path(LIGHTCONE_SOURCE_DIR) / "tests" / "data" / "bad";

std::vector<Case> loadCases() {
    std::ifstream in(kBad / "cases.json");
    Json::Value root;
    Json::CharReaderBuilder b;
    std::string errors;
    std::vector<Case> cases;
    if (!Json::parseFromStream(b, in, &root, &errors)) return cases;
    for (const auto& c : root) {
        Case k;
        k.name = c["name"].asString();
        for (const auto& a : c["args"]) k.args.push_back(a.asString());
        k.mustFail = c["expect"].asString() == "error";
        k.text = c["text"].asString();
        cases.push_back(k);
    }
    return cases;
}

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

std::string substitute(std::string s, const fs::path& out) {
    const std::pair<std::string, std::string> subs[] = {{"{bad}", kBad.string()},
                                                        {"{data}", (fs::path(LIGHTCONE_SOURCE_DIR) / "data").string()},
                                                        {"{out}", out.string()}};
    for (const auto& [from, to] : subs)
        for (std::size_t p; (p = s.find(from)) != std::string::npos;) s.replace(p, from.size(), to);
    return s;
}

struct Outcome {
    bool timedOut = false;
    int signal = 0, exitCode = -1;
    std::string out, err;
};

Outcome finished(Outcome r, int status, const fs::path& outLog, const fs::path& errLog) {
    if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
    if (WIFEXITED(status)) r.exitCode = WEXITSTATUS(status);
    r.out = slurp(outLog);
    r.err = slurp(errLog);
    return r;
}

Outcome runLightcone(const std::vector<std::string>& args, const fs::path& cwd, const fs::path& logs) {
    const fs::path outLog = logs / "stdout", errLog = logs / "stderr";
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::chdir(cwd.c_str());  // relative default outputs land in the case's folder
        const int o = ::open(outLog.c_str(), O_CREAT | O_TRUNC | O_WRONLY, 0644);
        const int e = ::open(errLog.c_str(), O_CREAT | O_TRUNC | O_WRONLY, 0644);
        ::dup2(o, 1);
        ::dup2(e, 2);
        const int null = ::open("/dev/null", O_RDONLY);
        ::dup2(null, 0);
        std::vector<char*> argv{const_cast<char*>(LIGHTCONE_BINARY)};
        for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        ::execv(LIGHTCONE_BINARY, argv.data());
        ::_exit(127);
    }
    Outcome r;
    int status = 0;
    // Woken by the child's exit itself (a pidfd), not by polling: a 5 ms poll cost 2.5 ms a case.
    const int exited = static_cast<int>(::syscall(SYS_pidfd_open, pid, 0));
    if (exited >= 0) {
        pollfd wait{exited, POLLIN, 0};
        int ready = 0;
        while ((ready = ::poll(&wait, 1, 120 * 1000)) < 0 && errno == EINTR) {
        }
        if (ready == 0) {
            ::kill(pid, SIGKILL);
            r.timedOut = true;
        }
        ::close(exited);
    } else {  // no pidfd (a kernel before 5.3, or a sandbox that forbids it): poll
        const auto t0 = std::chrono::steady_clock::now();
        while (::waitpid(pid, &status, WNOHANG) != pid) {
            if (std::chrono::steady_clock::now() - t0 > std::chrono::seconds(120)) {
                ::kill(pid, SIGKILL);
                r.timedOut = true;
                break;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
        if (!r.timedOut) return finished(r, status, outLog, errLog);
    }
    ::waitpid(pid, &status, 0);
    return finished(r, status, outLog, errLog);
}

// The corpus folder is flat: a name added, removed or renamed in it changes its modification
// time (nanoseconds on ext4), which is cheaper to compare than its 1100 names for every case.
struct FolderStamp {
    timespec modified{};
    bool operator==(const FolderStamp& o) const {
        return modified.tv_sec == o.modified.tv_sec && modified.tv_nsec == o.modified.tv_nsec;
    }
};

FolderStamp stampOf(const fs::path& dir) {
    struct stat st {};
    ::stat(dir.c_str(), &st);
    return {st.st_mtim};
}

// Every name under the output folder is visible (no temporaries, no hidden piece folders) and
// every file a .vtm points to exists.
void expectCleanOutputs(const fs::path& out) {
    for (const auto& e : fs::recursive_directory_iterator(out)) {
        const std::string name = e.path().filename().string();
        EXPECT_NE(name.front(), '.') << "hidden or temporary name left: " << e.path();
        if (e.path().extension() == ".vtm") {
            const std::string index = slurp(e.path());
            const std::regex file("file=\"([^\"]+)\"");
            for (std::sregex_iterator m(index.begin(), index.end(), file), end; m != end; ++m) {
                const fs::path piece = e.path().parent_path() / (*m)[1].str();
                EXPECT_TRUE(fs::exists(piece)) << e.path() << " points to a missing " << piece;
                EXPECT_EQ((*m)[1].str().find(".."), std::string::npos) << "piece outside the folder: " << (*m)[1];
            }
        }
    }
}

// A word "nan", "inf" or "infinity" (any case), or a JSON null value, in the output.
bool printsNonFinite(const std::string& text) {
    if (text.find(": null") != std::string::npos) return true;
    std::string word;
    for (std::size_t i = 0; i <= text.size(); ++i) {
        const char c = i < text.size() ? text[i] : ' ';
        if (std::isalpha(static_cast<unsigned char>(c))) {
            word += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
            continue;
        }
        if (word == "nan" || word == "inf" || word == "infinity") return true;
        word.clear();
    }
    return false;
}

class HostileCorpus : public ::testing::TestWithParam<Case> {};

TEST(HostileCorpusFile, HasAtLeastThreeHundredCases) { EXPECT_GE(loadCases().size(), 300u); }

TEST_P(HostileCorpus, NoCrashNoHangNoNanNothingLost) {
    const Case& c = GetParam();
    const fs::path root = fs::temp_directory_path() / ("lightcone-hostile-" + std::to_string(::getpid()));
    const fs::path out = root / c.name, logs = root / (c.name + ".logs");
    fs::remove_all(out);
    fs::remove_all(logs);
    fs::create_directories(out / "old");
    fs::create_directories(logs);
    std::ofstream(out / "old.png") << "OLD";
    std::ofstream(out / "old" / "marker.txt") << "OLD";
    std::vector<std::string> args;
    for (const auto& a : c.args) args.push_back(substitute(a, out));
    const FolderStamp corpusBefore = stampOf(kBad);

    // Exports run twice: a second run into the same folder must leave it as clean as the first.
    const bool twice = !c.mustFail && c.args.front() == "export";
    Outcome r;
    for (int k = 0; k < (twice ? 2 : 1); ++k) r = runLightcone(args, out, logs);

    ASSERT_FALSE(r.timedOut) << "hang: killed after 120 s";
    ASSERT_EQ(r.signal, 0) << "crashed with signal " << r.signal << "\nstderr: " << r.err;
    if (c.mustFail) {
        EXPECT_NE(r.exitCode, 0) << "exit 0 on bad input\nstdout: " << r.out;
        EXPECT_NE(r.err.find(c.text), std::string::npos) << "stderr lacks '" << c.text << "':\n" << r.err;
        EXPECT_NE(r.err.find("lightcone"), std::string::npos) << "errors start with the program's name";
        EXPECT_EQ(slurp(out / "old.png"), "OLD") << "a failed run replaced an earlier output";
        EXPECT_EQ(slurp(out / "old" / "marker.txt"), "OLD");
    } else {
        EXPECT_EQ(r.exitCode, 0) << "stderr: " << r.err;
        EXPECT_NE(r.out.find(c.text), std::string::npos) << "stdout lacks '" << c.text << "':\n" << r.out;
        if (c.args.front() == "render") {
            EXPECT_EQ(slurp(out / "old.png").substr(1, 3), "PNG") << "no image written";
        }
    }
    // Results (stdout) hold no non-finite number; error messages may quote the bad input.
    EXPECT_FALSE(printsNonFinite(r.out)) << "non-finite value printed:\n" << r.out;
    expectCleanOutputs(out);
    EXPECT_TRUE(stampOf(kBad) == corpusBefore) << "something was written into the corpus folder";
    EXPECT_FALSE(fs::exists("/tmp/escaped")) << "an object name escaped its folder";
    fs::remove_all(out);
    fs::remove_all(logs);
}

INSTANTIATE_TEST_SUITE_P(Corpus, HostileCorpus, ::testing::ValuesIn(loadCases()),
                         [](const ::testing::TestParamInfo<Case>& param) { return param.param.name; });

}  // namespace

// SIGKILL cannot be caught: outputs are made in memory and unnamed files, so a run killed at any
// moment leaves the earlier image and data as they were and no temporary names.
TEST(KilledRun, LeavesEarlierOutputsAndNoTemporaryNames) {
    const fs::path out = fs::temp_directory_path() / ("lightcone-killed-" + std::to_string(::getpid()));
    fs::remove_all(out);
    fs::create_directories(out);
    for (const int delayMs : {200, 700, 1500}) {
        std::ofstream(out / "old.png") << "OLD";
        std::ofstream(out / "old.exr") << "OLD";
        const pid_t pid = ::fork();
        if (pid == 0) {
            const int null = ::open("/dev/null", O_WRONLY);
            ::dup2(null, 1);
            ::dup2(null, 2);
            const std::string scene = (fs::path(LIGHTCONE_SOURCE_DIR) / "data" / "default.json").string();
            const std::string png = (out / "old.png").string(), exr = (out / "old.exr").string();
            ::execl(LIGHTCONE_BINARY, LIGHTCONE_BINARY, "render", scene.c_str(), "-o", png.c_str(), "--data",
                    exr.c_str(), "--method", "numeric", "--width", "720", "--height", "240",
                    static_cast<char*>(nullptr));
            ::_exit(127);
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(delayMs));
        ::kill(pid, SIGKILL);
        int status = 0;
        ::waitpid(pid, &status, 0);
        ASSERT_TRUE(WIFSIGNALED(status)) << "the render finished before the kill at " << delayMs << " ms";
        EXPECT_EQ(slurp(out / "old.png"), "OLD") << "killed at " << delayMs << " ms";
        EXPECT_EQ(slurp(out / "old.exr"), "OLD") << "killed at " << delayMs << " ms";
        for (const auto& e : fs::directory_iterator(out))
            EXPECT_NE(e.path().filename().string().front(), '.') << "left behind: " << e.path();
    }
    fs::remove_all(out);
}
