// mirrors lc::dayNightColour (core/scene/scene.hpp): the day colour times the light (which already
// holds the 0.08 ambient term), plus the night colour where the light is below 1/5.
vec3 lcDayNight(vec3 day, vec3 night, vec3 light)
{
  float lum = dot(light - vec3(0.08), vec3(0.2126, 0.7152, 0.0722));
  return day * light + night * clamp(1.0 - 5.0 * lum, 0.0, 1.0);
}
