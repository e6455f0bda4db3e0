// Colours of the debug views, shared by the views and the tonemap pass's legend.
#ifndef LLL_DEBUG_COLORS_GLSL
#define LLL_DEBUG_COLORS_GLSL

// Blue (few) through green to red (many), as ThreeL's light-count heatmap.
vec3 heat(float t) {
  t = clamp(t, 0.0, 1.0);
  return t < 0.5 ? mix(vec3(0.0, 0.0, 1.0), vec3(0.0, 1.0, 0.0), t * 2.0)
                 : mix(vec3(0.0, 1.0, 0.0), vec3(1.0, 0.0, 0.0), t * 2.0 - 1.0);
}

#endif
