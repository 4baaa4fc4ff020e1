// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Whether a null ray of a Kerr-Newman hole falls into the horizon or escapes to infinity, from
// its constants of motion alone, without integrating it: Carter's radial potential
//   R(r) = [E (r^2 + a^2) - a L]^2 - Delta (Q + (L - a E)^2),   Delta = r^2 - 2 M r + a^2 + Q_e^2
// (Carter 1968; MTW eq. 33.33b) is >= 0 wherever the ray goes, so a region where R < 0 between
// the ray's radius and the horizon (or infinity) turns it back, and none lets it through. E = -p_t,
// L = p_phi and Carter's Q = p_theta^2 + cos^2(theta) (L^2 / sin^2(theta) - a^2 E^2) come from the
// covariant momentum in the Kerr-Schild chart of lc::KerrNewman (docs/PHYSICS.md section 10).
// The shadow's edges (core/analysis/shadow) decide every ray's fate so: exactly, in microseconds.
#include "core/spacetime/spacetime.hpp"

#include <optional>

namespace lc {

enum class RayFate { Captured, Escapes };

// The fate of the ray with covariant momentum p at event x, followed along dx/dlambda = g^-1 p.
// std::nullopt where the potential does not decide it: an event on the axis (theta undefined) or
// at or inside the outer horizon, a ray at a turning point (R(r) = 0 to rounding), E = 0, or a
// ray held between two turning points (a bound orbit).
std::optional<RayFate> radialPotentialFate(const Spacetime::KerrNewmanParameters& hole, const Spacetime& st,
                                           const Vec4& x, const Vec4& p);

}  // namespace lc
