// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Reads back what the diagrams' SVG export holds, as a viewer would place it: text labels and
// markers (<use> of a symbol) in page pixels, after every enclosing group's transform, and the
// plot area (the clip rectangle). The axes' numeric tick labels give the map from page pixels
// back to data units, so a test finds data positions from the drawing alone.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace lc::test {

struct SvgAffine {  // page = (a x + c y + e, b x + d y + f)
    double a = 1, b = 0, c = 0, d = 1, e = 0, f = 0;
    SvgAffine then(const SvgAffine& inner) const {  // this applied after inner
        return {a * inner.a + c * inner.b, b * inner.a + d * inner.b,     a * inner.c + c * inner.d,
                b * inner.c + d * inner.d, a * inner.e + c * inner.f + e, b * inner.e + d * inner.f + f};
    }
    double x(double px, double py) const { return a * px + c * py + e; }
    double y(double px, double py) const { return b * px + d * py + f; }
};

struct SvgText {
    double x = 0, y = 0;
    std::string text;
};
struct SvgUse {  // centre of the marker
    double x = 0, y = 0;
    std::string symbol;
};
struct SvgImage {  // an embedded raster (<image>), its rectangle in page pixels
    double x = 0, y = 0, width = 0, height = 0;
};
struct SvgRect {
    double x = 0, y = 0, width = 0, height = 0;
    bool contains(double px, double py) const { return px >= x && px <= x + width && py >= y && py <= y + height; }
};

// Linear map from page pixels to data units along one axis, fitted to the tick labels.
struct SvgAxisMap {
    double scale = 0, offset = 0;  // value = scale * pixel + offset
    double pixelsPerUnit() const { return 1 / std::abs(scale); }
    double operator()(double pixel) const { return scale * pixel + offset; }
};

struct SvgDocument {
    std::vector<SvgText> texts;
    std::vector<SvgUse> uses;
    std::vector<SvgImage> images;
    SvgRect clip;  // the first clip rectangle: the chart's plot area (in <defs>, see DiagramChart::encode)
    double width = 0, height = 0;
};

namespace svg_detail {

inline std::string attribute(const std::string& tag, const std::string& name) {
    const std::string key = " " + name + "=\"";
    const std::size_t at = tag.find(key);
    if (at == std::string::npos) return "";
    const std::size_t from = at + key.size();
    return tag.substr(from, tag.find('"', from) - from);
}

inline double number(const std::string& tag, const std::string& name) {
    const std::string v = attribute(tag, name);
    return v.empty() ? 0.0 : std::stod(v);
}

inline std::vector<double> arguments(const std::string& text, std::size_t open) {
    std::vector<double> out;
    const std::size_t close = text.find(')', open);
    std::string list = text.substr(open + 1, close - open - 1);
    std::replace(list.begin(), list.end(), ',', ' ');
    const char* p = list.c_str();
    char* end = nullptr;
    for (double v = std::strtod(p, &end); end != p; v = std::strtod(p, &end)) {
        out.push_back(v);
        p = end;
    }
    return out;
}

// "matrix(a,b,c,d,e,f)", "translate(x,y)", "rotate(...)" (ignored: only axis titles rotate).
inline SvgAffine transform(const std::string& tag) {
    const std::string t = attribute(tag, "transform");
    SvgAffine m;
    if (const std::size_t at = t.find("matrix("); at != std::string::npos) {
        const auto v = arguments(t, at + 6);
        if (v.size() == 6) m = {v[0], v[1], v[2], v[3], v[4], v[5]};
    } else if (const std::size_t at2 = t.find("translate("); at2 != std::string::npos) {
        const auto v = arguments(t, at2 + 9);
        if (!v.empty()) m.e = v[0];
        if (v.size() > 1) m.f = v[1];
    }
    return m;
}

inline std::string trimmed(const std::string& s) {
    const std::size_t first = s.find_first_not_of(" \n\t\r");
    if (first == std::string::npos) return "";
    return s.substr(first, s.find_last_not_of(" \n\t\r") - first + 1);
}

// The five predefined XML entities, the only ones VTK's exporter writes.
inline std::string unescaped(std::string s) {
    const std::pair<const char*, const char*> entities[] = {
        {"&apos;", "'"}, {"&quot;", "\""}, {"&lt;", "<"}, {"&gt;", ">"}, {"&amp;", "&"}};
    for (const auto& [entity, character] : entities)
        for (std::size_t at = s.find(entity); at != std::string::npos; at = s.find(entity, at + 1))
            s.replace(at, std::string(entity).size(), character);
    return s;
}

inline bool isNumber(const std::string& s, double& value) {
    if (s.empty()) return false;
    char* end = nullptr;
    value = std::strtod(s.c_str(), &end);
    return end == s.c_str() + s.size();
}

}  // namespace svg_detail

inline SvgDocument parseSvg(const std::string& svg) {
    using namespace svg_detail;
    SvgDocument doc;
    std::vector<SvgAffine> groups{SvgAffine{}};
    bool haveClip = false;
    // Embedded images: their sizes by id (<defs>), and where each <use> puts one.
    std::map<std::string, std::pair<double, double>> imageSizes;
    struct Placement {
        std::string id;
        SvgAffine m;
        double x, y;
    };
    std::vector<Placement> placed;
    for (std::size_t at = svg.find('<'); at != std::string::npos; at = svg.find('<', at + 1)) {
        const std::size_t end = svg.find('>', at);
        if (end == std::string::npos) break;
        const std::string tag = svg.substr(at, end - at + 1);
        const bool selfClosing = tag.size() > 2 && tag[tag.size() - 2] == '/';
        auto is = [&](const char* name) {
            const std::string n = std::string("<") + name;
            return tag.compare(0, n.size(), n) == 0 && (tag[n.size()] == ' ' || tag[n.size()] == '>');
        };
        if (is("svg")) {
            doc.width = number(tag, "width");
            doc.height = number(tag, "height");
        } else if (is("g")) {
            if (!selfClosing) groups.push_back(groups.back().then(transform(tag)));
        } else if (tag.compare(0, 4, "</g>") == 0) {
            if (groups.size() > 1) groups.pop_back();
        } else if (is("rect") && !haveClip) {
            doc.clip = {number(tag, "x"), number(tag, "y"), number(tag, "width"), number(tag, "height")};
            haveClip = true;
        } else if (is("use")) {
            const double cx = number(tag, "x") + number(tag, "width") / 2;
            const double cy = number(tag, "y") + number(tag, "height") / 2;
            const SvgAffine& m = groups.back();
            std::string symbol = attribute(tag, "xlink:href");
            if (!symbol.empty() && symbol[0] == '#') symbol.erase(0, 1);
            doc.uses.push_back({m.x(cx, cy), m.y(cx, cy), symbol});
            placed.push_back({symbol, m.then(transform(tag)), number(tag, "x"), number(tag, "y")});
        } else if (is("image")) {  // a definition: placed by <use> below
            imageSizes[attribute(tag, "id")] = {number(tag, "width"), number(tag, "height")};
        } else if (is("text")) {
            const SvgAffine m = groups.back().then(transform(tag));
            const double x = number(tag, "x"), y = number(tag, "y");
            const std::size_t close = svg.find("</text>", end);
            doc.texts.push_back({m.x(x, y), m.y(x, y), unescaped(trimmed(svg.substr(end + 1, close - end - 1)))});
        }
    }
    for (const Placement& p : placed) {
        const auto size = imageSizes.find(p.id);
        if (size == imageSizes.end()) continue;
        const double x1 = p.x + size->second.first, y1 = p.y + size->second.second;
        const double px0 = p.m.x(p.x, p.y), py0 = p.m.y(p.x, p.y), px1 = p.m.x(x1, y1), py1 = p.m.y(x1, y1);
        doc.images.push_back({std::min(px0, px1), std::min(py0, py1), std::abs(px1 - px0), std::abs(py1 - py0)});
    }
    return doc;
}

// The horizontal (x = true) or vertical axis's map, from its numeric tick labels: those that
// share one page row (x axis) or column (y axis) with at least two others. `valueOf` turns a
// label into the axis's data value (a figure's pinhole axes: degrees at their tangents).
inline SvgAxisMap axisMap(const SvgDocument& doc, bool horizontal, double (*valueOf)(double) = nullptr) {
    std::map<long, std::vector<std::pair<double, double>>> lines;  // row or column -> (pixel, value)
    for (const auto& t : doc.texts) {
        double value = 0;
        if (!svg_detail::isNumber(t.text, value)) continue;
        if (valueOf) value = valueOf(value);
        const long line = std::lround(horizontal ? t.y : t.x);
        lines[line].emplace_back(horizontal ? t.x : t.y, value);
    }
    const std::vector<std::pair<double, double>>* ticks = nullptr;
    for (const auto& [line, points] : lines)
        if (points.size() >= 3 && (!ticks || points.size() > ticks->size())) ticks = &points;
    if (!ticks) throw std::runtime_error("no tick labels for the " + std::string(horizontal ? "x" : "y") + " axis");
    // Least squares: the labels' positions are rounded to whole pixels.
    double sp = 0, sv = 0, spp = 0, spv = 0;
    const double n = static_cast<double>(ticks->size());
    for (auto [p, v] : *ticks) sp += p, sv += v, spp += p * p, spv += p * v;
    SvgAxisMap map;
    map.scale = (n * spv - sp * sv) / (n * spp - sp * sp);
    map.offset = (sv - map.scale * sp) / n;
    return map;
}

}  // namespace lc::test
