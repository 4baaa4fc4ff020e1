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

std::string svgPlots(const std::string& xName, const std::vector<double>& x, const std::vector<PlotColumn>& columns) {
    const double height = columns.size() * (kPanel + kTop + kBottom);
    std::ostringstream svg;
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kWidth << "\" height=\"" << height
        << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    const auto [x0, x1] = finiteRange(x);
    const Axis ax(x0, x1);
    const double plotWidth = kWidth - kLeft - kRight;
    for (std::size_t c = 0; c < columns.size(); ++c) {
        const double top = c * (kPanel + kTop + kBottom) + kTop;
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
