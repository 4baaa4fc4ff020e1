// SPDX-License-Identifier: BSD-3-Clause
// mirrors lc::Camera (core/scene/camera.hpp) as lc::views::setCameraUniforms (views/shaders/
// camera_uniforms) sets it on every program that looks through it: its axes (Camera::axes), the
// projection (0 pinhole, 1 panorama), the pinhole's half-field tangents, the panorama's half
// extents in radians, and the image size in pixels.
uniform vec3 lcForward;
uniform vec3 lcRight;
uniform vec3 lcUp;
uniform int lcProjection;
uniform float lcTanHalfX;
uniform float lcTanHalfY;
uniform float lcHalfX;
uniform float lcHalfY;
uniform float lcWidth;
uniform float lcHeight;
