// SPDX-License-Identifier: BSD-3-Clause
// Work-precision diagrams: for every hard ray of tests/common/hard_rays.hpp and every adaptive
// stepper, the error relative to the independent reference against the time per ray, at
// tolerances 1e-6 to 1e-14. Prints a markdown table (machine named) and, with --svg FILE, draws
// the diagrams, one panel per ray (docs/PERFORMANCE.md, docs/images/work_precision.svg).
//   ./build/bench/bench_work_precision [--svg docs/images/work_precision.svg] [--seconds S]
#include "bench_common.hpp"
#include "tests/common/hard_rays.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

using namespace lc;

namespace {

const std::vector<std::string> kSteppers{"cash_karp54", "dopri5", "dopri87", "bulirsch_stoer"};
const std::vector<const char*> kColours{"#1b9e77", "#d95f02", "#7570b3", "#e7298a"};
const std::vector<double> kTolerances{1e-6, 1e-8, 1e-10, 1e-12, 1e-14};

struct Point {
    double tolerance = 0, microseconds = 0, error = 0;
};

// Mean microseconds of one ray over at least `minSeconds`, and its error.
Point measure(const test::HardRay& ray, const TraceOptions& o, double minSeconds) {
    Point p;
    p.tolerance = o.relTol;
    int calls = 0;
    double elapsed = 0;
    test::HardRayAnswer answer;
    while (elapsed < minSeconds || calls < 3) {
        elapsed += bench::seconds([&] { answer = ray.trace(o); });
        ++calls;
    }
    p.error = ray.error(answer);  // the reference is neither timed nor repeated
    p.microseconds = 1e6 * elapsed / calls;
    return p;
}

// A log-log panel per ray: x = log10 microseconds, y = log10 relative error.
void writeSvg(const std::string& path, const std::vector<test::HardRay>& rays,
              const std::vector<std::vector<std::vector<Point>>>& data) {
    const int cols = 5, panelW = 250, panelH = 210, margin = 46, top = 56;
    const int rows = static_cast<int>((rays.size() + cols - 1) / cols);
    const int width = cols * panelW + 20, height = top + rows * panelH + 10;
    double xMin = 1e300, xMax = -1e300;
    for (const auto& r : data)
        for (const auto& s : r)
            for (const Point& p : s) {
                xMin = std::min(xMin, std::log10(p.microseconds));
                xMax = std::max(xMax, std::log10(p.microseconds));
            }
    xMin = std::floor(xMin);
    xMax = std::ceil(xMax);
    const double yMin = -17, yMax = -3;
    std::ofstream out(path);
    out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
        << "\" font-family=\"sans-serif\" font-size=\"10\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    out << "<text x=\"10\" y=\"18\" font-size=\"13\">Work-precision: relative error against microseconds per ray ("
        << bench::machineName() << ", one core)</text>\n";
    for (std::size_t s = 0; s < kSteppers.size(); ++s)
        out << "<text x=\"" << 10 + 130 * s << "\" y=\"38\" fill=\"" << kColours[s] << "\" font-size=\"12\">&#9632; "
            << kSteppers[s] << "</text>\n";
    for (std::size_t r = 0; r < rays.size(); ++r) {
        const int x0 = 10 + static_cast<int>(r % cols) * panelW, y0 = top + static_cast<int>(r / cols) * panelH;
        const int w = panelW - margin - 8, h = panelH - 60;
        auto X = [&](double us) { return x0 + margin + w * (std::log10(us) - xMin) / (xMax - xMin); };
        auto Y = [&](double e) {
            const double l = std::clamp(std::log10(std::max(e, 1e-17)), yMin, yMax);
            return y0 + 18 + h * (yMax - l) / (yMax - yMin);
        };
        out << "<text x=\"" << x0 + 4 << "\" y=\"" << y0 + 10 << "\" font-size=\"9\">" << rays[r].name << "</text>\n";
        out << "<rect x=\"" << x0 + margin << "\" y=\"" << y0 + 18 << "\" width=\"" << w << "\" height=\"" << h
            << "\" fill=\"none\" stroke=\"#888\"/>\n";
        for (int e = static_cast<int>(yMin) + 1; e <= yMax; e += 3)
            out << "<text x=\"" << x0 + margin - 3 << "\" y=\"" << Y(std::pow(10.0, e)) + 3
                << "\" text-anchor=\"end\">1e" << e << "</text>\n";
        for (int d = static_cast<int>(xMin); d <= xMax; ++d)
            out << "<text x=\"" << X(std::pow(10.0, d)) << "\" y=\"" << y0 + 18 + h + 12
                << "\" text-anchor=\"middle\">1e" << d << "</text>\n";
        out << "<text x=\"" << x0 + margin + w / 2 << "\" y=\"" << y0 + 18 + h + 24
            << "\" text-anchor=\"middle\">us per ray</text>\n";
        for (std::size_t s = 0; s < kSteppers.size(); ++s) {
            out << "<polyline fill=\"none\" stroke=\"" << kColours[s] << "\" stroke-width=\"1.5\" points=\"";
            for (const Point& p : data[r][s])
                if (std::isfinite(p.error)) out << X(p.microseconds) << "," << Y(p.error) << " ";
            out << "\"/>\n";
            for (const Point& p : data[r][s])
                if (std::isfinite(p.error))
                    out << "<circle cx=\"" << X(p.microseconds) << "\" cy=\"" << Y(p.error) << "\" r=\"2.2\" fill=\""
                        << kColours[s] << "\"/>\n";
        }
    }
    out << "</svg>\n";
}

}  // namespace

int main(int argc, char** argv) {
    std::string svg;
    double minSeconds = 0.05;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--svg") && i + 1 < argc)
            svg = argv[++i];
        else if (!std::strcmp(argv[i], "--seconds") && i + 1 < argc)
            minSeconds = std::atof(argv[++i]);
        else {
            std::fprintf(stderr, "usage: bench_work_precision [--svg FILE] [--seconds S]\n");
            return 2;
        }
    }
    const std::vector<test::HardRay> rays = test::hardRays();
    std::printf(
        "Work-precision on the hard rays (%s, one core): relative error against the reference and "
        "microseconds per ray\n\n",
        bench::machineName().c_str());
    std::printf("| ray | stepper |");
    for (double t : kTolerances) std::printf(" tol %.0e |", t);
    std::printf("\n|---|---|");
    for (std::size_t i = 0; i < kTolerances.size(); ++i) std::printf("---|");
    std::printf("\n");
    std::vector<std::vector<std::vector<Point>>> data(rays.size());
    for (std::size_t r = 0; r < rays.size(); ++r) {
        for (const std::string& name : kSteppers) {
            std::vector<Point> line;
            std::printf("| %s | %s |", rays[r].name.c_str(), name.c_str());
            for (double tol : kTolerances) {
                line.push_back(measure(rays[r], test::hardRayOptions(parseStepper(name), tol), minSeconds));
                std::printf(" %.1e in %.0f us |", line.back().error, line.back().microseconds);
                std::fflush(stdout);
            }
            std::printf("\n");
            data[r].push_back(line);
        }
    }
    if (!svg.empty()) {
        writeSvg(svg, rays, data);
        std::printf("\nwrote %s\n", svg.c_str());
    }
    return 0;
}
