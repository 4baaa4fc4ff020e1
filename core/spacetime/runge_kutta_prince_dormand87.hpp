// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Prince and Dormand's 8(7) pair RK8(7)13M as an Odeint error stepper: 13 stages, an 8th-order
// step and a 7th-order embedded solution (P. J. Prince and J. R. Dormand, "High order embedded
// Runge-Kutta formulae", J. Comput. Appl. Math. 7 (1981) 67-75, table 2; docs/PHYSICS.md
// section 7). Lightcone's high-order stepper "dopri87". It replaces Fehlberg's 7(8) pair, whose
// error estimate, 41/840 h (k1 + k11 - k12 - k13), uses the derivatives at the ends of the
// step only and vanishes where the right-hand side barely depends on the state (a ray crossing
// a warp drive's wall): there the error stalled near 5e-9 at any tolerance. This pair's error
// weights involve the stages inside the step.
#include <boost/array.hpp>
#include <boost/fusion/include/make_vector.hpp>
#include <boost/numeric/odeint/stepper/controlled_runge_kutta.hpp>
#include <boost/numeric/odeint/stepper/explicit_error_generic_rk.hpp>

#include <algorithm>
#include <cstddef>
#include <initializer_list>

namespace lc {

namespace prince_dormand87_detail {

// One row of the tableau, padded with zeros.
template <std::size_t N>
boost::array<double, N> row(std::initializer_list<double> values) {
    boost::array<double, N> r{};
    std::copy(values.begin(), values.end(), r.begin());
    return r;
}

}  // namespace prince_dormand87_detail

template <class State>
class RungeKuttaPrinceDormand87 : public boost::numeric::odeint::explicit_error_generic_rk<13, 8, 8, 7, State, double> {
public:
    using Base = boost::numeric::odeint::explicit_error_generic_rk<13, 8, 8, 7, State, double>;

    RungeKuttaPrinceDormand87()
        : Base(boost::fusion::make_vector(
                   prince_dormand87_detail::row<1>({1.0 / 18}), prince_dormand87_detail::row<2>({1.0 / 48, 1.0 / 16}),
                   prince_dormand87_detail::row<3>({1.0 / 32, 0, 3.0 / 32}),
                   prince_dormand87_detail::row<4>({5.0 / 16, 0, -75.0 / 64, 75.0 / 64}),
                   prince_dormand87_detail::row<5>({3.0 / 80, 0, 0, 3.0 / 16, 3.0 / 20}),
                   prince_dormand87_detail::row<6>({29443841.0 / 614563906, 0, 0, 77736538.0 / 692538347,
                                                    -28693883.0 / 1125000000, 23124283.0 / 1800000000}),
                   prince_dormand87_detail::row<7>({16016141.0 / 946692911, 0, 0, 61564180.0 / 158732637,
                                                    22789713.0 / 633445777, 545815736.0 / 2771057229,
                                                    -180193667.0 / 1043307555}),
                   prince_dormand87_detail::row<8>({39632708.0 / 573591083, 0, 0, -433636366.0 / 683701615,
                                                    -421739975.0 / 2616292301, 100302831.0 / 723423059,
                                                    790204164.0 / 839813087, 800635310.0 / 3783071287}),
                   prince_dormand87_detail::row<9>({246121993.0 / 1340847787, 0, 0, -37695042795.0 / 15268766246,
                                                    -309121744.0 / 1061227803, -12992083.0 / 490766935,
                                                    6005943493.0 / 2108947869, 393006217.0 / 1396673457,
                                                    123872331.0 / 1001029789}),
                   prince_dormand87_detail::row<10>({-1028468189.0 / 846180014, 0, 0, 8478235783.0 / 508512852,
                                                     1311729495.0 / 1432422823, -10304129995.0 / 1701304382,
                                                     -48777925059.0 / 3047939560, 15336726248.0 / 1032824649,
                                                     -45442868181.0 / 3398467696, 3065993473.0 / 597172653}),
                   prince_dormand87_detail::row<11>(
                       {185892177.0 / 718116043, 0, 0, -3185094517.0 / 667107341, -477755414.0 / 1098053517,
                        -703635378.0 / 230739211, 5731566787.0 / 1027545527, 5232866602.0 / 850066563,
                        -4093664535.0 / 808688257, 3962137247.0 / 1805957418, 65686358.0 / 487910083}),
                   prince_dormand87_detail::row<12>(
                       {403863854.0 / 491063109, 0, 0, -5068492393.0 / 434740067, -411421997.0 / 543043805,
                        652783627.0 / 914296604, 11173962825.0 / 925320556, -13158990841.0 / 6184727034,
                        3936647629.0 / 1978049680, -160528059.0 / 685178525, 248638103.0 / 1413531060, 0})),
               eighthOrderWeights(), errorWeights(), nodes()) {}

    // The 8th-order solution's weights b.
    static boost::array<double, 13> eighthOrderWeights() {
        return prince_dormand87_detail::row<13>({14005451.0 / 335480064, 0, 0, 0, 0, -59238493.0 / 1068277825,
                                                 181606767.0 / 758867731, 561292985.0 / 797845732,
                                                 -1041891430.0 / 1371343529, 760417239.0 / 1151165299,
                                                 118820643.0 / 751138087, -528747749.0 / 2220607170, 1.0 / 4});
    }
    // The embedded 7th-order solution's weights b-hat.
    static boost::array<double, 13> seventhOrderWeights() {
        return prince_dormand87_detail::row<13>({13451932.0 / 455176623, 0, 0, 0, 0, -808719846.0 / 976000145,
                                                 1757004468.0 / 5645159321, 656045339.0 / 265891186,
                                                 -3867574721.0 / 1518517206, 465885868.0 / 322736535,
                                                 53011238.0 / 667516719, 2.0 / 45, 0});
    }
    // Odeint's error weights: b - b-hat.
    static boost::array<double, 13> errorWeights() {
        const auto b = eighthOrderWeights(), bHat = seventhOrderWeights();
        boost::array<double, 13> d{};
        for (std::size_t i = 0; i < d.size(); ++i) d[i] = b[i] - bHat[i];
        return d;
    }
    static boost::array<double, 13> nodes() {
        return prince_dormand87_detail::row<13>({0, 1.0 / 18, 1.0 / 12, 1.0 / 8, 5.0 / 16, 3.0 / 8, 59.0 / 400,
                                                 93.0 / 200, 5490023248.0 / 9719169821, 13.0 / 20,
                                                 1201146811.0 / 1299019798, 1, 1});
    }
};

// The step-size controller Odeint gives its own error steppers, with absolute and relative
// tolerances.
template <class State>
boost::numeric::odeint::controlled_runge_kutta<RungeKuttaPrinceDormand87<State>> controlledPrinceDormand87(
    double absTol, double relTol) {
    using Controlled = boost::numeric::odeint::controlled_runge_kutta<RungeKuttaPrinceDormand87<State>>;
    return Controlled(typename Controlled::error_checker_type(absTol, relTol));
}

}  // namespace lc
