// SPDX-License-Identifier: BSD-3-Clause
#include "core/godel/images.hpp"

#include "core/numerics/roots.hpp"
#include "core/metrics/godel.hpp"
#include "core/spacetime/frame.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace lc::godel {

std::string branchName(Branch b) { return b == Branch::Outbound ? "outbound" : "inbound"; }
std::string imageStatusName(ImageStatus s) {
    switch (s) {
        case ImageStatus::Ok: return "ok";
        case ImageStatus::BeyondHorizon: return "beyond_horizon";
        case ImageStatus::InvalidInput: return "invalid_input";
    }
    return "?";
}

OriginGeodesic Image::ray(double a, double tObserver) const {
    return OriginGeodesic::nullFromDirection(a, k3, std::sin(psi), phi0, k0, tObserver, 0.0);
}

namespace {

double wrapAngle(double x) {
    double y = std::remainder(x, 2 * kPi);
    if (y <= -kPi) y += 2 * kPi;
    return y;
}

// Geometry of the equations for one point and winding (see images.hpp). A ray is a point on
// the curve beta in [0, beta_max], equivalently h in [h0 = arcsin q, pi/2]. Two variables because
// each is ill-conditioned somewhere when q is small: beta near beta_max (cos beta ~ q, where h
// sweeps from 0 to pi/2 within dbeta ~ q: the near-axis, nearly polar rays) and h near h0
// (sin beta ~ sqrt(h - h0): the nearly horizontal rays). With c = q/sin h the split is at c = 1/2:
// beta below it (there dZ/dbeta ~ sin^2 h / q <= 4q), h above it (there dZ/dh is O(1)).
struct Param {
    double b, h;  // the two variables; sb, cb = sin, cos of beta
    double sb, cb;
};

struct Curve {
    double a, q, n;
    double S(double sb) const { return sb / std::sqrt(1 + sb * sb); }
    Param fromBeta(double b) const {
        Param p;
        p.b = b;
        p.sb = std::sin(b);
        p.cb = std::cos(b);
        // y = q sqrt(1+s^2)/cos(beta) = sin h; clipped at the fold of the cylinder.
        const double y = p.cb > 0 ? std::min(1.0, q * std::sqrt(1 + p.sb * p.sb) / p.cb) : 1.0;
        p.h = std::atan2(y, std::sqrt((1 - y) * (1 + y)));
        return p;
    }
    Param fromH(double h) const {
        Param p;
        p.h = h;
        const double sh = std::sin(h), c = q / sh;
        const double omc2 = std::max(0.0, (sh - q) * (sh + q)) / (sh * sh);  // 1 - c^2, no cancellation
        p.cb = c * std::sqrt(2 / (1 + c * c));
        p.sb = std::sqrt(omc2 / (1 + c * c));
        p.b = std::atan2(p.sb, p.cb);
        return p;
    }
    double Zout(const Param& p) const { return 2 * a * S(p.sb) * (p.h + n * kPi); }
    double Zin(const Param& p) const { return 2 * a * S(p.sb) * ((n + 1) * kPi - p.h); }
    // dZin/dbeta times sqrt(1 - y^2)/(2a): finite on [0, beta_max], > 0 at 0, < 0 at beta_max.
    double dZinBeta(double b) const {
        const Param p = fromBeta(b);
        const double w = 1 + p.sb * p.sb, sw = std::sqrt(w);
        const double y = std::sin(p.h);
        const double Sp = p.cb / (w * sw);
        const double yp = p.cb > 0 ? q * p.sb * (1 / sw + sw / (p.cb * p.cb)) : HUGE_VAL;
        return Sp * ((n + 1) * kPi - p.h) * std::sqrt((1 - y) * (1 + y)) - S(p.sb) * yp;
    }
    // dZin/dh up to a positive factor: Z_in = sqrt2 a sqrt(1-c^2) ((n+1) pi - h);
    // > 0 at h0 (c = 1), < 0 at pi/2.
    double dZinH(double h) const {
        const double sh = std::sin(h), c = q / sh;
        const double omc2 = std::max(0.0, (sh - q) * (sh + q)) / (sh * sh);
        return c * c * (std::cos(h) / sh) * ((n + 1) * kPi - h) - omc2;
    }
};

// Endpoints of the sub-brackets, known in both variables.
struct Bracketing {
    const Curve& C;
    bool split;  // q < 1/2: the c = 1/2 point lies inside the curve
    Param mid;   // the c = 1/2 point
    Param solve(bool inward, const Param& lo, const Param& hi, double z) const {
        auto Fb = [&](double b) {
            const Param p = C.fromBeta(b);
            return (inward ? C.Zin(p) : C.Zout(p)) - z;
        };
        auto Fh = [&](double h) {
            const Param p = C.fromH(h);
            return (inward ? C.Zin(p) : C.Zout(p)) - z;
        };
        Param L = lo, H = hi;
        if (split && L.b < mid.b && H.b > mid.b) {
            const double fl = Fb(L.b), fm = inward ? C.Zin(mid) - z : C.Zout(mid) - z;
            if (fm == 0) return mid;
            if ((fl > 0) != (fm > 0))
                H = mid;
            else
                L = mid;
        }
        if (split && L.b >= mid.b) {
            const RootResult r = illinois(Fh, L.h, H.h, Fh(L.h), Fh(H.h));
            return C.fromH(r.x);
        }
        const RootResult r = illinois(Fb, L.b, H.b, Fb(L.b), Fb(H.b));
        return C.fromBeta(r.x);
    }
};

}  // namespace

ImageSolver::ImageSolver(double a) : a_(a) {
    if (!(a > 0)) throw std::invalid_argument("Goedel image solver: a must be > 0");
}

ImageSolver::Point ImageSolver::prepare(const Vec3& p) const {
    Point P;
    if (!p.allFinite()) {
        P.status = ImageStatus::InvalidInput;
        return P;
    }
    const double r = std::hypot(p(0), p(1));
    P.q = r / (2 * a_);
    P.phi = (r == 0) ? 0.0 : std::atan2(p(1), p(0));
    P.absz = std::abs(p(2));
    P.sgnz = p(2) > 0 ? 1.0 : (p(2) < 0 ? -1.0 : 0.0);
    if (r >= 2 * a_) {
        P.status = ImageStatus::BeyondHorizon;
        return P;
    }
    // Below ~1e-150 the derivative terms ~ 1/q^2 would overflow; such points are on the axis.
    P.onAxis = P.q < 1e-150;
    // cos beta_max = q sqrt(2/(1+q^2)); sin beta_max from (1-q)(1+q), exact near r_p -> 2a.
    const double omq = (2 * a_ - r) / (2 * a_);
    P.cosBmax = P.q * std::sqrt(2 / (1 + P.q * P.q));
    P.sinBmax = std::sqrt(omq * (1 + P.q) / (1 + P.q * P.q));
    P.bmax = std::atan2(P.sinBmax, P.cosBmax);
    return P;
}

Image ImageSolver::finish(const Point& P, int n, Branch b, bool past, double sb, double cb, double h,
                          const ImageOptions& opt) const {
    Image im;
    im.winding = n;
    im.branch = b;
    im.k0 = opt.k0 >= 0 ? 1 : -1;
    im.pastTurningPoint = past;
    im.k3 = P.sgnz * sb;
    const double sinPsi = cb;
    im.psi = std::atan2(sinPsi, im.k3);
    const double theta = past ? (n + 1) * kPi - h : h + n * kPi;
    const double omega = std::sqrt(1 + sb * sb) / (2 * a_);
    im.lambda = theta / omega;
    // phi0 so that the ray ends at phi_p; on odd windings the ray is on the far side of the axis
    // (signed radius < 0), hence the extra pi (see geodesic.hpp).
    const OriginGeodesic g0 = OriginGeodesic::nullFromDirection(a_, im.k3, sinPsi, 0.0, im.k0, opt.tObserver);
    const double Phi = g0.phase(im.lambda);
    im.phi0 = wrapAngle(P.phi - im.k0 * Phi - ((n % 2) ? kPi : 0.0));
    im.direction = Vec3(sinPsi * std::cos(im.phi0), sinPsi * std::sin(im.phi0), im.k3);
    im.emissionTime = opt.tObserver + im.k0 * (2 * kSqrt2 * a_ * Phi - im.lambda);
    const double rp = 2 * a_ * P.q;
    im.event = Vec4(im.emissionTime, rp * std::cos(P.phi), rp * std::sin(P.phi), P.sgnz * P.absz);
    return im;
}

// Straight along the axis: k3 = +-1, lambda = |z|, t = tObs + k0 lambda.
Image ImageSolver::axial(const Point& P, const ImageOptions& opt) const {
    Image im;
    im.k0 = opt.k0 >= 0 ? 1 : -1;
    im.k3 = P.sgnz;
    im.psi = P.sgnz > 0 ? 0.0 : kPi;
    im.lambda = P.absz;
    const double theta = std::sqrt(2.0) / (2 * a_) * P.absz;
    im.winding = int(std::floor(theta / kPi));
    im.branch = Branch::Outbound;
    im.pastTurningPoint = theta - im.winding * kPi > kPi / 2;
    im.direction = Vec3(0, 0, P.sgnz);
    im.emissionTime = opt.tObserver + im.k0 * im.lambda;
    im.event = Vec4(im.emissionTime, 0, 0, P.sgnz * P.absz);
    return im;
}

// Ray back on the axis after m half-periods: (1+k3^2) z^2 = (2 a m pi k3)^2.
Image ImageSolver::ringImage(const Point& P, int m, Branch b, int n, const ImageOptions& opt) const {
    const double L = 2 * a_ * m * kPi;
    // sin beta = |k3| = |z|/sqrt(L^2 - z^2), cos beta = sqrt(L^2 - 2 z^2)/sqrt(L^2 - z^2).
    const double den = std::sqrt((L - P.absz) * (L + P.absz));
    const double sb = P.absz / den;
    const double cb = std::sqrt(std::max(0.0, (L - kSqrt2 * P.absz) * (L + kSqrt2 * P.absz))) / den;
    Image im;
    im.winding = n;
    im.branch = b;
    im.k0 = opt.k0 >= 0 ? 1 : -1;
    im.ring = true;
    im.pastTurningPoint = b == Branch::Inbound;
    im.k3 = P.sgnz * sb;
    im.psi = std::atan2(cb, im.k3);
    im.lambda = m * kPi * 2 * a_ / std::sqrt(1 + sb * sb);
    im.phi0 = 0;
    im.direction = Vec3(cb, 0, im.k3);
    const OriginGeodesic g0 = OriginGeodesic::nullFromDirection(a_, im.k3, cb, 0.0, im.k0, opt.tObserver);
    im.emissionTime = g0.cartesian(im.lambda)(0);
    im.event = Vec4(im.emissionTime, 0, 0, P.sgnz * P.absz);
    return im;
}

int ImageSolver::solveWinding(const Point& P, int n, const ImageOptions& opt, std::optional<Image> out[2]) const {
    out[0].reset();
    out[1].reset();
    if (P.status != ImageStatus::Ok || n < 0) return 0;
    if (P.onAxis) {
        const double thetaAxis = std::sqrt(2.0) / (2 * a_) * P.absz;
        // In double: far up the axis (|z| > 1e10 a) the turns exceed int; n never does (windings <= 1000).
        const double nStar = std::floor(thetaAxis / kPi);
        int count = 0;
        // Front sheet: the axial ray at n*, rings m = n beyond it; back sheet: ring m = n + 1.
        if (n == nStar && P.absz > 0) out[0] = axial(P, opt);
        if (n > nStar && n * kPi > thetaAxis) out[0] = ringImage(P, n, Branch::Outbound, n, opt);
        if (n >= nStar && (n + 1) * kPi > thetaAxis) out[1] = ringImage(P, n + 1, Branch::Inbound, n, opt);
        count = int(out[0].has_value()) + int(out[1].has_value());
        return count;
    }
    const Curve C{a_, P.q, double(n)};
    const double z = P.absz;
    auto make = [&](const Param& p, Branch br, bool past) { return finish(P, n, br, past, p.sb, p.cb, p.h, opt); };
    Param p0;  // beta = 0: k3 = 0, h = arcsin q
    p0.b = 0;
    p0.sb = 0;
    p0.cb = 1;
    p0.h = std::asin(P.q);
    Param pmax;  // beta_max: the ray grazes the cylinder, h = pi/2
    pmax.b = P.bmax;
    pmax.sb = P.sinBmax;
    pmax.cb = P.cosBmax;
    pmax.h = kPi / 2;
    const double Zstar = C.Zout(pmax);
    if (z == 0) {  // k3 = 0: omega lambda = h + n pi and pi - h + n pi
        out[0] = make(p0, Branch::Outbound, false);
        out[1] = make(p0, Branch::Inbound, true);
        return 2;
    }
    const bool split = P.q < 0.5;
    const Bracketing br{C, split, split ? C.fromH(std::asin(2 * P.q)) : p0};
    if (z <= Zstar) {
        // Z_out rises from 0 to Z*, Z_in crosses z once on its rising side: brackets [0, beta_max].
        out[0] = make(br.solve(false, p0, pmax, z), Branch::Outbound, false);
        out[1] = make(br.solve(true, p0, pmax, z), Branch::Inbound, true);
        return 2;
    }
    // Beyond Z*: both roots are on the way back, on either side of the peak of Z_in.
    Param pk;
    if (split) {
        pk = C.fromH(illinois([&](double h) { return C.dZinH(h); }, p0.h, kPi / 2, C.dZinH(p0.h), C.dZinH(kPi / 2)).x);
    } else {
        pk = C.fromBeta(
            illinois([&](double b) { return C.dZinBeta(b); }, 0.0, P.bmax, C.dZinBeta(0.0), C.dZinBeta(P.bmax)).x);
    }
    if (z > C.Zin(pk)) return 0;
    out[0] = make(br.solve(true, pk, pmax, z), Branch::Outbound, true);
    out[1] = make(br.solve(true, p0, pk, z), Branch::Inbound, true);
    return 2;
}

ImageSet ImageSolver::solve(const Vec3& p, const ImageOptions& opt) const {
    ImageSet set;
    const Point P = prepare(p);
    set.status = P.status;
    if (P.status == ImageStatus::InvalidInput) {
        set.message = "point has non-finite coordinates";
        return set;
    }
    if (P.status == ImageStatus::BeyondHorizon) {
        std::ostringstream os;
        os << "point at r = " << 2 * a_ * P.q << " is at or beyond the Goedel radius 2a = " << 2 * a_
           << ": no light ray connects it with the observer, no image";
        set.message = os.str();
        return set;
    }
    for (int n = 0; n <= opt.maxWinding; ++n) {
        std::optional<Image> out[2];
        solveWinding(P, n, opt, out);
        for (int b = 0; b < 2; ++b) {
            if (!out[b]) continue;
            // A ring is the limit of two images (outbound n, inbound n-1): list it once.
            if (out[b]->ring && out[b]->branch == Branch::Outbound) continue;
            set.images.push_back(*out[b]);
        }
    }
    if (P.onAxis && P.absz == 0)
        set.message = "point at the observer: only its earlier copies (horizontal rings) are listed";
    std::sort(set.images.begin(), set.images.end(), [](const Image& x, const Image& y) { return x.lambda < y.lambda; });
    return set;
}

ImageSet ImageSolver::solveCylindrical(double r, double phi, double z, const ImageOptions& opt) const {
    return solve(Vec3(r * std::cos(phi), r * std::sin(phi), z), opt);
}

// ---- moving emitters ----------------------------------------------------------------------------

FreeFall::FreeFall(const OriginGeodesic& timelike, const Isometry& toWorld) : g_(timelike), I_(toWorld) {
    if (!timelike.isTimelike()) throw std::invalid_argument("FreeFall: needs a timelike geodesic");
}
Vec4 FreeFall::position(double tau) const { return I_.apply(g_.cartesian(tau)); }
Vec4 FreeFall::velocity(double tau) const { return I_.pushForward(g_.cartesian(tau), g_.tangentCartesian(tau)); }
WorldLine FreeFall::worldLine() const {
    const FreeFall self = *this;
    return {[self](double t) { return self.position(t); }, [self](double t) { return self.velocity(t); }};
}

std::vector<MovingImage> imagesOfWorldLine(double a, const WorldLine& w, const MovingImageOptions& opt) {
    std::vector<MovingImage> result;
    const std::vector<MovingImageOptions::Span> spans =
        opt.spans.empty() ? std::vector<MovingImageOptions::Span>{{opt.tauMin, opt.tauMax, opt.samples}} : opt.spans;
    if (!w.position) return result;
    const ImageSolver solver(a);
    const GodelCartesian metric(a);
    auto velocityAt = [&](double tau) -> Vec4 {
        Vec4 u;
        if (w.velocity) {
            u = w.velocity(tau);
        } else {
            const double h = 1e-6 * std::max(1.0, std::abs(tau));
            u = (w.position(tau + h) - w.position(tau - h)) / (2 * h);
        }
        const Vec4 x = w.position(tau);
        const double n2 = u.dot(metric.metric(x) * u);
        return n2 > 0 ? Vec4(u / std::sqrt(n2)) : u;
    };
    // Residual of slot (n, b) at tau: emission time of the image of x(tau) minus x^0(tau).
    auto residual = [&](double tau, int n, int b, Image* im) -> std::optional<double> {
        const Vec4 x = w.position(tau);
        const ImageSolver::Point P = solver.prepare(x.segment<3>(1));
        std::optional<Image> out[2];
        solver.solveWinding(P, n, opt.image, out);
        if (!out[b]) return std::nullopt;
        if (im) *im = *out[b];
        return out[b]->emissionTime - x(0);
    };
    const Vec4 uObs = opt.observerVelocity;
    // One span: every slot's residual sampled (one point and one solve per winding serve both
    // branches), then each slot's sign changes solved by Illinois.
    const int slots = 2 * (opt.image.maxWinding + 1);
    auto scan = [&](const MovingImageOptions::Span& span) {
        const int N = span.samples;
        std::vector<std::optional<double>> f(static_cast<std::size_t>(slots) * (N + 1));
        auto at = [&](int slot, int i) -> std::optional<double>& {
            return f[static_cast<std::size_t>(slot) * (N + 1) + i];
        };
        std::vector<double> taus(N + 1);
        for (int i = 0; i <= N; ++i) {
            taus[i] = span.tauMin + (span.tauMax - span.tauMin) * i / N;
            const Vec4 x = w.position(taus[i]);
            const ImageSolver::Point P = solver.prepare(x.segment<3>(1));
            for (int n = 0; n <= opt.image.maxWinding; ++n) {
                std::optional<Image> out[2];
                solver.solveWinding(P, n, opt.image, out);
                for (int b = 0; b < 2; ++b)
                    if (out[b]) at(2 * n + b, i) = out[b]->emissionTime - x(0);
            }
        }
        for (int slot = 0; slot < slots; ++slot) {
            const int n = slot / 2, b = slot % 2;
            for (int i = 0; i < N; ++i) {
                const std::optional<double>&fi = at(slot, i), &fnext = at(slot, i + 1);
                if (!fi || !fnext) continue;
                if (*fi != 0 && (*fi > 0) == (*fnext > 0)) continue;
                if (*fnext == 0 && i + 1 < N) continue;  // counted in the next interval
                auto F = [&](double tau) {
                    const auto v = residual(tau, n, b, nullptr);
                    return v ? *v : 0.0;  // image vanished inside: stop there
                };
                const RootResult rr = illinois(F, taus[i], taus[i + 1], *fi, *fnext, 1e-15);
                MovingImage mi;
                mi.tau = rr.x;
                if (!residual(rr.x, n, b, &mi.image)) continue;
                mi.velocity = velocityAt(rr.x);
                // Frequency ratio g(k,u_obs)/g(k,u_em) with the ray's covariant momentum at both ends.
                const OriginGeodesic g = mi.image.ray(a, opt.image.tObserver);
                const double kObs = g.momentumCartesian(0).dot(uObs);
                const double kEm = g.momentumCartesian(mi.image.lambda).dot(mi.velocity);
                mi.image.frequencyRatio = kObs / kEm;
                mi.image.event = w.position(rr.x);
                mi.image.emissionTime = mi.image.event(0);
                result.push_back(mi);
            }
        }
    };
    for (const MovingImageOptions::Span& span : spans) {
        if (!(span.tauMax > span.tauMin) || span.samples < 2) continue;
        scan(span);
    }
    std::sort(result.begin(), result.end(),
              [](const MovingImage& x, const MovingImage& y) { return x.image.lambda < y.image.lambda; });
    return result;
}

// ---- observer anywhere --------------------------------------------------------------------------

ObserverView::ObserverView(double a, const Vec4& observerEvent)
    : a_(a),
      obs_(observerEvent),
      toObs_(Isometry::observerToOrigin(a, observerEvent)),
      toWorld_(toObs_.inverse()),
      solver_(a) {
    const LocalFrame frame = LocalFrame::staticObserver(GodelCartesian(a), observerEvent);
    for (int i = 0; i < 3; ++i) axes_[i] = toObs_.pushForward(observerEvent, frame.e[i + 1]).tail<3>();
}

ImageSet ObserverView::images(const Vec3& worldPoint, int maxWinding, int k0) const {
    const Vec4 local = toObs_.apply(Vec4(obs_(0), worldPoint(0), worldPoint(1), worldPoint(2)));
    ImageOptions opt;
    opt.maxWinding = maxWinding;
    opt.k0 = k0;
    opt.tObserver = 0;  // the observer event is the origin of the moved chart
    ImageSet set = solver_.solve(local.segment<3>(1), opt);
    for (Image& im : set.images) {
        im.event = toWorld_.apply(im.event);
        im.emissionTime = im.event(0);
    }
    return set;
}

}  // namespace lc::godel
