// SPDX-License-Identifier: BSD-3-Clause
// Lightcone's thin accretion disk beside GYOTO 1.4.4's Page-Thorne example
// (example-page-thorne-disk-BL.xml, rendered by bench/gyoto/gyoto_disk.py): the same hole, the same
// static observer at Boyer-Lindquist r = 100 M, theta = 1.22 rad, the same 18-degree azimuth-elevation
// screen (our panorama projection is GYOTO's EquatorialAngles), pixel by pixel.
//  - GYOTO's User4 is g^4 F / pi (Mdot = M = 1): ours is intensity * F_max / pi, absolute, so the
//    images are compared both as they are and after normalising the total flux;
//  - g and the emission radius per pixel are compared too (GYOTO's --extras maps);
//  - seconds per image at several tolerances, against our own render at 1e-12 as the reference.
// GYOTO's half needs /usr/bin/python3 with python3-gyoto; without it the saved images in
// bench/gyoto/out are used, or the comparison is skipped with a message.
// Usage, from the repository root: ./build/bench/bench_gyoto_disk [N=128] [--no-gyoto-run]
#include "bench_common.hpp"
#include "core/accretion/thin_disk.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/render/render.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

using namespace lc;

namespace {

constexpr double kObserverR = 100, kObserverTheta = 1.22, kFovDeg = 18, kOuterRadius = 1e4;

std::string fileStem(double spin, int n) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "bench/gyoto/out/gyoto_disk_a%g_n%d", spin, n);
    return buf;
}

std::vector<double> readDoubles(const std::string& path, std::size_t count) {
    std::ifstream in(path, std::ios::binary);
    std::vector<double> v(count);
    in.read(reinterpret_cast<char*>(v.data()), static_cast<std::streamsize>(count * sizeof(double)));
    if (!in) return {};
    return v;
}

double jsonNumber(const std::string& path, const std::string& key) {
    std::ifstream in(path);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::size_t k = text.find("\"" + key + "\"");
    if (k == std::string::npos) return NAN;
    return std::atof(text.c_str() + text.find(':', k) + 1);
}

// The spatial part of g^-1 df at x (f a function of the chart's x, y, z), by central
// differences: the Boyer-Lindquist directions e_r and e_theta are the gradients of r and theta
// (g^{r mu} and g^{theta mu} vanish off the diagonal), whatever the chart.
template <class F>
Vec3 gradient(const Spacetime& st, const Vec4& x, F&& f) {
    Vec4 df = Vec4::Zero();
    for (int i = 1; i < 4; ++i) {
        const double h = 1e-6 * std::max(1.0, std::abs(x(i)));
        Vec4 a = x, b = x;
        a(i) += h;
        b(i) -= h;
        df(i) = (f(a) - f(b)) / (2 * h);
    }
    return (st.inverseMetric(x) * df).tail<3>();
}

Scene gyotoScene(double spin, int n, double tolerance) {
    Scene s;
    s.source = "GYOTO Page-Thorne example";
    auto kn = std::make_shared<KerrNewman>(1.0, spin, 0.0);
    s.spacetime = kn;
    // Kerr-Schild x^2 + y^2 = (r^2 + a^2) sin^2 theta, z = r cos theta; any azimuth (axisymmetry).
    s.observer = Vec4(0, std::sqrt(kObserverR * kObserverR + spin * spin) * std::sin(kObserverTheta), 0,
                      kObserverR * std::cos(kObserverTheta));
    auto r = [&](const Vec4& x) { return kn->radius(x(1), x(2), x(3)); };
    auto theta = [&](const Vec4& x) { return std::acos(x(3) / r(x)); };
    s.camera.projection = Camera::Projection::Panorama;
    s.camera.width = s.camera.height = n;
    s.camera.fovXDeg = s.camera.fovYDeg = kFovDeg;
    // g^-1 dr points to decreasing r (signature +,-,-,-): it is -e_r, towards the hole; likewise
    // g^-1 dtheta is -e_theta, the spin axis up.
    s.camera.forward = gradient(*kn, s.observer, r);
    s.camera.up = gradient(*kn, s.observer, theta);
    DiskObject d;
    d.name = "disk";
    d.emission = DiskObject::Emission::Flux;
    d.model = std::make_shared<ThinDiskModel>(s.spacetime, 0, kOuterRadius, true);
    s.disks.push_back(d);
    s.settings.trace.absTol = s.settings.trace.relTol = tolerance;
    s.settings.threads = 2;
    s.settings.progress = false;
    return s;
}

struct Images {
    std::vector<double> intensity, redshift, radius;  // 0 where no disk
};

Images ours(const Scene& s, const RenderResult& r) {
    const ThinDiskModel& m = *s.disks[0].model;
    Images out;
    for (const PixelRecord& p : r.pixels) {
        const bool disk = p.kind == PixelRecord::Disk;
        out.intensity.push_back(disk ? p.intensity * m.maxFlux() / kPi : 0);
        out.redshift.push_back(disk ? p.frequencyRatio : 0);
        out.radius.push_back(disk ? p.diskRadius : 0);
    }
    return out;
}

double median(std::vector<double> v) {
    if (v.empty()) return NAN;
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
}

struct Difference {
    double medianRel = 0, p95Rel = 0, medianRelNormalised = 0, fluxRatio = 0, medianG = 0, medianR = 0;
    std::size_t onlyA = 0, onlyB = 0, both = 0;
};

Difference compare(const Images& a, const Images& b) {
    Difference d;
    double sumA = 0, sumB = 0;
    for (std::size_t k = 0; k < a.intensity.size(); ++k) {
        sumA += a.intensity[k];
        sumB += b.intensity[k];
    }
    d.fluxRatio = sumA / sumB;
    std::vector<double> rel, relN, dg, dr;
    for (std::size_t k = 0; k < a.intensity.size(); ++k) {
        const bool ha = a.intensity[k] > 0, hb = b.intensity[k] > 0;
        d.onlyA += ha && !hb;
        d.onlyB += hb && !ha;
        if (!(ha && hb)) continue;
        ++d.both;
        rel.push_back(std::abs(a.intensity[k] / b.intensity[k] - 1));
        relN.push_back(std::abs(a.intensity[k] / sumA / (b.intensity[k] / sumB) - 1));
        if (!a.redshift.empty() && !b.redshift.empty()) dg.push_back(std::abs(a.redshift[k] / b.redshift[k] - 1));
        if (!a.radius.empty() && !b.radius.empty()) dr.push_back(std::abs(a.radius[k] / b.radius[k] - 1));
    }
    d.medianRel = median(rel);
    d.medianRelNormalised = median(relN);
    std::sort(rel.begin(), rel.end());
    d.p95Rel = rel.empty() ? NAN : rel[rel.size() * 95 / 100];
    d.medianG = median(dg);
    d.medianR = median(dr);
    return d;
}

void writeDoubles(const std::string& path, const std::vector<double>& v) {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(v.data()), static_cast<std::streamsize>(v.size() * sizeof(double)));
}

}  // namespace

int main(int argc, char** argv) {
    int n = 128;
    bool runGyoto = true;
    for (int k = 1; k < argc; ++k) {
        const std::string a = argv[k];
        if (a == "--no-gyoto-run")
            runGyoto = false;
        else
            n = std::max(8, std::atoi(argv[k]));
    }
    std::printf("# Thin disk beside GYOTO 1.4.4 (Page-Thorne example), %d x %d, 2 threads, %s\n\n", n, n,
                bench::machineName().c_str());
    for (double spin : {0.0, 0.9}) {
        const std::string stem = fileStem(spin, n);
        if (runGyoto) {
            char cmd[256];
            std::snprintf(cmd, sizeof cmd,
                          "/usr/bin/python3 bench/gyoto/gyoto_disk.py %d --spin %g --repeat 3 --extras > /dev/null", n,
                          spin);
            if (std::system(cmd) != 0) std::printf("(GYOTO run failed or python3-gyoto missing: using saved images)\n");
        }
        const std::size_t count = static_cast<std::size_t>(n) * n;
        Images gyoto{readDoubles(stem + ".f64", count), readDoubles(stem + "_redshift.f64", count),
                     readDoubles(stem + "_rhit.f64", count)};
        const double gyotoSeconds = jsonNumber(stem + ".json", "seconds");
        for (double& g : gyoto.redshift)
            if (!(g > 0)) g = 0;

        const Scene reference = gyotoScene(spin, n, 1e-12);
        const RenderResult refResult = render(reference);
        const Images truth = ours(reference, refResult);
        writeDoubles(stem + "_lightcone.f64", truth.intensity);

        std::printf("## a = %g (ISCO %.6f M)\n\n", spin, reference.disks[0].model->isco());
        std::printf(
            "| code | tolerance | seconds | rays/s | median rel. diff. to reference | 95th pct | pixels hit "
            "only by one |\n|---|---|---|---|---|---|---|\n");
        for (double tol : {1e-6, 1e-8, 1e-10}) {
            const Scene s = gyotoScene(spin, n, tol);
            RenderResult r;
            double best = 1e300;
            for (int rep = 0; rep < 3; ++rep) best = std::min(best, bench::seconds([&] { r = render(s); }));
            const Difference d = compare(ours(s, r), truth);
            std::printf("| Lightcone dopri5 | %.0e | %.3f | %.0f | %.2e | %.2e | %zu |\n", tol, best, count / best,
                        d.medianRel, d.p95Rel, d.onlyA + d.onlyB);
        }
        if (gyoto.intensity.empty()) {
            std::printf("\n(no GYOTO image at %s.f64: run bench/gyoto/gyoto_disk.py)\n\n", stem.c_str());
            continue;
        }
        const Difference d = compare(gyoto, truth);
        std::printf("| GYOTO RKF78 | 1e-6 | %.3f | %.0f | %.2e | %.2e | %zu |\n\n", gyotoSeconds, count / gyotoSeconds,
                    d.medianRel, d.p95Rel, d.onlyA + d.onlyB);
        std::printf("GYOTO against the reference, pixels both hit: %zu; only GYOTO: %zu; only Lightcone: %zu\n\n",
                    d.both, d.onlyA, d.onlyB);
        std::printf("| quantity | median relative difference |\n|---|---|\n");
        std::printf("| intensity g^4 F / pi (absolute) | %.2e |\n", d.medianRel);
        std::printf("| intensity after normalising total flux | %.2e |\n", d.medianRelNormalised);
        std::printf("| redshift g | %.2e |\n", d.medianG);
        std::printf("| emission radius | %.2e |\n", d.medianR);
        std::printf("| total flux GYOTO / Lightcone | %.6f |\n\n", d.fluxRatio);
    }
    return 0;
}
