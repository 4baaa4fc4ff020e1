// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Curvature, matter and tides sampled on a grid of the chart at one coordinate time: the arrays
// behind vtkLightconeCurvatureSource, `lightcone curvature -o FILE.vti` and Python's numpy
// arrays. Quantities that need an observer are read by the chosen observer field
// (core/curvature/observer_field.hpp) and are NaN where it has none; every quantity is NaN where
// the metric is not finite (a singularity).
#include "core/curvature/curvature.hpp"
#include "core/curvature/matter.hpp"
#include "core/curvature/observer_field.hpp"

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace lc {

enum class CurvatureQuantity {
    Kretschmann,
    RicciScalar,
    RicciSquared,
    WeylSquared,
    EnergyDensity,
    EnergyFlux,
    PrincipalPressures,
    HawkingEllisType,
    NullEnergyViolation,
    WeakEnergyViolation,
    StrongEnergyViolation,
    DominantEnergyViolation,
    TidalEigenvalues
};

struct CurvatureQuantityInfo {
    CurvatureQuantity quantity;
    const char* name;  // as the command line, the VTK arrays and Python name it
    int components;
    bool needsObserver;
    const char* meaning;
};
// Every quantity, in the order above.
const std::vector<CurvatureQuantityInfo>& curvatureQuantities();
const CurvatureQuantityInfo& curvatureQuantityInfo(CurvatureQuantity quantity);
// By name; nullopt for an unknown one.
std::optional<CurvatureQuantity> curvatureQuantityNamed(const std::string& name);

// What is read at each event besides the metric: Lambda in G_ab = 8 pi T_ab + Lambda g_ab, and
// which observers measure.
struct CurvatureReading {
    double cosmologicalConstant = 0;
    ObserverField observers = ObserverField::StaticElseNormal;
};

// The quantities at one event, each computed once however many are asked (the matter's
// classification is the costly part, shared by the four energy conditions).
class EventReading {
public:
    EventReading(const CurvatureAt& curvature, std::optional<LocalFrame> observer, const CurvatureReading& reading)
        : curvature_(curvature), observer_(std::move(observer)), reading_(reading) {}
    // The quantity's components into `out` (NaN where it needs an observer and there is none).
    void values(CurvatureQuantity quantity, double* out);

private:
    const Mat4& matterInFrame();
    const MatterClass& matterClass();

    const CurvatureAt& curvature_;
    std::optional<LocalFrame> observer_;
    CurvatureReading reading_;
    std::optional<Mat4> matterInFrame_;
    std::optional<MatterClass> matterClass_;
};

// A regular grid of the spatial chart coordinates x^1..x^3 at chart time `time`; point (i, j, k)
// is origin + (i, j, k) * spacing, i fastest (VTK's vtkImageData order).
struct ChartGrid {
    double time = 0;
    Vec3 origin = Vec3::Zero();
    Vec3 spacing = Vec3::Ones();
    std::array<int, 3> dimensions{1, 1, 1};
    std::size_t points() const;
};

struct CurvatureField {
    std::vector<CurvatureQuantity> quantities;
    std::vector<std::vector<double>> values;  // per quantity: points x components, interleaved
    std::size_t singularPoints = 0;           // where the metric or its curvature is not finite
    std::size_t pointsWithoutObserver = 0;    // where the observer field has no observer
    bool stopped = false;                     // progress asked to stop: points not reached are NaN
};

// Samples the quantities on the grid on every core. `progress` (if given) is called from the
// calling thread with the fraction done, between slabs of points; returning false stops the
// sampling (the values already computed stay, the rest are NaN) and the result says so.
CurvatureField sampleCurvatureField(const Spacetime& spacetime, const ChartGrid& grid,
                                    const std::vector<CurvatureQuantity>& quantities, const CurvatureReading& reading,
                                    const std::function<bool(double)>& progress = {});

// The same quantities at a list of events (a ray's points, an observer's world line): values per
// event in the order given, as CurvatureField's per grid point.
CurvatureField sampleCurvatureAtEvents(const Spacetime& spacetime, const std::vector<Vec4>& events,
                                       const std::vector<CurvatureQuantity>& quantities,
                                       const CurvatureReading& reading);

}  // namespace lc
