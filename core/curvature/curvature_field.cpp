// SPDX-License-Identifier: BSD-3-Clause
#include "core/curvature/curvature_field.hpp"

#include "core/numerics/parallel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace lc {

const std::vector<CurvatureQuantityInfo>& curvatureQuantities() {
    using Q = CurvatureQuantity;
    static const std::vector<CurvatureQuantityInfo> all{
        {Q::Kretschmann, "kretschmann", 1, false, "R_abcd R^abcd"},
        {Q::RicciScalar, "ricci_scalar", 1, false, "R = g^ab R_ab, signature (+,-,-,-)"},
        {Q::RicciSquared, "ricci_squared", 1, false, "R_ab R^ab"},
        {Q::WeylSquared, "weyl_squared", 1, false, "C_abcd C^abcd"},
        {Q::EnergyDensity, "energy_density", 1, true, "T_ab u^a u^b the observer measures"},
        {Q::EnergyFlux, "energy_flux", 3, true, "T^(0)(i): the energy flux in the observer's frame"},
        {Q::PrincipalPressures, "principal_pressures", 3, true,
         "eigenvalues of the stress T^(i)(j) in the observer's frame, ascending"},
        {Q::HawkingEllisType, "hawking_ellis_type", 1, true, "1, 2, 3 or 4 for types I-IV of T^a_b"},
        {Q::NullEnergyViolation, "null_energy_violation", 1, true,
         "how far T_ab k^a k^b falls below 0 (k null, k.u = 1); 0 where it holds"},
        {Q::WeakEnergyViolation, "weak_energy_violation", 1, true,
         "how far the energy density any observer measures falls below 0; 0 where it holds"},
        {Q::StrongEnergyViolation, "strong_energy_violation", 1, true,
         "how far (T_ab - T g_ab / 2) v^a v^b falls below 0; 0 where it holds"},
        {Q::DominantEnergyViolation, "dominant_energy_violation", 1, true,
         "how far the energy flux exceeds the density (or the density falls below 0); 0 where it holds"},
        {Q::TidalEigenvalues, "tidal_eigenvalues", 3, true,
         "eigenvalues of the tidal tensor E_ij = R_(i)(0)(j)(0) (MTW sign), ascending"},
    };
    return all;
}

const CurvatureQuantityInfo& curvatureQuantityInfo(CurvatureQuantity quantity) {
    return curvatureQuantities()[static_cast<std::size_t>(quantity)];
}

std::optional<CurvatureQuantity> curvatureQuantityNamed(const std::string& name) {
    for (const auto& q : curvatureQuantities())
        if (name == q.name) return q.quantity;
    return std::nullopt;
}

std::size_t ChartGrid::points() const {
    return static_cast<std::size_t>(dimensions[0]) * static_cast<std::size_t>(dimensions[1]) *
           static_cast<std::size_t>(dimensions[2]);
}

const Mat4& EventReading::matterInFrame() {
    if (!matterInFrame_)
        matterInFrame_ = inFrame(stressEnergyTensor(curvature_, reading_.cosmologicalConstant), *observer_);
    return *matterInFrame_;
}

const MatterClass& EventReading::matterClass() {
    if (!matterClass_) matterClass_ = classifyMatter(matterInFrame());
    return *matterClass_;
}

void EventReading::values(CurvatureQuantity quantity, double* out) {
    using Q = CurvatureQuantity;
    const CurvatureQuantityInfo& info = curvatureQuantityInfo(quantity);
    if (info.needsObserver && !observer_) {
        std::fill(out, out + info.components, std::numeric_limits<double>::quiet_NaN());
        return;
    }
    const CurvatureAt& c = curvature_;
    auto copy3 = [out](const Vec3& v) { std::copy(v.data(), v.data() + 3, out); };
    switch (quantity) {
        case Q::Kretschmann: *out = c.kretschmann; break;
        case Q::RicciScalar: *out = c.ricciScalar; break;
        case Q::RicciSquared: *out = c.ricciSquared; break;
        case Q::WeylSquared: *out = c.weylSquared; break;
        case Q::EnergyDensity: *out = matterInFrame()(0, 0); break;
        case Q::EnergyFlux: copy3(matterSeenBy(matterInFrame()).energyFlux); break;
        case Q::PrincipalPressures: copy3(matterSeenBy(matterInFrame()).principalPressures); break;
        case Q::TidalEigenvalues: copy3(tidalEigenvalues(c, *observer_)); break;
        case Q::HawkingEllisType: *out = 1 + static_cast<int>(matterClass().type); break;
        case Q::NullEnergyViolation: *out = matterClass().nullEnergy.violation; break;
        case Q::WeakEnergyViolation: *out = matterClass().weak.violation; break;
        case Q::StrongEnergyViolation: *out = matterClass().strong.violation; break;
        case Q::DominantEnergyViolation: *out = matterClass().dominant.violation; break;
    }
}

namespace {

// The quantities at events 0..n-1 (eventOf), in slabs on every core; the work of both samplers.
CurvatureField sampleAt(const Spacetime& spacetime, std::size_t n, const std::function<Vec4(std::size_t)>& eventOf,
                        const std::vector<CurvatureQuantity>& quantities, const CurvatureReading& reading,
                        const std::function<bool(double)>& progress) {
    const CurvatureProbe probe(spacetime);
    CurvatureField field;
    field.quantities = quantities;
    bool anyObserver = false;
    for (CurvatureQuantity q : quantities) {
        const auto& info = curvatureQuantityInfo(q);
        field.values.emplace_back(n * static_cast<std::size_t>(info.components),
                                  std::numeric_limits<double>::quiet_NaN());
        anyObserver = anyObserver || info.needsObserver;
    }
    // Slabs of about 1 % of the points, so progress and stopping come often but each slab still
    // keeps both cores busy.
    const std::size_t slab = std::max<std::size_t>(4096, n / 100);
    std::size_t singular = 0, withoutObserver = 0;
    FirstError error;
    for (std::size_t begin = 0; begin < n; begin += slab) {
        const auto end = static_cast<std::ptrdiff_t>(std::min(n, begin + slab));
#pragma omp parallel for schedule(dynamic, 64) reduction(+ : singular, withoutObserver)
        for (auto p = static_cast<std::ptrdiff_t>(begin); p < end; ++p) {
            error.run([&] {
                const auto i = static_cast<std::size_t>(p);
                const Vec4 x = eventOf(i);
                const CurvatureAt c = probe.at(x);
                if (!std::isfinite(c.kretschmann) || !c.g.allFinite()) {
                    ++singular;
                    return;
                }
                std::optional<LocalFrame> observer;
                if (anyObserver) {
                    observer = observerFrameAt(c.g, c.gInverse, x, reading.observers);
                    if (!observer) ++withoutObserver;
                }
                EventReading values(c, std::move(observer), reading);
                for (std::size_t q = 0; q < quantities.size(); ++q) {
                    const auto components = static_cast<std::size_t>(curvatureQuantityInfo(quantities[q]).components);
                    values.values(quantities[q], &field.values[q][i * components]);
                }
            });
        }
        error.rethrow();
        if (progress && !progress(static_cast<double>(end) / static_cast<double>(n))) {
            field.stopped = end < static_cast<std::ptrdiff_t>(n);
            break;
        }
    }
    field.singularPoints = singular;
    field.pointsWithoutObserver = withoutObserver;
    return field;
}

}  // namespace

CurvatureField sampleCurvatureField(const Spacetime& spacetime, const ChartGrid& grid,
                                    const std::vector<CurvatureQuantity>& quantities, const CurvatureReading& reading,
                                    const std::function<bool(double)>& progress) {
    for (int d : grid.dimensions)
        if (d < 1) throw std::invalid_argument("curvature grid: every dimension must be >= 1");
    const auto nx = static_cast<std::size_t>(grid.dimensions[0]), ny = static_cast<std::size_t>(grid.dimensions[1]);
    return sampleAt(
        spacetime, grid.points(),
        [&](std::size_t i) {
            const Vec3 index(static_cast<double>(i % nx), static_cast<double>((i / nx) % ny),
                             static_cast<double>(i / (nx * ny)));
            Vec4 x;
            x << grid.time, grid.origin + grid.spacing.cwiseProduct(index);
            return x;
        },
        quantities, reading, progress);
}

CurvatureField sampleCurvatureAtEvents(const Spacetime& spacetime, const std::vector<Vec4>& events,
                                       const std::vector<CurvatureQuantity>& quantities,
                                       const CurvatureReading& reading) {
    return sampleAt(spacetime, events.size(), [&](std::size_t i) { return events[i]; }, quantities, reading, {});
}

}  // namespace lc
