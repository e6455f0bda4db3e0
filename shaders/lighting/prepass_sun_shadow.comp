#version 460
// Light pre-pass, the sun's shadow as Resistance 2 kept it: a screen-space buffer, 8 bits a pixel,
// of how much of the sun reaches each pixel's surface, written once before the combine pass reads
// it (lighting/prepass_combine.frag). Resistance 2 drew each cascade's region over the screen and
// min-blended the results; here one compute pass picks each pixel's cascade directly, so there is
// nothing to blend. The surface comes back from the pre-pass's own buffers: the position from the
// depth, the normal from the stored surface.
#extension GL_EXT_samplerless_texture_functions : require
#include "common/gbuffer.glsl"
#include "common/sun_shadow.glsl"
#include "lighting/prepass_terms.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 5) uniform texture2D depthImage;
layout(set = 0, binding = 6) uniform utexture2D surfaceBuffer;
layout(set = 0, binding = 7, r8) uniform writeonly image2D sunShadowBuffer;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(vec2(pixel), frame.viewport.xy))) return;
  float depth = texelFetch(depthImage, pixel, 0).r;
  float visible = 1.0;
  if (depth > 0.0 && frame.display.z > 0u) {
    PrepassSurface stored = unpackPrepassSurface(texelFetch(surfaceBuffer, pixel, 0).xy);
    vec3 n = normalize(stored.viewNormal * mat3(frame.view));  // view to world: the rotation's transpose
    visible = sunVisibleAt(reconstructPosition(vec2(pixel) + 0.5, linearizeDepth(depth)), n);
  }
  imageStore(sunShadowBuffer, pixel, vec4(visible));
}
