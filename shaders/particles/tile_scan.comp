#version 460
#define PARTICLE_TILES_WRITE
// particles-bin's prefix sum of the cells' counts into their first entries and cursors, in blocks of
// kParticleScanBlock cells (one workgroup each), in three steps (specialization constant 0):
//   0 each block sums its cells (blockSums: x the sum, y the same sum in float, which tells a total
//     past 2^32);
//   1 one workgroup turns the block sums into each block's first entry, and the total into the
//     header (`requested`: the scatter's capacity check and the CPU's overflow check read it);
//   2 each block scans its cells from its first entry.
// The light bins' scan (lighting/bins/bin_scan.comp) runs in one workgroup: a few hundred cells
// there, but one per tile and slab here (130,560 for 65,536 particles at 1080p, 522,240 for a
// million). On the H200 in one workgroup particles-bin took 0.70 ms for 65,536 smoke particles at
// 1080p and 0.39 for the sparks' 49,146, in blocks 0.35 and 0.05.
#define PARTICLE_TILE_BLOCKS
#include "particles/tiles.glsl"

layout(local_size_x = 256) in;
layout(constant_id = 0) const uint kStep = 0u;
const uint kThreads = 256u;
const uint kPerThread = kParticleScanBlock / kThreads;

shared uint sums[kThreads];
shared float approxSums[kThreads];

// Hillis-Steele inclusive scan of sums over the workgroup, and of approxSums with `approx` (the same
// in every invocation).
void scanShared(bool approx) {
  uint i = gl_LocalInvocationIndex;
  for (uint offset = 1u; offset < kThreads; offset <<= 1u) {
    uint add = i >= offset ? sums[i - offset] : 0u;
    float addApprox = approx && i >= offset ? approxSums[i - offset] : 0.0;
    barrier();
    sums[i] += add;
    if (approx) approxSums[i] += addApprox;
    barrier();
  }
}

void main() {
  uint cells = tileHeader.cellsX * tileHeader.cellsY;
  uint i = gl_LocalInvocationIndex;
  if (kStep == 0u) {
    // Consecutive invocations read consecutive cells.
    uint base = gl_WorkGroupID.x * kParticleScanBlock;
    uint sum = 0u;
    for (uint k = 0u; k < kPerThread; ++k) {
      uint c = base + k * kThreads + i;
      if (c < cells) sum += tileCells[c].count;
    }
    sums[i] = sum;
    approxSums[i] = float(sum);
    barrier();
    for (uint stride = kThreads / 2u; stride > 0u; stride >>= 1u) {
      if (i < stride) {
        sums[i] += sums[i + stride];
        approxSums[i] += approxSums[i + stride];
      }
      barrier();
    }
    if (i == 0u) tileBlockSums[gl_WorkGroupID.x] = uvec2(sums[0], floatBitsToUint(approxSums[0]));
  } else if (kStep == 1u) {
    // Each invocation a run of consecutive blocks.
    uint blocks = (cells + kParticleScanBlock - 1u) / kParticleScanBlock;
    uint perThread = (blocks + kThreads - 1u) / kThreads;
    uint begin = min(i * perThread, blocks), end = min(begin + perThread, blocks);
    uint sum = 0u;
    float approx = 0.0;
    for (uint b = begin; b < end; ++b) {
      sum += tileBlockSums[b].x;
      approx += uintBitsToFloat(tileBlockSums[b].y);
    }
    sums[i] = sum;
    approxSums[i] = approx;
    barrier();
    scanShared(true);
    uint first = sums[i] - sum;
    for (uint b = begin; b < end; ++b) {
      uint own = tileBlockSums[b].x;
      tileBlockSums[b].x = first;
      first += own;
    }
    // A total past 2^31 entries fits no storage buffer: ask for the most, which the CPU refuses.
    if (i == kThreads - 1u) tileHeader.requested = approxSums[i] >= 2147483648.0 ? 0xFFFFFFFFu : sums[i];
  } else {
    // Each invocation kPerThread consecutive cells.
    uint base = gl_WorkGroupID.x * kParticleScanBlock + i * kPerThread;
    uint counts[kPerThread];
    uint sum = 0u;
    for (uint k = 0u; k < kPerThread; ++k) {
      counts[k] = base + k < cells ? tileCells[base + k].count : 0u;
      sum += counts[k];
    }
    sums[i] = sum;
    barrier();
    scanShared(false);
    uint first = tileBlockSums[gl_WorkGroupID.x].x + sums[i] - sum;
    for (uint k = 0u; k < kPerThread; ++k) {
      if (base + k >= cells) break;
      tileCells[base + k].first = first;
      tileCells[base + k].cursor = first;
      first += counts[k];
    }
  }
}
