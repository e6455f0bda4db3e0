// Index arithmetic of a bitonic sorting network, shared by the particle sort (sort_pairs.glsl) and
// the tile sort of the compute particle renderer (lit/particles_tiles.comp.glsl).
#ifndef LLL_BITONIC_GLSL
#define LLL_BITONIC_GLSL

// Thread t's pair in a step of compare distance j: the lower element i and its partner i + j.
uint lowerIndex(uint t, uint j) {
  return 2u * j * (t / j) + (t % j);
}

#endif
