// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Which observer reads the matter and the tides at an event when none is given: the static
// observer (along the Killing field d/dt) where d/dt is timelike, else the normal observer of the
// slice t = const (u_a proportional to d_a t) where that slice is spacelike.
#include "core/spacetime/frame.hpp"

#include <optional>
#include <string>

namespace lc {

enum class ObserverField { Static, Normal, StaticElseNormal };

// "static", "normal" or "auto"; nullopt for anything else.
std::optional<ObserverField> observerFieldNamed(const std::string& name);

// The observer's orthonormal frame at x (e[0] its 4-velocity), or nullopt where the field has
// no observer there (static inside an ergoregion, normal where t = const is not spacelike).
std::optional<LocalFrame> observerFrameAt(const Mat4& g, const Mat4& gInverse, const Vec4& x, ObserverField field);

}  // namespace lc
