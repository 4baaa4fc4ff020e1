// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A spacetime is a metric written as code. The tracer needs g_{mu nu}, its exact first
// derivatives (automatic differentiation, never finite differences) and where rays must stop.
//
// Convention for the whole project: signature (+,-,-,-) and x^0 = t, so a future-directed
// timelike unit vector u has g(u,u) = +1 and spatial unit vectors have g(e,e) = -1.
#include "core/codegen/symbolic_metric.hpp"
#include "core/numerics/types.hpp"
#include "core/spacetime/hamilton.hpp"

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <type_traits>
#include <unsupported/Eigen/AutoDiff>

namespace lc {

// A direction k at x seen through the inversion x -> a^2 x/|x|^2 (whose Jacobian is
// (a/|x|)^2 (I - 2 x^ x^T)): k reflected in the plane normal to x, made unit. For every scalar:
// Spacetime::otherEndDirection calls it in double, the GPU tracer's lcOtherEndDirection is
// generated from it.
template <class S>
Eigen::Matrix<S, 3, 1> inversionReflected(const Eigen::Matrix<S, 3, 1>& x, const Eigen::Matrix<S, 3, 1>& k) {
    using std::sqrt;
    const Eigen::Matrix<S, 3, 1> r = k - (S(2.0) * x.dot(k) / x.dot(x)) * x;
    return r / sqrt(r.dot(r));
}

// Where a ray must stop because the chart or the spacetime ends there.
// OtherEnd: the ray has reached a two-ended spacetime's other asymptotic end (Spacetime::hasOtherEnd).
enum class Boundary { None, Horizon, Singularity, OtherEnd };

// What the tracer knows of an asymptotically flat metric's far field (Spacetime::farField):
// outside a ball of radius `size` about `centre` the metric is analytic and, at distance d,
// deviates from flat by about 2 mass / d (spin adds mass spin / d^2).
struct FarField {
    Vec3 centre = Vec3::Zero();    // at the event asked about
    Vec3 velocity = Vec3::Zero();  // d centre / dt (a moving warp bubble)
    double size = 0;               // ring singularity, bubble wall: where the field is not analytic
    double mass = 0;               // monopole; 0: exactly flat beyond `size`
    double spin = 0;               // |a| of a spinning mass
    double captureRadius = 0;      // a null ray moving outwards beyond it never comes back
};

// Right-hand side of Hamilton's equations for H = 1/2 g^{mu nu} p_mu p_nu.
struct HamiltonianFlow {
    double H = 0;              // value of the Hamiltonian (0 on a null ray)
    Vec4 dxdl = Vec4::Zero();  // dx^mu/dlambda = g^{mu nu} p_nu
    Vec4 dpdl = Vec4::Zero();  // dp_mu/dlambda = -dH/dx^mu
};

class Spacetime {
public:
    virtual ~Spacetime() = default;
    virtual std::string name() const = 0;
    virtual std::map<std::string, double> parameters() const = 0;
    // Names of the four coordinates, e.g. {"t","x","y","z"}.
    virtual std::array<std::string, 4> coordinateNames() const = 0;

    virtual Mat4 metric(const Vec4& x) const = 0;
    // g and dg[k] = d g / d x^k, exact.
    virtual void metricAndDerivatives(const Vec4& x, Mat4& g, std::array<Mat4, 4>& dg) const = 0;
    virtual Mat4 inverseMetric(const Vec4& x) const { return metric(x).inverse(); }

    virtual Boundary boundary(const Vec4& /*x*/) const { return Boundary::None; }
    // The metric as expressions in x (core/codegen), from which the GPU tracer's GLSL is
    // generated; none for a metric not written as code.
    virtual std::optional<codegen::SymbolicMetric> symbolic() const { return std::nullopt; }
    // True when the spatial chart is Cartesian and the metric tends to Minkowski far away.
    virtual bool asymptoticallyFlat() const { return false; }
    // Asymptotically flat metrics: their far field near event x (core/spacetime/integrator.cpp
    // sizes steps and decides escape with it). The default claims a unit mass at the origin.
    virtual FarField farField(const Vec4& /*x*/) const {
        FarField f;
        f.mass = 1;
        f.captureRadius = 10;
        return f;
    }

    // What the metric is, beyond g: features ask these, not the metric's class.
    // A horizon where rays stop (boundary() gives Horizon somewhere): with asymptotic flatness, a
    // black hole or a wormhole's throat casts a shadow (lightcone sweep's shadow rows).
    virtual bool hasHorizon() const { return false; }
    // Two asymptotic ends (a wormhole): boundary() gives OtherEnd where a ray has reached the far
    // one. The chart maps that end to its origin by an inversion x -> a^2 x/|x|^2, as a wormhole's
    // isotropic chart does; the ray's direction in the far side's sky is its velocity seen through
    // the inversion: k reflected in the plane normal to x (the inversion's Jacobian is
    // (a/|x|)^2 (I - 2 x^ x^T)).
    virtual bool hasOtherEnd() const { return false; }
    Vec3 otherEndDirection(const PhasePoint& q) const {
        return inversionReflected<double>(q.x.tail<3>(), (inverseMetric(q.x) * q.p).tail<3>());
    }
    // Closed forms of a Kerr-Newman hole (Boyer-Lindquist radius, Bardeen's coordinates) that a
    // built-in offers; none for other metrics, which get what the numeric tracer measures.
    struct KerrNewmanParameters {
        double mass, spin, charge;
    };
    virtual std::optional<KerrNewmanParameters> kerrNewmanParameters() const { return std::nullopt; }
    // Goedel's universe in the axis-regular chart (t, x, y, z), whose closed forms core/godel
    // implements (geodesics, every image, isometries, photo-objects): its radius a.
    virtual std::optional<double> godelRadius() const { return std::nullopt; }
    // Stationary (d/dt a Killing field), axisymmetric about the chart's z axis (-y d/dx + x d/dy
    // one), z = 0 a mirror plane, asymptotically flat: circular equatorial orbits, their ISCO and
    // thin disks exist (core/accretion/thin_disk). The radius that labels them, as an expression
    // of the chart's coordinates, increasing outwards along +x on z = 0: Boyer-Lindquist r for
    // Kerr-Newman, a formula metric's "radius" (else the cylindrical radius). None when the metric
    // is not so.
    virtual std::optional<codegen::Expr> equatorialRadius() const { return std::nullopt; }
    // Declared stationary (d/dt a Killing field, so p_t is conserved along every geodesic): a
    // Kerr-Newman built-in or a metric with an equatorial radius. What the GPU's black-body sky,
    // whose g is 1 / |p_t| of the camera ray, needs.
    bool declaredStationary() const { return kerrNewmanParameters() || equatorialRadius(); }
    // The symmetries whose Killing fields xi make p . xi a constant of every geodesic, in a
    // Cartesian spatial chart: d/dt, rotations about z (-y d/dx + x d/dy), every rotation about
    // the origin. The tracer holds these constants (core/spacetime/constants_of_motion). The
    // default: what a declared equatorial radius was checked for (d/dt and rotations about z).
    struct Symmetries {
        bool stationary = false, axisymmetric = false, spherical = false;
    };
    virtual Symmetries symmetries() const {
        const bool circular = equatorialRadius().has_value();
        return {circular, circular, false};
    }

    double hamiltonian(const Vec4& x, const Vec4& p) const { return 0.5 * p.dot(inverseMetric(x) * p); }
    // Hamilton's equations (core/spacetime/hamilton.hpp) at (x, p). A metric with a cheaper exact
    // form (KerrSchildMetric) overrides it; tests hold the override to this general one.
    virtual HamiltonianFlow flow(const Vec4& x, const Vec4& p) const { return generalFlow(x, p); }
    HamiltonianFlow generalFlow(const Vec4& x, const Vec4& p) const {
        Mat4 g;
        std::array<Mat4, 4> dg;
        metricAndDerivatives(x, g, dg);
        HamiltonianFlow f;
        hamiltonEquations(g, dg, p, f.dxdl, f.dpdl);
        f.H = 0.5 * p.dot(f.dxdl);
        return f;
    }
};

using SpacetimePtr = std::shared_ptr<const Spacetime>;

namespace detail {
// Whether a metric class defines `template <class S> S boundaryFunction(const Matrix<S,4,1>&)`.
template <class T, class = void>
struct HasBoundaryFunction : std::false_type {};
template <class T>
struct HasBoundaryFunction<
    T, std::void_t<decltype(std::declval<const T&>().template boundaryFunction<double>(std::declval<const Vec4&>()))>>
    : std::true_type {};
}  // namespace detail

// CRTP base: a metric class writes `template <class S> Eigen::Matrix<S,4,4> g(const
// Eigen::Matrix<S,4,1>& x) const` once; values and exact derivatives both come from it,
// the derivatives through Eigen's forward-mode AutoDiffScalar, and the GPU's GLSL through
// codegen::Expr (symbolic()). A metric whose chart or spacetime ends (a horizon) also writes
// `template <class S> S boundaryFunction(x)`, <= 0 where rays stop, for both.
template <class Derived>
class CodedMetric : public Spacetime {
public:
    std::optional<codegen::SymbolicMetric> symbolic() const override {
        codegen::ExprVector4 x;
        for (int i = 0; i < 4; ++i) x(i) = codegen::Expr::coordinate(i);
        codegen::SymbolicMetric s;
        s.g = self().template g<codegen::Expr>(x);
        if constexpr (detail::HasBoundaryFunction<Derived>::value)
            s.boundary = self().template boundaryFunction<codegen::Expr>(x);
        std::ostringstream origin;
        origin.precision(17);
        origin << "metric '" << name() << "'";
        for (const auto& [key, value] : parameters()) origin << " " << key << "=" << value;
        s.origin = origin.str();
        return s;
    }

    using Dual = Eigen::AutoDiffScalar<Eigen::Matrix<double, 4, 1>>;

    Mat4 metric(const Vec4& x) const override { return self().template g<double>(x); }

    void metricAndDerivatives(const Vec4& x, Mat4& g, std::array<Mat4, 4>& dg) const override {
        Eigen::Matrix<Dual, 4, 1> xd;
        for (int i = 0; i < 4; ++i) xd(i) = Dual(x(i), 4, i);
        const Eigen::Matrix<Dual, 4, 4> gd = self().template g<Dual>(xd);
        for (int m = 0; m < 4; ++m)
            for (int n = 0; n < 4; ++n) {
                g(m, n) = gd(m, n).value();
                const auto& d = gd(m, n).derivatives();
                // A constant entry carries an empty derivative vector.
                for (int k = 0; k < 4; ++k) dg[k](m, n) = d.size() == 4 ? d(k) : 0.0;
            }
    }

private:
    const Derived& self() const { return static_cast<const Derived&>(*this); }
};

// CRTP base for metrics of Kerr-Schild form g = eta - f l (x) l, where l is null for eta
// (|l_spatial| = l_t): the metric class writes `template <class S> void kerrSchild(const
// Eigen::Matrix<S,4,1>& x, S& f, Eigen::Matrix<S,4,1>& l) const` (l covariant) once, and gets
//  - g<S> (so values, GLSL and the general automatic derivatives all follow from it);
//  - the exact inverse g^{mu nu} = eta^{mu nu} + f l^mu l^nu (l^mu = eta^{mu nu} l_nu), no 4x4
//    inversion;
//  - Hamilton's equations from automatic derivatives of the five functions f and l alone:
//    v = eta p + f (l.p) l^,  dp_k/dl = -(l.p) (1/2 d_k f (l.p) + f d_k l^.p),
//    instead of derivatives of all sixteen entries of g.
template <class Derived>
class KerrSchildMetric : public CodedMetric<Derived> {
public:
    template <class S>
    Eigen::Matrix<S, 4, 4> g(const Eigen::Matrix<S, 4, 1>& x) const {
        S f;
        Eigen::Matrix<S, 4, 1> l;
        self().kerrSchild(x, f, l);
        Eigen::Matrix<S, 4, 4> m;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) m(i, j) = -f * l(i) * l(j);
        m(0, 0) += S(1.0);
        for (int i = 1; i < 4; ++i) m(i, i) -= S(1.0);
        return m;
    }

    Mat4 inverseMetric(const Vec4& x) const override {
        double f;
        Vec4 l;
        self().kerrSchild(x, f, l);
        const Vec4 lUp = raised(l);
        Mat4 gi = f * lUp * lUp.transpose();
        gi.diagonal() += Vec4(1, -1, -1, -1);
        return gi;
    }

    HamiltonianFlow flow(const Vec4& x, const Vec4& p) const override {
        using D = typename CodedMetric<Derived>::Dual;
        Eigen::Matrix<D, 4, 1> xd;
        for (int i = 0; i < 4; ++i) xd(i) = D(x(i), 4, i);
        D fd;
        Eigen::Matrix<D, 4, 1> ld;
        self().kerrSchild(xd, fd, ld);
        // l^mu p_mu and its derivatives d_k (l^mu) p_mu; constant entries carry no derivatives.
        Vec4 lUp, dlp = Vec4::Zero();
        for (int m = 0; m < 4; ++m) {
            const double sign = m == 0 ? 1 : -1;
            lUp(m) = sign * ld(m).value();
            if (ld(m).derivatives().size() == 4) dlp += sign * p(m) * ld(m).derivatives();
        }
        const double f = fd.value(), lp = lUp.dot(p);
        const Vec4 df = fd.derivatives().size() == 4 ? Vec4(fd.derivatives()) : Vec4::Zero();
        HamiltonianFlow out;
        out.dxdl = raised(p) + f * lp * lUp;
        out.dpdl = -lp * (0.5 * lp * df + f * dlp);
        out.H = 0.5 * p.dot(out.dxdl);
        return out;
    }

private:
    static Vec4 raised(const Vec4& v) { return Vec4(v(0), -v(1), -v(2), -v(3)); }
    const Derived& self() const { return static_cast<const Derived&>(*this); }
};

}  // namespace lc
