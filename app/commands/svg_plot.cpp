// SPDX-License-Identifier: BSD-3-Clause
#include "app/commands/svg_plot.hpp"

#include "app/commands/xml_text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

namespace lc::cli {
namespace {

constexpr double kWidth = 640, kPanel = 200, kLeft = 70, kRight = 20, kTop = 30, kBottom = 40;

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}

// [lo, hi] widened to round numbers, with a round tick step (1, 2 or 5 times a power of ten).
struct Axis {
    double lo, hi, step;
    Axis(double minimum, double maximum) {
        // Equal up to rounding: one value, drawn in the middle of a padded axis.
        if (!(maximum - minimum > 1e-9 * std::max(std::abs(minimum), std::abs(maximum)))) {
            const double pad = minimum == 0 ? 1 : 0.1 * std::abs(minimum);
            minimum -= pad;
            maximum += pad;
        }
        const double raw = (maximum - minimum) / 5, power = std::pow(10, std::floor(std::log10(raw)));
        step = raw / power < 1.5 ? power : raw / power < 3.5 ? 2 * power : raw / power < 7.5 ? 5 * power : 10 * power;
        lo = std::floor(minimum / step) * step;
        hi = std::ceil(maximum / step) * step;
    }
    int ticks() const { return static_cast<int>(std::lround((hi - lo) / step)); }
};

std::pair<double, double> finiteRange(const std::vector<double>& v) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (double x : v)
        if (std::isfinite(x)) lo = std::min(lo, x), hi = std::max(hi, x);
    return {lo, hi};
}

}  // namespace

namespace {

constexpr double kSkyPanel = 420;

// The sky panel: rings every 30 degrees from forward, the curves in the azimuthal equidistant
// projection, a legend of the curves' labels.
void drawSky(std::ostringstream& svg, const std::string& xName, const std::vector<SkyCurve>& curves) {
    double reach = 0;
    for (const SkyCurve& c : curves)
        for (double p : c.polarDegrees)
            if (std::isfinite(p)) reach = std::max(reach, p);
    const double outer = std::min(180.0, std::max(30.0, std::ceil(reach / 30) * 30));
    const double cx = kLeft + kSkyPanel / 2, cy = kTop + kSkyPanel / 2, scale = kSkyPanel / 2 / outer;
    svg << "<text x=\"" << kLeft << "\" y=\"" << kTop - 10
        << "\" font-weight=\"bold\">shadow outline (angle from forward, right to the right, up up)</text>\n";
    svg << "<text x=\"" << kLeft + kSkyPanel + 10 << "\" y=\"" << kTop + 14 << "\">" << xmlEscaped(xName)
        << "</text>\n";
    for (double ring = 30; ring <= outer + 1e-9; ring += 30)
        svg << "<circle cx=\"" << cx << "\" cy=\"" << cy << "\" r=\"" << number(ring * scale)
            << "\" fill=\"none\" stroke=\"#bbbbbb\"/>\n<text x=\"" << number(cx + ring * scale + 2) << "\" y=\""
            << cy - 2 << "\" fill=\"#888888\">" << number(ring) << "&#176;</text>\n";
    for (std::size_t k = 0; k < curves.size(); ++k) {
        const double t = curves.size() > 1 ? double(k) / double(curves.size() - 1) : 0;
        char colour[16];
        std::snprintf(colour, sizeof colour, "#%02x40%02x", int(std::lround(40 + 200 * t)),
                      int(std::lround(220 - 180 * t)));
        std::string points;
        const SkyCurve& c = curves[k];
        for (std::size_t i = 0; i < c.polarDegrees.size(); ++i) {
            const double p = c.polarDegrees[i], a = c.azimuthDegrees[i] * 3.14159265358979323846 / 180;
            if (!std::isfinite(p) || !std::isfinite(a)) continue;
            points += number(cx + p * scale * std::cos(a)) + "," + number(cy - p * scale * std::sin(a)) + " ";
        }
        if (!points.empty())
            svg << "<polygon fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"1.5\" points=\"" << points
                << "\"/>\n";
        svg << "<text x=\"" << kLeft + kSkyPanel + 10 << "\" y=\"" << kTop + 14 * (k + 2) << "\" fill=\"" << colour
            << "\">" << xmlEscaped(c.label) << "</text>\n";
    }
}

}  // namespace

std::string svgPlots(const std::string& xName, const std::vector<double>& x, const std::vector<PlotColumn>& columns,
                     const std::vector<SkyCurve>& curves) {
    const double skyHeight = curves.empty() ? 0 : kSkyPanel + kTop + kBottom;
    const double height = skyHeight + columns.size() * (kPanel + kTop + kBottom);
    std::ostringstream svg;
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kWidth << "\" height=\"" << height
        << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    if (!curves.empty()) drawSky(svg, xName, curves);
    const auto [x0, x1] = finiteRange(x);
    const Axis ax(x0, x1);
    const double plotWidth = kWidth - kLeft - kRight;
    for (std::size_t c = 0; c < columns.size(); ++c) {
        const double top = skyHeight + c * (kPanel + kTop + kBottom) + kTop;
        const auto [y0, y1] = finiteRange(columns[c].values);
        const Axis ay(std::isfinite(y0) ? y0 : 0, std::isfinite(y1) ? y1 : 1);
        auto px = [&](double v) { return kLeft + (v - ax.lo) / (ax.hi - ax.lo) * plotWidth; };
        auto py = [&](double v) { return top + kPanel - (v - ay.lo) / (ay.hi - ay.lo) * kPanel; };
        svg << "<text x=\"" << kLeft << "\" y=\"" << top - 10 << "\" font-weight=\"bold\">"
            << xmlEscaped(columns[c].name) << "</text>\n";
        svg << "<rect x=\"" << kLeft << "\" y=\"" << top << "\" width=\"" << plotWidth << "\" height=\"" << kPanel
            << "\" fill=\"none\" stroke=\"black\"/>\n";
        for (int k = 0; k <= ax.ticks(); ++k) {
            const double t = ax.lo + k * ax.step;
            svg << "<text x=\"" << px(t) << "\" y=\"" << top + kPanel + 15 << "\" text-anchor=\"middle\">"
                << number(std::abs(t) < 1e-12 * ax.step ? 0 : t) << "</text>\n";
        }
        for (int k = 0; k <= ay.ticks(); ++k) {
            const double t = ay.lo + k * ay.step;
            svg << "<text x=\"" << kLeft - 5 << "\" y=\"" << py(t) + 4 << "\" text-anchor=\"end\">"
                << number(std::abs(t) < 1e-12 * ay.step ? 0 : t) << "</text>\n";
        }
        svg << "<text x=\"" << kLeft + plotWidth / 2 << "\" y=\"" << top + kPanel + 32 << "\" text-anchor=\"middle\">"
            << xmlEscaped(xName) << "</text>\n";
        // One polyline per run of finite values; points marked so single values show.
        std::string run;
        auto flush = [&] {
            if (!run.empty())
                svg << "<polyline fill=\"none\" stroke=\"#1f5fa8\" stroke-width=\"1.5\" points=\"" << run << "\"/>\n";
            run.clear();
        };
        for (std::size_t k = 0; k < x.size() && k < columns[c].values.size(); ++k) {
            const double v = columns[c].values[k];
            if (!std::isfinite(v) || !std::isfinite(x[k])) {
                flush();
                continue;
            }
            run += number(px(x[k])) + "," + number(py(v)) + " ";
            svg << "<circle cx=\"" << number(px(x[k])) << "\" cy=\"" << number(py(v))
                << "\" r=\"2.5\" fill=\"#1f5fa8\"/>\n";
        }
        flush();
    }
    svg << "</svg>\n";
    return svg.str();
}

}  // namespace lc::cli
