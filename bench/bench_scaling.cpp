// SPDX-License-Identifier: BSD-3-Clause
// Strong scaling of a numeric Kerr image over MPI ranks (lightcone render under mpirun): wall
// time against ranks and threads, the load imbalance of static against dynamic tiles, the bytes
// gathered to rank 0 per frame and the cost of a task (bands of 1 to 64 rows). Runs the real
// binary; prints markdown tables for docs/SCALING.md. Usage: bench_scaling [WIDTH HEIGHT].
#include "bench_common.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/render/render.hpp"
#include "readers/io/image_io.hpp"

#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <string>
#include <thread>
#include <tuple>
#include <unistd.h>

namespace {

struct Run {
    double wall = 0, renderSeconds = 0, imbalance = 1, megabytes = 0;
    bool ok = false;
};

double number(const std::string& text, const std::string& pattern) {
    std::smatch m;
    return std::regex_search(text, m, std::regex(pattern)) ? std::stod(m[1]) : -1;
}

Run render(int ranks, int threads, const std::string& schedule, int tileRows, int width, int height) {
    char cmd[1024];
    const std::string launcher = ranks > 1 ? std::string("OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 ") +
                                                 LIGHTCONE_MPIEXEC + " --oversubscribe --bind-to none -np " +
                                                 std::to_string(ranks) + " "
                                           : "";
    std::snprintf(cmd, sizeof cmd,
                  "%s%s render %s/data/kerr.json -o /tmp/bench_scaling_%d.png --width %d --height %d --threads %d "
                  "--schedule %s --tile-rows %d --quiet 2>&1",
                  launcher.c_str(), LIGHTCONE_BINARY, LIGHTCONE_SOURCE_DIR, static_cast<int>(::getpid()), width, height,
                  threads, schedule.c_str(), tileRows);
    const auto t0 = std::chrono::steady_clock::now();
    FILE* pipe = ::popen(cmd, "r");
    std::string out;
    std::array<char, 4096> buf{};
    std::size_t n;
    while (pipe && (n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0) out.append(buf.data(), n);
    Run r;
    r.ok = pipe && ::pclose(pipe) == 0;
    r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    r.renderSeconds = number(out, R"(time ([0-9.]+) s)");
    if (ranks > 1) {
        r.imbalance = number(out, R"(load imbalance ([0-9.]+))");
        r.megabytes = number(out, R"(([0-9.]+) MB per frame)");
    }
    if (!r.ok) std::fprintf(stderr, "failed: %s\n%s\n", cmd, out.c_str());
    return r;
}

// Rank 0's own work per frame, which no rank count shortens: shading the gathered records and
// encoding the PNG, for a 1920x1080 frame of sky pixels.
void rootWorkPerFrame() {
    lc::Scene scene;
    scene.spacetime = std::make_shared<lc::KerrNewman>(1.0, 0.9, 0.0);
    scene.sky = std::make_shared<lc::CheckerTexture>(36, 18, lc::Vec3(0.9, 0.9, 0.85), lc::Vec3(0.1, 0.15, 0.3));
    lc::RenderResult records;
    records.width = 1920;
    records.height = 1080;
    records.pixels.resize(1920u * 1080u);
    for (std::size_t n = 0; n < records.pixels.size(); ++n) {
        records.pixels[n].kind = lc::PixelRecord::Sky;
        records.pixels[n].u = static_cast<float>(n % 1920) / 1920;
        records.pixels[n].v = static_cast<float>(n / 1920) / 1080;
    }
    const auto t0 = std::chrono::steady_clock::now();
    lc::io::ImageChannels img;
    img.width = 1920;
    img.height = 1080;
    img.names = {"R", "G", "B"};
    img.data = lc::shadePixels(scene, records);
    const auto t1 = std::chrono::steady_clock::now();
    const std::string png = lc::io::encodeImage("frame.png", img);
    const auto t2 = std::chrono::steady_clock::now();
    std::printf("\n## Rank 0's serial work per 1920x1080 frame\n\n| step | s | bytes |\n|---|---|---|\n");
    std::printf("| shading 2.07 M records | %.3f | |\n", std::chrono::duration<double>(t1 - t0).count());
    std::printf("| PNG encoding | %.3f | %zu |\n", std::chrono::duration<double>(t2 - t1).count(), png.size());
    std::printf("| records gathered (44 B/pixel: render, and animate with --data) | | %zu |\n",
                sizeof(lc::PixelRecord) * 1920u * 1080u);
    std::printf("| colours gathered (12 B/pixel, animate without --data) | | %zu |\n", std::size_t{12} * 1920 * 1080);
}

}  // namespace

int main(int argc, char** argv) {
    const int width = argc > 2 ? std::atoi(argv[1]) : 240, height = argc > 2 ? std::atoi(argv[2]) : 120;
    const unsigned cores = std::thread::hardware_concurrency();
    std::printf("# bench_scaling: numeric Kerr (data/kerr.json, a = 0.9, dopri5 tol 1e-8), %dx%d\n\n", width, height);
    std::printf(
        "Machine: %s, %u cores. Ranks beyond the cores are oversubscribed (mpirun --oversubscribe "
        "--bind-to none). Render time is lightcone's own (scene read to image written is the wall time, "
        "including MPI start-up).\n\n",
        lc::bench::machineName().c_str(), cores);

    std::printf("## Strong scaling (dynamic tiles of 8 rows)\n\n");
    std::printf(
        "| ranks | threads per rank | render s | wall s | speed-up (render) | imbalance | MB to rank 0 per frame |\n");
    std::printf("|---|---|---|---|---|---|---|\n");
    double base = 0;
    for (auto [ranks, threads] : {std::pair{1, 1}, {1, 2}, {2, 1}, {3, 1}, {2, 2}}) {
        const Run r = render(ranks, threads, "dynamic", 8, width, height);
        if (base == 0) base = r.renderSeconds;
        std::printf("| %d | %d | %.3f | %.3f | %.2f | %.3f | %.2f |\n", ranks, threads, r.renderSeconds, r.wall,
                    base / r.renderSeconds, r.imbalance, r.megabytes);
    }

    std::printf("\n## Static against dynamic tiles (1 thread per rank)\n\n");
    std::printf(
        "Static contiguous: one band of rows per rank (the split a fixed decomposition makes); static "
        "interleaved: 8-row tiles dealt round-robin; dynamic: 8-row tiles to whichever rank asks.\n\n");
    std::printf("| ranks | tiles | render s | imbalance (busiest / mean) |\n|---|---|---|---|\n");
    for (int ranks : {2, 3}) {
        const int band = (height + ranks - 1) / ranks;
        for (auto [label, schedule, rows] : {std::tuple{"static contiguous", "static", band},
                                             {"static interleaved", "static", 8},
                                             {"dynamic", "dynamic", 8}}) {
            const Run r = render(ranks, 1, schedule, rows, width, height);
            std::printf("| %d | %s | %.3f | %.3f |\n", ranks, label, r.renderSeconds, r.imbalance);
        }
    }

    std::printf("\n## Cost of a task: tile height (2 ranks, 1 thread each, dynamic)\n\n");
    std::printf("| rows per tile | tiles | render s | imbalance |\n|---|---|---|---|\n");
    for (int rows : {1, 4, 8, 32, height / 2}) {
        const Run r = render(2, 1, "dynamic", rows, width, height);
        std::printf("| %d | %d | %.3f | %.3f |\n", rows, (height + rows - 1) / rows, r.renderSeconds, r.imbalance);
    }
    rootWorkPerFrame();
    return 0;
}
