// SPDX-License-Identifier: BSD-3-Clause
// mirrors vtkLightconeSrMapper::SetMapperShaderParameters (views/): the uniforms of both
// special-relativity techniques' shaders (vertex and fragment), set on their program at each draw.
// (The camera's are glsl/camera_uniforms.)
// the object (lc::sr::SrObject: its frame's velocity, the observer event in its rest frame,
// ambient / diffuse / specular / shininess, emitter temperature; index for the id pass)
uniform vec3 lcBeta;
uniform vec4 lcObserverRest;
uniform vec4 lcMaterial;
uniform float lcTemperature;
uniform float lcObjectId;
// the light and the options (lc::sr::SrScene, lc::sr::SrRenderOptions)
uniform vec3 lcLightRel;
uniform float lcLightT;
uniform int lcShading;
uniform int lcDoppler;
uniform int lcReflected;
uniform int lcIdPass;
uniform float lcDepthScale;
uniform int lcVertexDoppler;
