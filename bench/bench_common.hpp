// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Helpers shared by the bench programs: machine name and wall-clock timing.
#include <chrono>
#include <cstdio>
#include <vector>
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

// ns per call of f over `points`, repeated until at least `minimum` seconds have passed; f's
// results are summed so the work stays observable.
template <class Point, class F>
double nsPerCall(const std::vector<Point>& points, F&& f, double minimum = 0.2) {
    double sink = 0, elapsed = 0;
    std::size_t calls = 0;
    while (elapsed < minimum) {
        elapsed += seconds([&] {
            for (const Point& x : points) sink += f(x);
        });
        calls += points.size();
    }
    if (sink == 42.4242) std::printf(" ");
    return 1e9 * elapsed / static_cast<double>(calls);
}

}  // namespace lc::bench
