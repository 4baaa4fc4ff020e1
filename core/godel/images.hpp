// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Every image of a point in the Goedel universe (docs/PHYSICS.md section 3; seed 001 section 5.2):
// the null rays through the observer at the origin that reach a point, found in closed form up
// to one scalar equation per image, solved by the Illinois method on a guaranteed bracket.
//
// Chart: Cartesian (t, X, Y, z) of GodelCartesian; the observer (or light) sits at the origin,
// static, at time tObserver. k0 = -1: past-directed rays (what a camera sees); k0 = +1:
// future-directed rays (light leaving a source at the origin, shadow rays).
//
// Parametrisation. A ray with elevation beta (k3 = sin beta sgn z, so psi = pi/2 - beta sgn z)
// meets the cylinder r = r_p at omega*lambda = h + n pi (way out) and pi - h + n pi (way back),
// h = arcsin(q sqrt(1+k3^2)/sqrt(1-k3^2)), q = r_p/2a, at heights
//   Z_out(beta) = 2a S (h + n pi),  Z_in(beta) = 2a S (pi(n+1) - h),  S = sin beta / sqrt(1 + sin^2 beta).
// Z_out rises monotonically to Z* = Z(beta_max) (where h = pi/2: the ray just grazes the cylinder);
// Z_in is NOT monotone (a source's "f is monotone" holds for the outbound equation only; docs/PHYSICS.md section 3): it
// rises to a peak Zpk >= Z* at beta_peak and falls back to Z* at beta_max. So the images of
// winding n are the two solutions of Z = |z_p| on the closed curve out -> in, which exist iff
// |z_p| <= Zpk, and merge at the fold beta_peak. The two branches are the two sides of that fold:
//   Outbound: the rising side, i.e. the way-out root, or (Z* < |z_p| <= Zpk) the way-back root
//             with beta in [beta_peak, beta_max] (Image::pastTurningPoint tells these apart);
//   Inbound:  the way-back root with beta in [0, beta_peak].
// This labelling gives at most one image per (winding, branch) and both branches exist for the
// same points, which is what stitching the two photo-objects of one winding needs.
// Each solve works on F(beta) = Z(beta) - |z_p|, which is finite on the closed bracket (no 1/k3).
#include "core/godel/geodesic.hpp"
#include "core/godel/isometry.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace lc::godel {

enum class Branch { Outbound, Inbound };
enum class ImageStatus {
    Ok,             // images listed (may be none if maxWinding is too low for a far-off |z|)
    BeyondHorizon,  // r_p >= 2a from the observer: no null ray connects them, no image
    InvalidInput    // non-finite input or a <= 0
};
std::string branchName(Branch b);
std::string imageStatusName(ImageStatus s);

// The polar angle from +z and the azimuth, in (-pi, pi], of a unit sky direction: Image's psi and
// phi0 of a direction given in another frame (the camera's, ObserverView::inObserverFrame).
struct SkyAngles {
    double psi = 0, phi0 = 0;
};
inline SkyAngles skyAngles(const Vec3& direction) {
    return {std::acos(std::clamp(direction.z(), -1.0, 1.0)), std::atan2(direction.y(), direction.x())};
}

struct Image {
    int winding = 0;
    Branch branch = Branch::Outbound;
    double psi = 0;                 // polar angle of the sky direction from +z
    double phi0 = 0;                // azimuth of the sky direction, in (-pi, pi]
    double k3 = 0;                  // cos psi = dz/dlambda
    double lambda = 0;              // affine length (unit observed frequency): the depth for occlusion
    double emissionTime = 0;        // t of the emission event (arrival for k0 = +1)
    double frequencyRatio = 1;      // nu_obs/nu_em = g(k,u_obs)/g(k,u_em); exactly 1 for static ends
    Vec3 direction = Vec3::Zero();  // (sin psi cos phi0, sin psi sin phi0, cos psi), observer's frame
    Vec4 event = Vec4::Zero();      // the far end of the ray (emission event for k0 = -1)
    int k0 = -1;
    bool pastTurningPoint = false;  // reached on the ray's way back towards the axis
    bool ring = false;              // point on the axis: the image is a cone (Einstein ring) of half-angle psi;
                                    // phi0 is then arbitrary (set to 0)
    // The ray itself (closed form), starting at the observer.
    OriginGeodesic ray(double a, double tObserver = 0) const;
};

struct ImageSet {
    ImageStatus status = ImageStatus::Ok;
    std::string message;
    std::vector<Image> images;  // sorted by lambda
};

struct ImageOptions {
    int maxWinding = 3;    // windings 0..maxWinding
    int k0 = -1;           // -1: past-directed (camera), +1: future-directed (light)
    double tObserver = 0;  // time of the observer / light at the origin
};

// Static point, observer at the origin. Thread-safe (no state besides a).
class ImageSolver {
public:
    explicit ImageSolver(double a);
    double a() const { return a_; }

    ImageSet solve(const Vec3& pointXYz, const ImageOptions& opt = {}) const;
    ImageSet solveCylindrical(double r, double phi, double z, const ImageOptions& opt = {}) const;

    // Per-point data shared by all windings (public so the mesh code can reuse it).
    struct Point {
        double q = 0, phi = 0, absz = 0, sgnz = 0;
        double sinBmax = 0, cosBmax = 0, bmax = 0;
        bool onAxis = false;
        ImageStatus status = ImageStatus::Ok;
    };
    Point prepare(const Vec3& pointXYz) const;
    // The images of winding n on both branches (out[0] Outbound, out[1] Inbound). Returns the
    // number found (0 or 2; for an on-axis point the slots that carry an axial image or a ring).
    int solveWinding(const Point& P, int n, const ImageOptions& opt, std::optional<Image> out[2]) const;

private:
    Image finish(const Point& P, int n, Branch b, bool pastTurningPoint, double sinB, double cosB, double h,
                 const ImageOptions& opt) const;
    Image axial(const Point& P, const ImageOptions& opt) const;
    Image ringImage(const Point& P, int m, Branch b, int n, const ImageOptions& opt) const;
    double a_;
};

// ---- moving emitters ------------------------------------------------------------------------

// A world line in the Cartesian chart of the solver (observer at the origin).
struct WorldLine {
    std::function<Vec4(double)> position;  // x(tau)
    std::function<Vec4(double)> velocity;  // dx/dtau; if empty: central differences of position
};

// Free fall: docs/PHYSICS.md section 2's timelike geodesic through the origin, moved by an isometry.
class FreeFall {
public:
    FreeFall(const OriginGeodesic& timelike, const Isometry& toWorld);
    Vec4 position(double tau) const;
    Vec4 velocity(double tau) const;
    WorldLine worldLine() const;

private:
    OriginGeodesic g_;
    Isometry I_;
};

struct MovingImage {
    Image image;                   // image.frequencyRatio = g(k,u_obs)/g(k,u_em)
    double tau = 0;                // parameter of the emission event on the world line
    Vec4 velocity = Vec4::Zero();  // emitter 4-velocity there (normalised)
};

struct MovingImageOptions {
    ImageOptions image;  // maxWinding, k0, tObserver
    double tauMin = -10, tauMax = 10;
    int samples = 256;  // sign-change scan of each (winding, branch) over [tauMin, tauMax]
    // Where given, the scan covers these stretches instead, each with its own sample count (a long
    // trip: only where the observer can see it, ProperTimeWorldLine::spansWhere).
    struct Span {
        double tauMin, tauMax;
        int samples;
    };
    std::vector<Span> spans;
    Vec4 observerVelocity = Vec4(1, 0, 0, 0);  // contravariant, at the origin (static by default)
};

// The emission events on the world line seen by the observer: for every (winding, branch) the
// scalar equation t_image(x(tau)) = x^0(tau), bracketed by a scan over tau and solved by
// Illinois. Roots closer than the scan spacing to where an image (dis)appears can be missed.
std::vector<MovingImage> imagesOfWorldLine(double a, const WorldLine& w, const MovingImageOptions& opt);

// ---- observer anywhere ------------------------------------------------------------------------

// A static observer at any event: the scene is moved with the isometry that brings the observer
// to the origin and its static frame (Gram-Schmidt of d/dx, d/dy, d/dz: the camera's, docs/
// PHYSICS.md section 8) onto the coordinate axes there, so an Image::direction is where the camera
// sees it and the diagrams drawn in this chart face as the observer does.
class ObserverView {
public:
    ObserverView(double a, const Vec4& observerEvent);
    const Isometry& toObserver() const { return toObs_; }
    const Isometry& toWorld() const { return toWorld_; }
    Vec4 event(const Vec4& world) const { return toObs_.apply(world); }
    Vec4 vector(const Vec4& world, const Vec4& v) const { return toObs_.pushForward(world, v); }
    // The observer's static frame (lc::LocalFrame::staticObserver: Gram-Schmidt of d/dx, d/dy,
    // d/dz, the camera frame of docs/PHYSICS.md section 8) seen at the origin of the moved chart.
    const std::array<Vec3, 3>& frameAxes() const { return axes_; }
    // A direction at the origin of the moved chart (an Image::direction) in that frame: where the
    // observer's camera sees it (the identity up to rounding: the chart is aligned with the frame).
    Vec3 inObserverFrame(const Vec3& originDirection) const {
        return Vec3(originDirection.dot(axes_[0]), originDirection.dot(axes_[1]), originDirection.dot(axes_[2]));
    }
    // Images of a static world point; Image::event and emissionTime are given in the world chart.
    ImageSet images(const Vec3& worldPoint, int maxWinding, int k0 = -1) const;

private:
    double a_;
    Vec4 obs_;
    Isometry toObs_, toWorld_;
    std::array<Vec3, 3> axes_;
    ImageSolver solver_;
};

}  // namespace lc::godel
