// SPDX-License-Identifier: BSD-3-Clause
// The Planck spectrum against textbook constants (core/colour/planck).
#include <gtest/gtest.h>

#include <cmath>

#include "core/colour/planck.hpp"

using namespace lc::colour;

namespace {
// Golden-section maximisation of B_lambda(., T) on [a, b].
double peakWavelength(double T, double a, double b) {
    const double g = (std::sqrt(5.0) - 1.0) / 2.0;
    double c = b - g * (b - a), d = a + g * (b - a);
    for (int i = 0; i < 200; ++i) {
        if (planckRadiance(c, T) > planckRadiance(d, T))
            b = d;
        else
            a = c;
        c = b - g * (b - a);
        d = a + g * (b - a);
    }
    return 0.5 * (a + b);
}
}  // namespace

TEST(ColourPlanck, WienDisplacementLaw) {
    const double bWien = 2.897771955e-3;  // CODATA 2018, m K
    for (double T : {300.0, 1500.0, 5772.0, 26000.0}) {
        const double lmax = peakWavelength(T, 0.2 * bWien / T, 5.0 * bWien / T);
        EXPECT_NEAR(lmax * T / bWien, 1.0, 1e-7) << "T = " << T;
    }
}

TEST(ColourPlanck, StefanBoltzmannIntegral) {
    const double sigma = 5.670374419e-8;  // CODATA 2018, W m^-2 K^-4
    for (double T : {1000.0, 6000.0, 20000.0}) {
        // Trapezoid in ln(lambda) from 1e-2 to 1e4 times the peak: tails are < 1e-8.
        const double l0 = 1e-2 * 2.9e-3 / T, l1 = 1e4 * 2.9e-3 / T;
        const int n = 200000;
        const double h = std::log(l1 / l0) / n;
        double sum = 0.0;
        for (int i = 0; i <= n; ++i) {
            const double l = l0 * std::exp(i * h);
            sum += (i == 0 || i == n ? 0.5 : 1.0) * planckRadiance(l, T) * l;
        }
        const double integral = sum * h;
        EXPECT_NEAR(integral / (sigma * T * T * T * T / M_PI), 1.0, 1e-3) << "T = " << T;
    }
}

TEST(ColourPlanck, RadianceOfTheSunAtFiveHundredNanometres) {
    // Direct evaluation of 2hc^2/lambda^5 / (exp(hc/(lambda k T)) - 1) with rounded constants.
    const double l = 500e-9, T = 5778.0;
    const double expected = 2 * 6.626e-34 * 2.998e8 * 2.998e8 / std::pow(l, 5) /
                            (std::exp(6.626e-34 * 2.998e8 / (l * 1.381e-23 * T)) - 1.0);
    EXPECT_NEAR(planckRadiance(l, T) / expected, 1.0, 2e-3);
    EXPECT_EQ(planckRadiance(-1.0, T), 0.0);
    EXPECT_EQ(planckRadiance(1e-9, 10.0), 0.0);  // underflow, not NaN
}
