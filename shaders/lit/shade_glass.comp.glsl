// glass (--glass compute): each pixel's glass fragments (stored by common/glass_fragments.frag), the
// nearest kGlassLayers of them, lit through the technique's lighting interface and blended over the
// lit frame farthest first, as the raster path's premultiplied blend does draw by draw. A workgroup
// shades a group of 8x8 pixels, only those with glass: it walks each layer's lights itself, or,
// where the interface splits them into parts (kGlassLightParts), adds up what glass-light lit.
#include "common/glass_layers.glsl"
#include "common/lighting.glsl"
#define LLL_DISPLAY_FROM_SHADING
#include "post/display.glsl"

layout(local_size_x = kTileGroupSize, local_size_y = kTileGroupSize) in;

layout(set = 0, binding = 13, rgba16f) uniform image2D hdr;

// The light on a layer: its lights walked here, or glass-light's parts added up in part order.
vec3 layerLight(Surface s, uvec2 pixel, float viewDepth, uint node) {
  if (kGlassLightParts == 0u) return lightSurface(s, pixel, viewDepth);
  vec3 sum = vec3(0.0);
  for (uint part = 0u; part < kGlassLightParts; ++part) sum += glassLight[node * kGlassLightParts + part].rgb;
  return sum;
}

// Pixel `pixel`'s glass over what is behind it; its list head cleared for the next frame.
void shadeGlassPixel(uvec2 pixel) {
  uint headIndex = glassHeadIndex(pixel);
  uint nodes[kGlassLayers], listed;
  uint count = nearestGlassLayers(glassHeads[headIndex], nodes, listed);
  glassHeads[headIndex] = kGlassListEnd;
  if (listed == 0u) return;
  atomicMax(glassCounters.deepest, listed);
  vec4 color = imageLoad(hdr, ivec2(pixel));
  for (uint i = count; i-- > 0u;) {
    GlassFragment f = glassFragments[nodes[i]];
    Surface s = glassSurface(f);
    float depth = f.positionDepth.w;
    bool replaced;
    vec3 lit =
        lightingView(s, pixel, depth, f.unlitRoughness.rgb + layerLight(s, pixel, depth, nodes[i]), replaced);
    float alpha = replaced ? 1.0 : s.alpha;
    color = vec4(lit * alpha, alpha) + color * (1.0 - alpha);  // premultiplied over
  }
  imageStore(hdr, ivec2(pixel), color);
  storeDisplay(ivec2(pixel), color.rgb);
}

// One workgroup per group of 8x8 pixels with glass (listed by glass-groups).
void main() {
  uvec2 pixel = glassGroupOrigin() + gl_LocalInvocationID.xy;
  if (pixel.x < uint(frame.viewport.x) && pixel.y < uint(frame.viewport.y)) shadeGlassPixel(pixel);
}
