#version 460
#define LLL_BINS_WRITE
// Exclusive prefix sum of the cells' counts into their first entries (one workgroup; each thread
// sums a run of consecutive cells, then the runs' totals are scanned in shared memory), and the
// total into the header: the scatter's capacity check and the CPU's overflow check read it.
#include "common/light_bins.glsl"

layout(local_size_x = 256) in;
shared uint runTotals[256];
shared float runTotalsApprox[256];  // the same sums in float: tells a total past 2^32 (wrapped)

void main() {
  uint cells = binHeader.cellsX * binHeader.cellsY;
  uint perThread = (cells + 255u) / 256u;
  uint begin = min(gl_LocalInvocationIndex * perThread, cells);
  uint end = min(begin + perThread, cells);
  uint sum = 0u;
  float approx = 0.0;
  for (uint c = begin; c < end; ++c) {
    sum += binCells[c].count;
    approx += float(binCells[c].count);
  }
  runTotals[gl_LocalInvocationIndex] = sum;
  runTotalsApprox[gl_LocalInvocationIndex] = approx;
  barrier();
  // Hillis-Steele inclusive scan over the 256 run totals.
  for (uint offset = 1u; offset < 256u; offset <<= 1u) {
    bool take = gl_LocalInvocationIndex >= offset;
    uint add = take ? runTotals[gl_LocalInvocationIndex - offset] : 0u;
    float addApprox = take ? runTotalsApprox[gl_LocalInvocationIndex - offset] : 0.0;
    barrier();
    runTotals[gl_LocalInvocationIndex] += add;
    runTotalsApprox[gl_LocalInvocationIndex] += addApprox;
    barrier();
  }
  uint first = runTotals[gl_LocalInvocationIndex] - sum;
  for (uint c = begin; c < end; ++c) {
    binCells[c].first = first;
    binCells[c].cursor = first;
    first += binCells[c].count;
  }
  // A total past 2^31 entries fits no storage buffer: ask for the most, which the CPU refuses.
  if (gl_LocalInvocationIndex == 255u)
    binHeader.requested = runTotalsApprox[255] >= 2147483648.0 ? 0xFFFFFFFFu : runTotals[255];
}
