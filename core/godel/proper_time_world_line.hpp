// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A body's world line in the Goedel universe parametrised by its proper time, built from segments
// one after the other (docs/PHYSICS.md section 11): at rest, radial travel at a constant speed
// relative to the static (dust) observers, uniform circular motion about the axis, free fall, and
// rocket burns of constant proper acceleration.
// Coordinate time may decrease along it: beyond r = 2a the circles of constant t and r are closed
// timelike curves, and a circle run with dt/dphi < 0 takes the traveller into the past of the chart
// (the time machine of seed 000 section 3.2.2). Every segment is checked timelike and
// future-directed (g(u, d/dt) > 0, d/dt being timelike everywhere) where it is built; a refused
// segment is named by its index and kind. Between segments the position is continuous; the
// velocity may jump (an impulsive burn), and the jumps are reported.
#include "core/numerics/types.hpp"

#include <functional>
#include <string>
#include <vector>

namespace lc::godel {

struct WorldLineSegment {
    enum class Kind { Rest, Radial, Circle, FreeFall, Rocket, Samples } kind = Kind::Rest;
    double properTime = 0;  // Rest, FreeFall, Rocket: how long (> 0)
    // Rocket: a burn of constant proper acceleration (units 1/a) along a chart direction at the
    // body's place, projected into its rest space: outward, inward (radial), prograde, retrograde
    // (about the axis), up, down (z). Integrated with Boost.Odeint (dopri5, 1e-13).
    double acceleration = 0;
    enum class Thrust { Outward, Inward, Prograde, Retrograde, Up, Down } thrust = Thrust::Outward;
    // Samples: events x(tau) (world chart) at increasing proper times, the first where the world
    // line is; straight in between. Each chord must be future timelike with the proper length its
    // proper times give (to 1 %): the velocity is the chord's, normalised.
    std::vector<std::pair<double, Vec4>> samples;
    double speed = 0;     // Radial: speed relative to the static observers, in (0, 1)
    double toRadius = 0;  // Radial: the cylindrical radius where it ends (> 0)
    double dtDphi = 0;    // Circle: coordinate time per radian (negative: into the chart's past)
    double turns = 0;     // Circle: signed turns about the axis (> 0: phi increasing)
    static std::string name(Kind k);
};

class ProperTimeWorldLine {
public:
    // Starts at `start` (world chart, Cartesian (t, x, y, z)) with the static observer's velocity
    // there. Throws std::invalid_argument naming the segment ("segment 2 (circle): ...") when one
    // is not timelike or not future-directed, or cannot start where the previous one ends.
    ProperTimeWorldLine(double a, const Vec4& start, std::vector<WorldLineSegment> segments);

    double duration() const { return pieces_.empty() ? 0 : pieces_.back().tau0 + pieces_.back().length; }
    Vec4 position(double tau) const;  // clamped to [0, duration()]
    Vec4 velocity(double tau) const;  // dx/dtau, g(u, u) = 1
    double a() const { return a_; }
    // Where each segment starts (proper time) and the Lorentz factor of the velocity jump there
    // (1: smooth), for the docs and the command line's report.
    struct Junction {
        double tau;
        double jumpGamma;
    };
    std::vector<Junction> junctions() const;
    // The world line sampled at `n` + 1 evenly spaced proper times (diagrams, exports).
    std::vector<Vec4> sampled(int n) const;

    // Where an observer can see the body is a small part of a long trip: the emission search
    // (core/render/photo_scene) asks only there. ChartBox bounds the chart's t and z over a
    // stretch of proper time (exact for rest, radial and circle legs, whose t is linear in tau;
    // within 4 sqrt2 pi a for free fall, whose t is monotonic in the chart its geodesic starts
    // from; from the stored samples for rockets and sampled legs).
    struct ChartBox {
        double tMin, tMax, zMin, zMax;
    };
    // The stretches [tau0, tau1] of blocks of proper time (at most kSpanBlock long) whose box
    // `wanted` accepts, adjacent ones merged; costs one box per block of the whole trip.
    std::vector<std::pair<double, double>> spansWhere(const std::function<bool(const ChartBox&)>& wanted) const;
    static constexpr double kSpanBlock = 4;  // in units of a
    // The longest trip, in units of a: its blocks stay under 2.5e5.
    static constexpr double kMaxDuration = 1e6;

private:
    struct Piece {
        double tau0 = 0, length = 0;
        std::function<Vec4(double)> x, u;             // of the proper time since the piece's start
        std::function<ChartBox(double, double)> box;  // bounds over [l0, l1] of the piece's own time
    };
    const Piece& pieceAt(double tau, double& local) const;
    double a_;
    std::vector<Piece> pieces_;
};

}  // namespace lc::godel
