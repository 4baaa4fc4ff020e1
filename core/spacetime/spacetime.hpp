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

// Where a ray must stop because the chart or the spacetime ends there.
enum class Boundary { None, Horizon, Singularity };

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

    double hamiltonian(const Vec4& x, const Vec4& p) const { return 0.5 * p.dot(inverseMetric(x) * p); }
    // Hamilton's equations (core/spacetime/hamilton.hpp) at (x, p).
    HamiltonianFlow flow(const Vec4& x, const Vec4& p) const {
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

}  // namespace lc
