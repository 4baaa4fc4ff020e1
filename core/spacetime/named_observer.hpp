// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The observers physicists name instead of writing a 4-velocity (docs/PHYSICS.md section
// "Named observers"), built from the metric's Killing fields d/dt and d/dphi = -y d/dx + x d/dy
// and the gradients of Boyer-Lindquist r and theta, so they are the same in every chart of
// Kerr-Newman:
//   static     along d/dt, where d/dt is timelike (outside ergoregions);
//   zamo       zero angular momentum, along d/dt + omega d/dphi with omega = -g(t,phi)/g(phi,phi)
//              (stationary axisymmetric metrics, outside the horizon);
//   carter     Carter's observer ((r^2 + a^2) d/dt + a d/dphi) / sqrt(rho^2 Delta), the standard
//              observer of the finite-distance shadow literature (Kerr-Newman, Delta > 0);
//   free_fall  falling from rest at infinity: E = 1, L_z = 0, Carter's Q = 0 (Kerr-Newman; the
//              Painleve-Gullstrand observer of Schwarzschild, Doran's of Kerr);
//   normal     normal to the slice t = const (u_a proportional to d_a t), where it is spacelike.
#include "core/spacetime/spacetime.hpp"

#include <optional>
#include <string>

namespace lc {

enum class NamedObserver { Static, Zamo, Carter, FreeFall, Normal };

// "static", "zamo", "carter", "free_fall", "normal"; nullopt for anything else.
std::optional<NamedObserver> namedObserverFrom(const std::string& name);
std::string nameOf(NamedObserver observer);
// The accepted names, comma separated, for messages and docs.
std::string namedObserverNames();

// The observer's contravariant 4-velocity at x, g(u, u) = +1, future directed. Throws
// std::invalid_argument where it does not exist (static inside an ergoregion, any of them inside
// a horizon, carter and free_fall off Kerr-Newman, zamo without an axial Killing field); the
// message says why and which observers exist there.
Vec4 namedObserverVelocity(const Spacetime& spacetime, const Vec4& x, NamedObserver observer);
// The named observers other than the static one that exist at x, in the order of NamedObserver,
// as a phrase ("zamo, normal") for messages; "none" where none does.
std::string namedObserversAt(const Spacetime& spacetime, const Vec4& x);

}  // namespace lc
