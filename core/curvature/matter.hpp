// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The matter a metric implies through Einstein's equations, G_ab = 8 pi T_ab + Lambda g_ab in
// the project's signature (+,-,-,-) (docs/PHYSICS.md section 13): what an observer measures of it,
// its Hawking-Ellis type, and the energy conditions, each with the amount by which it fails.
// Also the tidal tensor an observer feels.
#include "core/curvature/curvature.hpp"
#include "core/spacetime/frame.hpp"

namespace lc {

// T_ab = (G_ab - Lambda g_ab) / 8 pi (coordinate basis).
Mat4 stressEnergyTensor(const CurvatureAt& curvature, double cosmologicalConstant);

// T in the observer's orthonormal frame: T_(a)(b) = T_ab e_a^a e_b^b.
Mat4 inFrame(const Mat4& covariantTensor, const LocalFrame& frame);

// What one observer measures (frame components).
struct MatterSeen {
    double energyDensity = 0;                // T_ab u^a u^b
    Vec3 energyFlux = Vec3::Zero();          // T^(0)(i): momentum density, energy flux
    Mat3 stress = Mat3::Zero();              // T^(i)(j)
    Vec3 principalPressures = Vec3::Zero();  // eigenvalues of the stress, ascending
};
MatterSeen matterSeenBy(const Mat4& frameComponents);

// Hawking-Ellis classification of T^a_b: I (a timelike eigenvector: a rest frame with density
// and three principal pressures), II (a double null eigenvector), III (a triple one), IV
// (complex eigenvalues).
enum class HawkingEllisType { I, II, III, IV };
const char* hawkingEllisName(HawkingEllisType type);

// An energy condition: holds, or fails by `violation` > 0 (the most negative value of the
// quantity it requires to be >= 0: rho + p_i for the null condition, and so on).
struct EnergyCondition {
    bool holds = true;
    double violation = 0;
};

struct MatterClass {
    HawkingEllisType type = HawkingEllisType::I;
    double restDensity = 0;             // type I: the eigenvalue along the timelike eigenvector
    Vec3 restPressures = Vec3::Zero();  // type I: principal pressures, ascending
    EnergyCondition nullEnergy, weak, strong, dominant;
    // Types II-IV: the conditions were tested on sampled null directions and on observers
    // moving up to 0.99 c (a lower bound on the violation), not in closed form.
    bool sampled = false;
};
// From T in an orthonormal frame (what counts as zero is relative to its largest component).
MatterClass classifyMatter(const Mat4& frameComponents);

// The tidal tensor E_ij = R_(i)(0)(j)(0) in the (-,+,+,+) sign of MTW (eq. 1.14), so that the
// geodesic deviation reads d^2 xi^i / d tau^2 = -E_ij xi^j: a static observer in Schwarzschild
// at radius r has eigenvalues -2M/r^3 (radial stretching), M/r^3, M/r^3. In this signature
// E_ij = -R_abcd e_i^a u^b e_j^c u^d.
Mat3 tidalTensor(const CurvatureAt& curvature, const LocalFrame& observer);
// Its eigenvalues, ascending.
Vec3 tidalEigenvalues(const CurvatureAt& curvature, const LocalFrame& observer);

}  // namespace lc
