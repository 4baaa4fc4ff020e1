#pragma once
// Helpers shared by the bench programs: machine name and wall-clock timing.
#include <chrono>
#include <fstream>
#include <string>

namespace lc::bench {

inline std::string machineName() {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
    return "unknown CPU";
}

template <class F>
double seconds(F&& f) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace lc::bench
