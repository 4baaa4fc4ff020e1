// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Edits that change what a scene holds rather than one value: another metric, an object or a light
// added, duplicated or removed. Each is one SceneEdit of a whole member ("metric", "objects",
// "lights"), so it is one undo step and the scene reader accepts or refuses it as it would the same
// text in a file (docs/GUI.md).
#include "core/scene/scene.hpp"
#include "readers/io/scene_edits.hpp"

#include <string>

namespace lc::io {

// The metric `name` with every parameter at its default (core/metrics/factory.hpp). Throws
// std::invalid_argument naming the known metrics when `name` is not one.
SceneEdit metricChange(const std::string& name);
// A metric change the scene can take. The metric edit alone when the scene reads with it.
// Otherwise, when the reader refuses the observer or the camera there (the old observer sits on
// the new metric's singularity or a chart's axis, inside its horizon, or where its static
// observers do not exist), the first of these that reads: the observer at the same event with a
// named velocity (normal, zamo, free_fall, carter); for an asymptotically flat metric, moved to six
// capture radii from the hole against the camera's forward direction (the hole ahead), static or
// with those velocities; otherwise moved off the chart's axis by a tenth of placeDistance along
// x^1. `moved` says what it changed and why. Throws the reader's refusal of the metric alone (it
// names the cause) when it concerns something else or when no place reads, and the refusal of
// anything else a moved observer meets (an object the new metric cannot hold) as soon as it does.
struct MetricChangePlan {
    std::vector<SceneEdit> edits;  // the metric first
    std::string moved;             // "" when only the metric changes
};
MetricChangePlan plannedMetricChange(const EditableScene& scene, const SceneEdit& metric);

// The metric written in `file` (docs/METRICS.md), its parameters at their defaults: named
// relative to `sceneFolder` when it lies inside it (a session moves with its folder), else
// absolute.
SceneEdit metricFileChange(const std::string& file, const std::string& sceneFolder);

// Which list an element edit works on.
enum class SceneList { Objects, Lights };
const char* fieldName(SceneList list);  // "objects", "lights"

// A sphere ahead of the camera: on the chart ray from the observer along its forward direction, at
// the distance placeDistance(), with a tenth of that as radius; named "sphere-N", N unused.
SceneEdit sphereAdded(const Json::Value& document, const Scene& scene);
// A light of 6500 K at the observer's event shifted by placeDistance() along the camera's up.
SceneEdit lightAdded(const Json::Value& document, const Scene& scene);
// Element `index` of the list copied right after itself, named "<name>-copy" (numbered when taken),
// and moved to the camera's right (forward x up, chart components) so that it shows beside the
// original: an object by 2.5 times its size (a sphere's radius, a mesh's farthest vertex from its
// centre), a light by 0.3 placeDistance. Throws std::invalid_argument when the list has no such
// element.
SceneEdit elementDuplicated(const Json::Value& document, const Scene& scene, SceneList list, int index);
// Element `index` left out; the member goes when the list becomes empty.
SceneEdit elementRemoved(const Json::Value& document, SceneList list, int index);

// Where new things go, in the metric's own length scale: Goedel a (inside the horizon 2a), the
// flat and warp metrics 3, black holes 0.3 of the observer's distance from the hole (at least 3 M).
double placeDistance(const Scene& scene);

}  // namespace lc::io
