// The sRGB transfer function and its inverse (IEC 61966-2-1), as an sRGB image format applies them:
// for targets that cannot have an sRGB format (storage images) and for the display encoding.
#ifndef LLL_SRGB_GLSL
#define LLL_SRGB_GLSL

vec3 srgbEncode(vec3 linear) {
  vec3 c = clamp(linear, 0.0, 1.0);
  return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, greaterThan(c, vec3(0.0031308)));
}

vec3 srgbDecode(vec3 encoded) {
  return mix(encoded / 12.92, pow((encoded + 0.055) / 1.055, vec3(2.4)), greaterThan(encoded, vec3(0.04045)));
}

#endif
