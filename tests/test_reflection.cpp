// Pipeline layouts come from the shaders' SPIR-V: the reflection must read the bindings, types,
// stages and push-constant sizes the GLSL declares.
#include <gtest/gtest.h>

#include "gpu/reflection.h"
#include "gpu/shader_registry.h"
#include "shared/gpu_types.h"

namespace lll {
namespace {

ShaderInterface reflect(const char* path) {
  return reflectShader(shaderCode(path), path);
}

TEST(Reflection, TonemapReadsHdrAndWritesLdrAsStorageImages) {
  const ShaderInterface tonemap = reflect("post/tonemap.comp");
  EXPECT_EQ(tonemap.stages, VkShaderStageFlags(VK_SHADER_STAGE_COMPUTE_BIT));
  const ReflectedBinding* hdr = tonemap.find(0, 1);
  const ReflectedBinding* ldr = tonemap.find(0, 2);
  ASSERT_NE(hdr, nullptr);
  ASSERT_NE(ldr, nullptr);
  EXPECT_EQ(hdr->type, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE);
  EXPECT_EQ(hdr->name, "hdrImage");
  EXPECT_EQ(ldr->type, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE);
  EXPECT_EQ(tonemap.pushConstantBytes, 0u);
}

TEST(Reflection, MeshPassMergesStagesAndSizesThePushConstants) {
  const ShaderInterface vertex = reflect("common/mesh.vert");
  const ShaderInterface fragment = reflect("lit/forward/shade_geometry.frag");
  EXPECT_EQ(fragment.pushConstantBytes, sizeof(gpu::DrawPush));  // the material index
  const ShaderInterface mesh = mergeInterfaces({vertex, fragment});
  EXPECT_EQ(mesh.stages, VkShaderStageFlags(VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT));
  // The frame constants are read by both stages; the material textures (set 1) by the fragment.
  const ReflectedBinding* frame = mesh.find(0, 0);
  ASSERT_NE(frame, nullptr);
  EXPECT_EQ(frame->stages, VkShaderStageFlags(VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT));
  const std::vector<ReflectedBinding> textures = mesh.set(1);
  ASSERT_EQ(textures.size(), 5u);
  for (uint32_t i = 0; i < 5; ++i) {
    EXPECT_EQ(textures[i].binding, i);
    EXPECT_EQ(textures[i].type, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER);
    EXPECT_EQ(textures[i].stages, VkShaderStageFlags(VK_SHADER_STAGE_FRAGMENT_BIT));
  }
  EXPECT_EQ(mesh.pushConstantStages, VkShaderStageFlags(VK_SHADER_STAGE_FRAGMENT_BIT));  // who declares them
}

TEST(Reflection, ConflictingStagesAreABug) {
  ShaderInterface a, b;
  a.bindings = {{0, 3, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT, "lights"}};
  b.bindings = {{0, 3, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, 1, VK_SHADER_STAGE_FRAGMENT_BIT, "depth"}};
  EXPECT_THROW(mergeInterfaces({a, b}), std::logic_error);
}

TEST(Reflection, GarbageIsNotSpirv) {
  const uint32_t words[] = {1, 2, 3, 4, 5, 6};
  EXPECT_THROW(reflectShader(words, "garbage"), std::runtime_error);
}

}  // namespace
}  // namespace lll
