// meshoptimizer's analysis of the order of every primitive of the scenes named on the command line
// (issue 11: "meshoptimizer ... for vertex fetch/cache order if it helps"): the post-transform
// cache miss ratios (ACMR: vertices shaded per triangle; ATVR: per vertex) and the vertex-fetch
// overfetch as loaded, then after meshopt_optimizeVertexCache and meshopt_optimizeVertexFetch,
// weighted by triangles. Each primitive's vertex range is taken as [its least index, its largest].
// Built against the repository's build by build.sh; a measurement, not part of the product.
#include <meshoptimizer.h>

#include <fmt/format.h>
#include <algorithm>

#include "scene/scene_source.h"

int main(int argc, char** argv) {
  for (int a = 1; a < argc; ++a) {
    lll::SceneRequest request;
    request.scene = argv[a];
    const lll::Scene scene = lll::loadScene(request);
    double triangles = 0, acmr[2] = {0, 0}, atvr[2] = {0, 0}, overfetch[2] = {0, 0};
    size_t primitives = 0;
    for (const lll::Mesh& mesh : scene.meshes)
      for (const lll::Primitive& p : mesh.primitives) {
        if (p.indexCount < 3) continue;
        std::vector<unsigned> loaded(scene.indices.begin() + p.firstIndex,
                                     scene.indices.begin() + p.firstIndex + p.indexCount);
        const unsigned lo = *std::min_element(loaded.begin(), loaded.end());
        const unsigned hi = *std::max_element(loaded.begin(), loaded.end());
        for (unsigned& i : loaded) i -= lo;
        const size_t count = hi - lo + 1;
        const lll::Vertex* vertices = scene.vertices.data() + p.vertexOffset + lo;
        std::vector<unsigned> optimized(loaded.size());
        meshopt_optimizeVertexCache(optimized.data(), loaded.data(), loaded.size(), count);
        std::vector<lll::Vertex> reordered(count);
        meshopt_optimizeVertexFetch(reordered.data(), optimized.data(), optimized.size(), vertices, count,
                                    sizeof(lll::Vertex));
        const double t = double(loaded.size()) / 3.0;
        const std::vector<unsigned>* orders[2] = {&loaded, &optimized};
        for (int o = 0; o < 2; ++o) {
          const auto cache =
              meshopt_analyzeVertexCache(orders[o]->data(), orders[o]->size(), count, 32, 32, 32);
          const auto fetch =
              meshopt_analyzeVertexFetch(orders[o]->data(), orders[o]->size(), count, sizeof(lll::Vertex));
          acmr[o] += cache.acmr * t;
          atvr[o] += cache.atvr * t;
          overfetch[o] += fetch.overfetch * t;
        }
        triangles += t;
        ++primitives;
      }
    fmt::print(
        "{}: {} primitives, {} triangles, {} vertices; ACMR {:.3f} -> {:.3f}, ATVR {:.3f} -> {:.3f}, "
        "overfetch {:.3f} -> {:.3f}\n",
        argv[a], primitives, triangles, scene.vertices.size(), acmr[0] / triangles, acmr[1] / triangles,
        atvr[0] / triangles, atvr[1] / triangles, overfetch[0] / triangles, overfetch[1] / triangles);
  }
}
