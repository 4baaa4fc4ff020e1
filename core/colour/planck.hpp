// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Black-body (Planck) spectral radiance, SI units.
namespace lc::colour {

// 2019 SI defining constants (exact).
constexpr double kPlanck = 6.62607015e-34;   // J s
constexpr double kLightSpeed = 299792458.0;  // m/s
constexpr double kBoltzmann = 1.380649e-23;  // J/K

// Spectral radiance B_lambda(lambda, T) in W sr^-1 m^-2 m^-1; lambda in metres, T in kelvin.
double planckRadiance(double lambdaMetres, double temperatureK);

// Same with lambda in nanometres (result still per metre of wavelength).
inline double planckRadianceNm(double lambdaNm, double temperatureK) {
    return planckRadiance(lambdaNm * 1e-9, temperatureK);
}

}  // namespace lc::colour
