// The options that name one of a few choices (core/enum_names.h): each enum's names are the ones
// its CLI option, its menu in the viewer and the bench's reports use, so every name must parse back
// to its own value, no two values may share a name, and what is not a name must not parse.
#include <gtest/gtest.h>

#include <cctype>
#include <set>
#include <string>

#include "cli_test_support.h"
#include "render/settings.h"
#include "scene/scene_source.h"

namespace lll {
namespace {

template <NamedEnum E>
void expectNamesRoundTrip(const char* option) {
  SCOPED_TRACE(option);
  const auto& names = EnumNames<E>::names;
  std::set<std::string_view> seen;
  for (size_t i = 0; i < names.size(); ++i) {
    const E value = static_cast<E>(i);
    EXPECT_FALSE(names[i].empty());
    EXPECT_TRUE(seen.insert(names[i]).second) << names[i] << " names two values";
    EXPECT_EQ(enumFromName<E>(names[i]), value) << names[i];
    EXPECT_EQ(nameOf(value), names[i]);
    EXPECT_EQ(fmt::format("{}", value), names[i]);
    for (const char c : names[i])
      EXPECT_TRUE(std::islower(static_cast<unsigned char>(c)) || c == '-') << names[i] << ": a CLI word";
    // Names are matched exactly: no case folding, no prefixes, no padding.
    std::string upper(names[i]);
    upper[0] = char(std::toupper(static_cast<unsigned char>(upper[0])));
    EXPECT_EQ(enumFromName<E>(upper), std::nullopt) << upper;
    EXPECT_EQ(enumFromName<E>(names[i].substr(0, names[i].size() - 1)), std::nullopt) << names[i];
    EXPECT_EQ(enumFromName<E>(std::string(names[i]) + " "), std::nullopt) << names[i];
  }
  EXPECT_EQ(enumFromName<E>(""), std::nullopt);
  EXPECT_EQ(enumFromName<E>("nosuch"), std::nullopt);
}

TEST(EnumNames, EveryOptionsNamesParseBackToTheirValues) {
  expectNamesRoundTrip<LightPlacement>("--light-motion");
  expectNamesRoundTrip<LllFill>("--lll-fill");
  expectNamesRoundTrip<LllLink>("--lll-link");
  expectNamesRoundTrip<LllRecords>("--lll-records");
  expectNamesRoundTrip<LllShade>("--lll-shade");
  expectNamesRoundTrip<SurfaceSource>("--surfaces");
  expectNamesRoundTrip<GlassLighting>("--glass");
  expectNamesRoundTrip<RasterChoice>("--raster");
  expectNamesRoundTrip<DebugView>("--debug-view");
  expectNamesRoundTrip<TranslucentLighting>("--deferred-translucent");
  expectNamesRoundTrip<AntiAliasing>("--aa");
  expectNamesRoundTrip<ParticleLighting>("--particle-lighting");
  expectNamesRoundTrip<ParticleRender>("--particle-render");
  expectNamesRoundTrip<ParticleResolution>("--particle-resolution");
  expectNamesRoundTrip<ShadowMode>("--shadows");
  expectNamesRoundTrip<ShadowFilter>("--shadow-filter");
  expectNamesRoundTrip<GiMode>("--gi");
  expectNamesRoundTrip<GiHierarchy>("--vpl-hierarchy");
}

TEST(EnumNames, ChoicesReadAsAList) {
  EXPECT_EQ(enumChoices<LllFill>(), "shells, ray or compute");
  EXPECT_EQ(enumChoices<GiHierarchy>(), "none or grid");
  EXPECT_EQ(enumChoices<DebugView>(), "none, heatmap, bounds or tiles");
}

TEST(EnumNames, ParticleResolutionScales) {
  EXPECT_EQ(particleResolutionScale(ParticleResolution::Full), 1u);
  EXPECT_EQ(particleResolutionScale(ParticleResolution::Half), 2u);
  EXPECT_EQ(particleResolutionScale(ParticleResolution::Quarter), 4u);
}

// The CLI offers exactly the enum's names: `render --help` shows the check CLI11 runs for each.
template <NamedEnum E>
void expectHelpOffers(const std::string& help, const std::string& option) {
  std::string list;
  for (const std::string_view name : EnumNames<E>::names)
    list += (list.empty() ? "" : ",") + std::string(name);
  EXPECT_NE(help.find(option + " TEXT:{" + list + "}"), std::string::npos) << option << " {" << list << "}";
}

TEST(EnumNames, RenderHelpOffersEveryName) {
  const test::CliResult r = test::runLll({"render", "--help"});
  ASSERT_EQ(r.exitCode, 0) << r;
  expectHelpOffers<LightPlacement>(r.output, "--light-motion");
  expectHelpOffers<LllFill>(r.output, "--lll-fill");
  expectHelpOffers<LllLink>(r.output, "--lll-link");
  expectHelpOffers<LllRecords>(r.output, "--lll-records");
  expectHelpOffers<LllShade>(r.output, "--lll-shade");
  expectHelpOffers<SurfaceSource>(r.output, "--surfaces");
  expectHelpOffers<GlassLighting>(r.output, "--glass");
  expectHelpOffers<RasterChoice>(r.output, "--raster");
  expectHelpOffers<RasterChoice>(r.output, "--shadow-raster");
  expectHelpOffers<DebugView>(r.output, "--debug-view");
  expectHelpOffers<TranslucentLighting>(r.output, "--deferred-translucent");
  expectHelpOffers<AntiAliasing>(r.output, "--aa");
  expectHelpOffers<ParticleLighting>(r.output, "--particle-lighting");
  expectHelpOffers<ParticleRender>(r.output, "--particle-render");
  expectHelpOffers<ParticleResolution>(r.output, "--particle-resolution");
  expectHelpOffers<ShadowMode>(r.output, "--shadows");
  expectHelpOffers<ShadowFilter>(r.output, "--shadow-filter");
  expectHelpOffers<GiMode>(r.output, "--gi");
  expectHelpOffers<GiHierarchy>(r.output, "--vpl-hierarchy");
}

}  // namespace
}  // namespace lll
