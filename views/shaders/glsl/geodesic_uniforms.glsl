// SPDX-License-Identifier: BSD-3-Clause
// mirrors vtkLightconeGeodesicTracerMapper::SetMapperShaderParameters (views/): the uniforms of the
// tracer's fragment shader (glsl/geodesic_trace, camera_direction, geodesic_pixel), set on its
// program at each draw.
uniform int lcMode;  // 0 colour, 1 (class, steps / 8), 2 escape direction
uniform float lcBoundaryStop;
uniform int lcEscapes;
uniform float lcEscapeRadius;
uniform float lcMaxAffine;
uniform vec3 lcBackground;
uniform float lcStepPerRadius;
uniform float lcFarRadius;
uniform float lcFarStepPerRadius;
uniform float lcInitialStep;
uniform float lcTolerance;
uniform int lcMaxSteps;
uniform float lcConstraintTolerance;
uniform vec4 lcObserver;
uniform vec4 lcE0;
uniform vec4 lcE1;
uniform vec4 lcE2;
uniform vec4 lcE3;
uniform vec4 lcG0r0;
uniform vec4 lcG0r1;
uniform vec4 lcG0r2;
uniform vec4 lcG0r3;
