// SPDX-License-Identifier: BSD-3-Clause
// Lightcone beside GYOTO 1.4.4 on the same rays (GYOTO optional: its half is skipped, with a
// message, where /usr/bin/python3 cannot import gyoto). Three tables:
//  1. Schwarzschild deflection error against the exact integral versus us/ray, b = 6, 10, 20
//     and a photon-sphere grazer, both codes starting and ending at D = 1e6 M;
//  2. the cost of a ray against the distance it starts from (1e3, 1e6, 1e10 M);
//  3. GYOTO's Kerr-Schild example, geodesics only, 128 x 128 on 2 threads: rays/s and the
//     shadow masks, pixel by pixel, at a = 0 and 0.9, and the ratio at equal or better error.
// Usage, from the repository root: ./build/bench/bench_gyoto [--quick]
#include "bench_common.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/render/render.hpp"
#include "core/spacetime/scattering.hpp"
#include "tests/common/geodesic_oracles.hpp"

#include <omp.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

using namespace lc;

namespace {

constexpr double kGrazerOffset = 1e-3;  // b = 3 sqrt(3) (1 + 1e-3): winds once (alpha > 2 pi)
constexpr const char* kPython = "/usr/bin/python3";
constexpr const char* kGyotoDir = "bench/gyoto";
constexpr double kGyotoExampleTol = 1e-6;  // GYOTO's Kerr-Schild example (RKF78, 1e-6)

// Exact Schwarzschild deflection (M = 1) of a ray from and to infinity: the quadrature of
// tests/common/geodesic_oracles.hpp, written independently of the tracer.
double exactDeflection(double b) { return test::kerrEquatorialDeflection(0, b).alpha; }

double grazerImpact() { return 3 * std::sqrt(3.0) * (1 + kGrazerOffset); }

// Mean us of one call over a batch of at least `minSeconds`, fastest of three batches.
template <class F>
double microseconds(F&& one, double minSeconds) {
    double best = 1e300;
    for (int batch = 0; batch < 3; ++batch) {
        int calls = 0;
        const double s = bench::seconds([&] {
            const auto t0 = std::chrono::steady_clock::now();
            do {
                one();
                ++calls;
            } while (calls < 3 ||
                     std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() < minSeconds);
        });
        best = std::min(best, 1e6 * s / calls);
    }
    return best;
}

// One JSON value of a flat object printed by the GYOTO scripts (numbers and strings only).
std::string jsonField(const std::string& line, const std::string& key) {
    const std::string tag = "\"" + key + "\": ";
    const auto at = line.find(tag);
    if (at == std::string::npos) return "";
    auto begin = at + tag.size();
    if (line[begin] == '"') return line.substr(begin + 1, line.find('"', begin + 1) - begin - 1);
    const auto end = line.find_first_of(",}", begin);
    return line.substr(begin, end - begin);
}
double jsonNumber(const std::string& line, const std::string& key) {
    const std::string v = jsonField(line, key);
    return v.empty() || v == "null" || v == "NaN" ? NAN : std::stod(v);
}

bool gyotoAvailable() {
    const std::string cmd = std::string(kPython) + " -c 'import gyoto.core, gyoto.std' > /dev/null 2>&1";
    return std::system(cmd.c_str()) == 0;
}

std::vector<std::string> runLines(const std::string& cmd) {
    std::vector<std::string> lines;
    FILE* pipe = popen(cmd.c_str(), "r");
    if (!pipe) return lines;
    char buf[8192];
    std::string line;
    while (fgets(buf, sizeof buf, pipe)) {
        line += buf;
        if (!line.empty() && line.back() == '\n') {
            line.pop_back();
            if (!line.empty() && line[0] == '{') lines.push_back(line);
            line.clear();
        }
    }
    pclose(pipe);
    return lines;
}

struct DeflectionRow {
    std::string code, stepper;
    double tolerance = 0, distance = 0;
    std::map<std::string, double> error, steps, us;  // by b's label
};

const std::vector<std::pair<std::string, double>>& impacts() {
    static const std::vector<std::pair<std::string, double>> v{
        {"6", 6.0}, {"10", 10.0}, {"20", 20.0}, {"grazer", grazerImpact()}};
    return v;
}

// A Lightcone setting's name in the tables: the stepper, marked where the constants of motion are
// not held (TraceOptions::holdConstants, the tracer's default since 2026-12-08).
std::string settingLabel(const std::string& stepper, bool hold) { return hold ? stepper : stepper + " (not held)"; }

DeflectionRow lightconeDeflection(const std::string& stepper, bool hold, double tol, double distance,
                                  double minSeconds) {
    const Schwarzschild bh(1.0);
    DeflectionRow row{"Lightcone", settingLabel(stepper, hold), tol, distance, {}, {}, {}};
    TraceOptions o;
    o.stepper = parseStepper(stepper);
    o.holdConstants = hold;
    o.absTol = o.relTol = tol;
    o.initialStep = 1;
    o.escapeRadius = distance;  // end where it started, as GYOTO's rays do
    o.escapeAngle = 4;          // the turning is measured along the whole ray, not extrapolated
    for (const auto& [label, b] : impacts()) {
        const PhasePoint start = impactParameterRay(bh, b, distance);
        DeflectionResult d = measureDeflection(bh, start, o);
        row.error[label] = d.trace.reason == StopReason::Escaped ? std::abs(d.deflection - exactDeflection(b)) : NAN;
        row.steps[label] = static_cast<double>(d.trace.steps + d.trace.rejected);
        row.us[label] = microseconds([&] { d = measureDeflection(bh, start, o); }, minSeconds);
    }
    return row;
}

std::vector<DeflectionRow> gyotoDeflection(const std::vector<double>& tolerances, double distance, double minSeconds,
                                           const std::vector<std::string>& integrators) {
    std::ostringstream cmd;
    cmd << kPython << " " << kGyotoDir << "/gyoto_deflection.py --b 6 10 20 grazer --distance " << distance
        << " --min-seconds " << minSeconds << " --repeat 3 --tol";
    for (double t : tolerances) cmd << " " << t;
    cmd << " --integrators";
    for (const auto& i : integrators) cmd << " " << i;
    cmd << " 2>/dev/null";
    std::map<std::pair<std::string, double>, DeflectionRow> rows;
    for (const std::string& line : runLines(cmd.str())) {
        const std::string integrator = jsonField(line, "integrator");
        const double tol = jsonNumber(line, "tolerance");
        auto& row = rows[{integrator, tol}];
        row.code = "GYOTO";
        row.stepper = integrator;
        row.tolerance = tol;
        row.distance = distance;
        std::string label = jsonField(line, "b");
        if (std::abs(std::stod(label) - grazerImpact()) < 1e-9) label = "grazer";
        if (label.find('.') != std::string::npos) label = label.substr(0, label.find('.'));
        const double err = jsonNumber(line, "error");
        row.error[label] = std::abs(err);
        row.steps[label] = jsonNumber(line, "steps");
        row.us[label] = jsonNumber(line, "us_per_ray");
    }
    std::vector<DeflectionRow> out;
    for (auto& [key, row] : rows) out.push_back(row);
    return out;
}

double worst(const std::map<std::string, double>& m) {
    double w = 0;
    for (const auto& [k, v] : m) w = std::isfinite(v) ? std::max(w, v) : INFINITY;
    return w;
}
double mean(const std::map<std::string, double>& m) {
    double s = 0;
    for (const auto& [k, v] : m) s += v;
    return m.empty() ? 0 : s / m.size();
}

void printDeflection(const DeflectionRow& r) {
    std::printf("| %s | %s | %.0e |", r.code.c_str(), r.stepper.c_str(), r.tolerance);
    for (const auto& [label, b] : impacts()) {
        (void)b;
        const double e = r.error.count(label) ? r.error.at(label) : NAN;
        std::printf(std::isfinite(e) ? " %.1e |" : " lost |", e);
    }
    std::printf(" %.0f | %.1f |\n", mean(r.steps), mean(r.us));
}

// GYOTO's Kerr-Schild example seen by Lightcone: the static observer at (0, -D, 0), looking
// along +y with the spin axis up, a square 150 micro-arcsecond field, no objects.
Scene gyotoExampleScene(double spin, int n, const std::string& stepper, bool hold, double tol, double escapeAngle) {
    constexpr double kDistance = 4.1793e10;  // 8 kpc in units of G 4e6 Msun / c^2 (bench/gyoto/README.md)
    constexpr double kFovDeg = 150e-6 / 3600;
    Scene s;
    s.spacetime = std::make_shared<KerrNewman>(1.0, spin, 0.0);
    s.observer = Vec4(0, 0, -kDistance, 0);
    s.camera.width = s.camera.height = n;
    s.camera.fovXDeg = s.camera.fovYDeg = kFovDeg;
    s.camera.forward = Vec3(0, 1, 0);
    s.camera.up = Vec3(0, 0, 1);
    s.settings.method = RenderSettings::Method::Numeric;
    s.settings.threads = 2;
    s.settings.trace.stepper = parseStepper(stepper);
    s.settings.trace.absTol = s.settings.trace.relTol = tol;
    s.settings.trace.escapeAngle = escapeAngle;
    s.settings.trace.holdConstants = hold;
    return s;
}

std::vector<int> readMask(const std::string& path, int n) {
    std::ifstream in(path);
    std::string magic, line;
    std::vector<int> mask;
    if (!(in >> magic) || magic != "P2") return mask;
    std::getline(in, line);
    while (in.peek() == '#') std::getline(in, line);
    int w = 0, h = 0, maxval = 0;
    in >> w >> h >> maxval;
    if (w != n || h != n) return mask;
    mask.resize(static_cast<std::size_t>(n) * n);
    for (int& v : mask) in >> v;
    return mask;
}

// The quadrature oracle against docs/PHYSICS.md section 7; exits if it is off.
void checkOracle() {
    // The oracle checks itself against docs/PHYSICS.md section 7.
    const std::vector<std::pair<double, double>> reference{
        {20, 0.2361359953884699}, {10, 0.5903957876058273}, {6, 1.719388310230169}};
    for (const auto& [b, alpha] : reference)
        if (std::abs(exactDeflection(b) - alpha) > 1e-13) {
            std::fprintf(stderr, "exact deflection quadrature is off at b = %g\n", b);
            std::exit(1);
        }
}

// Table 1 (Lightcone's rows, then GYOTO's), kept for the ratio at equal error.
struct DeflectionTables {
    std::vector<DeflectionRow> lightcone, gyoto;
};

DeflectionTables printDeflectionTable(bool gyoto, double minSeconds) {
    const std::vector<double> tolerances{1e-6, 1e-8, 1e-10, 1e-12};
    // dopri87 keeps its accuracy to looser tolerances (its error estimate is of order 7).
    const std::map<std::string, std::vector<double>> lightconeTolerances{
        {"dopri5", {1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-12}},
        {"dopri87", {1e-4, 3e-5, 1e-5, 1e-6, 1e-8, 1e-10, 1e-12}},
        {"cash_karp54", {1e-6, 1e-8, 1e-10, 1e-12}}};
    const double D = 1e6;
    std::printf("## Schwarzschild deflection: |error| against the exact integral, from and back to %.0e M\n\n", D);
    std::printf(
        "Grazer: b = 3√3 (1 + %.0e), exact α = %.13f. Both codes measure the turning of the spatial\n"
        "momentum along the ray; ending at finite D leaves O(M b / D²) ≈ 1e-11 untraced. steps: accepted +\n"
        "rejected (GYOTO: accepted only), mean over the four rays; µs: per ray, one thread, mean over the four.\n\n",
        kGrazerOffset, exactDeflection(grazerImpact()));
    std::printf("| code | stepper | tolerance | b = 6 | b = 10 | b = 20 | grazer | steps/ray | µs/ray |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|\n");
    DeflectionTables rows;
    for (const std::string stepper : {"dopri5", "dopri87", "cash_karp54"})
        for (bool hold : {true, false})
            for (double tol : lightconeTolerances.at(stepper)) {
                rows.lightcone.push_back(lightconeDeflection(stepper, hold, tol, D, minSeconds));
                printDeflection(rows.lightcone.back());
            }
    if (gyoto) {
        rows.gyoto = gyotoDeflection(tolerances, D, minSeconds, {"runge_kutta_fehlberg78", "runge_kutta_dopri5"});
        for (const auto& r : rows.gyoto) printDeflection(r);
    }
    return rows;
}

// Table 2: steps and time of one ray against the distance it starts from.
void printCostTable(bool gyoto, double minSeconds) {
    std::printf("\n## Cost against the starting distance (b = 10, back out to the same distance)\n\n");
    std::printf("| code | stepper | tolerance | D = 1e3: steps | µs | D = 1e6: steps | µs | D = 1e10: steps | µs |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|\n");
    for (const std::string stepper : {"dopri5", "dopri87"})
        for (double tol : {1e-6, 1e-10}) {
            std::printf("| Lightcone | %s | %.0e |", stepper.c_str(), tol);
            for (double d : {1e3, 1e6, 1e10}) {
                const Schwarzschild bh(1.0);
                TraceOptions o;
                o.stepper = parseStepper(stepper);
                o.absTol = o.relTol = tol;
                o.escapeRadius = d;
                o.escapeAngle = 4;
                const PhasePoint start = impactParameterRay(bh, 10, d);
                DeflectionResult r = measureDeflection(bh, start, o);
                const double us = microseconds([&] { r = measureDeflection(bh, start, o); }, minSeconds);
                std::printf(" %zu | %.1f |", r.trace.steps + r.trace.rejected, us);
            }
            std::printf("\n");
        }
    if (gyoto)
        for (double tol : {1e-6, 1e-10}) {
            std::printf("| GYOTO | runge_kutta_dopri5 | %.0e |", tol);
            for (double d : {1e3, 1e6, 1e10}) {
                std::ostringstream cmd;
                cmd << kPython << " " << kGyotoDir << "/gyoto_deflection.py --b 10 --distance " << d << " --tol " << tol
                    << " --integrators runge_kutta_dopri5 --min-seconds " << minSeconds << " --repeat 3 2>/dev/null";
                const auto lines = runLines(cmd.str());
                if (lines.empty())
                    std::printf(" - | - |");
                else
                    std::printf(" %.0f | %.1f |", jsonNumber(lines[0], "steps"), jsonNumber(lines[0], "us_per_ray"));
            }
            std::printf("\n");
        }
}

// Table 3, GYOTO's example image, and its rates: GYOTO's by (spin, tolerance), Lightcone's seconds per ray summed over
// a = 0, 0.9.
struct ImageRates {
    std::map<std::pair<double, double>, double> gyoto;
    std::map<std::pair<std::string, double>, double> lightconeSeconds;
};

ImageRates printImageTable(bool gyoto, bool quick, int n) {
    std::printf("\n## GYOTO's Kerr–Schild example, geodesics only: %d × %d, 2 threads\n\n", n, n);
    std::printf(
        "Lightcone: escape known once outgoing beyond the capture radius (escape angle π, no sky needed, as\n"
        "GYOTO stops rays outside its RMax); the \"sky\" rows also settle the escape direction to 1/100 of a\n"
        "pixel (5.7e-14 rad). GYOTO: bench/gyoto/gyoto_shadow.py, RMax 10 M.\n\n");
    std::printf("| code | spin | stepper | tolerance | rays/s | steps/ray | shadow pixels | differ from GYOTO |\n");
    std::printf("|---|---|---|---|---|---|---|---|\n");
    ImageRates rates;
    std::map<double, std::vector<int>> gyotoMask;
    if (gyoto) {
        std::ostringstream cmd;
        cmd << kPython << " " << kGyotoDir << "/gyoto_shadow.py --spin 0 0.9 --resolution " << n << " --tol "
            << kGyotoExampleTol << " 1e-8 --threads 2 --repeat " << (quick ? 1 : 3) << " 2>/dev/null";
        for (const std::string& line : runLines(cmd.str())) {
            if (line.find("\"spin\"") == std::string::npos) continue;
            const double spin = jsonNumber(line, "spin"), tol = jsonNumber(line, "tolerance");
            rates.gyoto[{spin, tol}] = jsonNumber(line, "rays_per_second");
            if (tol == kGyotoExampleTol) gyotoMask[spin] = readMask(jsonField(line, "mask"), n);
            std::printf("| GYOTO | %g | runge_kutta_fehlberg78 | %.0e | %.0f | | %.0f | |\n", spin, tol,
                        jsonNumber(line, "rays_per_second"), jsonNumber(line, "shadow_pixels"));
        }
    }
    struct Choice {
        std::string stepper;
        bool hold;
        double tol;
        double escapeAngle;
        const char* label;
    };
    std::vector<Choice> choices;
    for (bool hold : {true, false}) {
        for (double tol : {1e-6, 1e-7, 1e-8, 1e-9, 1e-10}) choices.push_back({"dopri5", hold, tol, 4, ""});
        for (double tol : {1e-4, 3e-5, 1e-5, 1e-6, 1e-8}) choices.push_back({"dopri87", hold, tol, 4, ""});
    }
    choices.push_back({"dopri5", true, 1e-8, 0, " (sky)"});
    for (double spin : {0.0, 0.9})
        for (const Choice& c : choices) {
            const Scene scene = gyotoExampleScene(spin, n, c.stepper, c.hold, c.tol, c.escapeAngle);
            RenderResult best;
            for (int rep = 0; rep < (quick ? 1 : 3); ++rep) {
                RenderResult r = renderNumeric(scene);
                if (rep == 0 || r.stats.seconds < best.stats.seconds) best = std::move(r);
            }
            int shadow = 0, differ = 0;
            const auto& mask = gyotoMask[spin];
            for (std::size_t k = 0; k < best.pixels.size(); ++k) {
                const int captured = best.pixels[k].kind == PixelRecord::Horizon;
                shadow += captured;
                if (!mask.empty()) differ += captured != mask[k];
            }
            const double rate = n * n / best.stats.seconds;
            const std::string setting = settingLabel(c.stepper, c.hold);
            if (c.escapeAngle == 4) rates.lightconeSeconds[{setting, c.tol}] += 1 / rate;
            std::printf("| Lightcone | %g | %s%s | %.0e | %.0f | %.1f | %d | %s |\n", spin, setting.c_str(), c.label,
                        c.tol, rate, best.stats.meanSteps, shadow, mask.empty() ? "-" : std::to_string(differ).c_str());
        }
    return rates;
}

// GYOTO at a tolerance against every Lightcone setting, marked where its worst deflection error
// (all four rays) is larger than GYOTO's.
void printEqualAccuracyRatio(const DeflectionTables& rows, ImageRates rates) {
    std::printf("\n## Ratio at equal or better deflection error\n");
    for (double tol : {kGyotoExampleTol, 1e-8}) {
        double gyotoWorst = INFINITY;
        for (const auto& r : rows.gyoto)
            if (r.stepper == "runge_kutta_fehlberg78" && r.tolerance == tol) gyotoWorst = worst(r.error);
        const double gyotoMean = 2 / (1 / rates.gyoto[{0.0, tol}] + 1 / rates.gyoto[{0.9, tol}]);
        std::printf(
            "\nGYOTO (RKF78, tolerance %.0e): worst deflection error %.1e, %.0f rays/s (harmonic mean of a = 0, "
            "0.9).\n\n",
            tol, gyotoWorst, gyotoMean);
        std::printf(
            "| Lightcone stepper | tolerance | worst deflection error | rays/s | × GYOTO "
            "|\n|---|---|---|---|---|\n");
        for (const auto& r : rows.lightcone) {
            if (!rates.lightconeSeconds.count({r.stepper, r.tolerance})) continue;
            const double w = worst(r.error), rate = 2 / rates.lightconeSeconds[{r.stepper, r.tolerance}];
            std::printf("| %s | %.0e | %.1e%s | %.0f | %.1f |\n", r.stepper.c_str(), r.tolerance, w,
                        w <= gyotoWorst ? "" : " (less accurate)", rate, rate / gyotoMean);
        }
    }
}

}  // namespace

int main(int argc, char** argv) {
    const bool quick = argc > 1 && std::string(argv[1]) == "--quick";
    const double minSeconds = quick ? 0.05 : 0.3;
    const bool gyoto = gyotoAvailable();
    std::printf("# Lightcone beside GYOTO\n\nMachine: %s, %d hardware threads. GYOTO: %s.\n\n",
                bench::machineName().c_str(), omp_get_num_procs(),
                gyoto ? "1.4.4 through python3-gyoto (bench/gyoto)"
                      : "not installed (apt install gyoto-bin python3-gyoto); its rows are skipped");
    checkOracle();
    const DeflectionTables rows = printDeflectionTable(gyoto, minSeconds);
    printCostTable(gyoto, minSeconds);
    const ImageRates rates = printImageTable(gyoto, quick, 128);
    if (gyoto && !rows.gyoto.empty()) printEqualAccuracyRatio(rows, rates);
    return 0;
}
