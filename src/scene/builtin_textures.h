#pragma once
// Small procedural textures for the built-in scenes, so that they need no image files. Each one is
// 256 x 256 RGBA8, tiles seamlessly, and is the same on every machine (hashed noise, no RNG).
#include "scene/scene.h"

namespace lll::builtin {

// sRGB base colours. Scale: the uvPerMetre each is drawn for is given beside it.
Texture makeFloorTilesTexture();  // 4 x 4 checkered stone slabs; 0.25 per metre = 1 m slabs
Texture makeAshlarTexture();      // sandstone blocks in running bond; 0.5 per metre
Texture makePlasterTexture();     // mottled lime plaster; 0.25 per metre
Texture makeWoodTexture();        // planks along v; 0.5 per metre
Texture makeMarbleTexture();      // veined white marble; 0.5 per metre
// A banner's cloth over the whole banner (UV 0..1): a weave, a dark border and a pale emblem,
// grey so that the material's base colour gives the hue.
Texture makeBannerTexture();

}  // namespace lll::builtin
