// SPDX-License-Identifier: BSD-3-Clause
// Start-up of `lightcone` as a whole process (issue #45): process start to exit, median of 20
// runs, for the commands that should answer at once (--version, help, completion) and for a
// small render, beside the render time the program itself reports ("time 0.05 s"): the goal is
// --version, help and completion in <= 50 ms and a 64 x 32 Schwarzschild render in <= 2x its
// render time. Run from anywhere: ./build/bench/bench_startup [RUNS]
#include "bench_common.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

extern char** environ;

namespace {

struct Run {
    double seconds = 0;  // process start to exit
    std::string output;  // stdout and stderr
    int exitCode = -1;
};

// posix_spawn with stdout and stderr into a pipe, timed from before the spawn to after waitpid.
Run runProcess(const std::vector<std::string>& args) {
    int pipeEnds[2];
    if (pipe(pipeEnds) != 0) std::abort();
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, pipeEnds[1], 1);
    posix_spawn_file_actions_adddup2(&actions, pipeEnds[1], 2);
    posix_spawn_file_actions_addclose(&actions, pipeEnds[0]);
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    Run run;
    pid_t pid = 0;
    const auto start = std::chrono::steady_clock::now();
    if (posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ) != 0) std::abort();
    close(pipeEnds[1]);
    std::array<char, 4096> buffer{};
    for (ssize_t n; (n = read(pipeEnds[0], buffer.data(), buffer.size())) > 0;) run.output.append(buffer.data(), n);
    int status = 0;
    waitpid(pid, &status, 0);
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    close(pipeEnds[0]);
    posix_spawn_file_actions_destroy(&actions);
    run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return run;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

// The render time the program reports: "time 0.045 s (45729 rays/s), ...".
double reportedRenderSeconds(const std::string& output) {
    std::smatch m;
    return std::regex_search(output, m, std::regex(R"(\ntime ([0-9.e+-]+) s)")) ? std::stod(m[1]) : -1;
}

}  // namespace

int main(int argc, char** argv) {
    const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 20;
    const std::string lightcone = LIGHTCONE_BINARY, data = std::string(LIGHTCONE_SOURCE_DIR) + "/data/";
    const std::filesystem::path out =
        std::filesystem::temp_directory_path() / ("bench_startup_" + std::to_string(getpid()));
    std::filesystem::create_directories(out);
    const std::string scene = data + "schwarzschild_infall.json";
    const auto render = [&](const std::string& file) {
        return std::vector<std::string>{lightcone, "render",   scene, "-o",      (out / file).string(), "--width",
                                        "64",      "--height", "32",  "--quiet", "--threads",           "2"};
    };
    struct Case {
        std::string name;
        std::vector<std::string> args;
        bool reportsRender;
    };
    const std::vector<Case> cases{
        {"`lightcone --version`", {lightcone, "--version"}, false},
        {"`lightcone help`", {lightcone, "help"}, false},
        {"`lightcone completion bash`", {lightcone, "completion", "bash"}, false},
        {"`lightcone render` 64 x 32 Schwarzschild, PNG", render("s.png"), true},
        {"`lightcone render` 64 x 32 Schwarzschild, EXR", render("s.exr"), true},
    };
    std::printf("## Start-up: whole processes, median of %d runs\n\n%s, %s\n\n", runs, lc::bench::machineName().c_str(),
                lightcone.c_str());
    std::printf("| command | process start to exit | render time it reports | process / render |\n|---|---|---|---|\n");
    for (const Case& c : cases) {
        runProcess(c.args);  // warm the page cache
        std::vector<double> wall, rendered;
        for (int i = 0; i < runs; ++i) {
            const Run r = runProcess(c.args);
            if (r.exitCode != 0) {
                std::fprintf(stderr, "%s failed (%d):\n%s\n", c.name.c_str(), r.exitCode, r.output.c_str());
                return 1;
            }
            wall.push_back(r.seconds);
            if (c.reportsRender) rendered.push_back(reportedRenderSeconds(r.output));
        }
        if (c.reportsRender)
            std::printf("| %s | %.1f ms | %.1f ms | %.2f |\n", c.name.c_str(), 1e3 * median(wall),
                        1e3 * median(rendered), median(wall) / median(rendered));
        else
            std::printf("| %s | %.1f ms | | |\n", c.name.c_str(), 1e3 * median(wall));
    }
    std::filesystem::remove_all(out);
    return 0;
}
