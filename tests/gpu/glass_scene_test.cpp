// The glass scene as a whole, rendered headless: the physics it promises, measured on its pictures.
#include "host/offscreen.h"
#include "support/gpu_test.h"

#include <algorithm>

namespace vitrine::test {
namespace {

class GlassScene : public GpuTest {
 protected:
  ImageRgba render(params::KeyValues values, uint32_t frames = 4) {
    host::OffscreenConfig config;
    config.scene = "glass";
    config.size = {240, 200};
    config.startTime = 0.5;
    config.parameters = {{"background", "checker"}, {"jitter", "off"}};
    config.parameters.insert(config.parameters.end(), values.begin(), values.end());
    host::Offscreen offscreen(device(), config);
    for (uint32_t i = 0; i < frames; ++i) offscreen.renderFrame();
    return offscreen.readback();
  }
};

// How coloured the picture is: over a grey checker, every bit of chroma is dispersion.
double meanChroma(const ImageRgba& image) {
  double sum = 0.0;
  for (size_t i = 0; i < image.pixels.size(); i += 4) {
    const float* p = &image.pixels[i];
    sum += std::max({p[0], p[1], p[2]}) - std::min({p[0], p[1], p[2]});
  }
  return sum / double(image.width * image.height);
}

double meanDifference(const ImageRgba& a, const ImageRgba& b) {
  double sum = 0.0;
  for (size_t i = 0; i < a.pixels.size(); ++i) sum += std::abs(a.pixels[i] - b.pixels[i]);
  return sum / double(a.pixels.size());
}

TEST_F(GlassScene, AVeryLargeAbbeNumberRemovesTheFringesASmallOneMakes) {
  const double dispersive = meanChroma(render({{"abbe", "2"}}));
  const double plain = meanChroma(render({{"abbe", "100"}}));
  EXPECT_GT(dispersive, 0.01) << "V_d = 2 should split the checker's edges into colours";
  EXPECT_LT(plain, dispersive * 0.05) << "V_d = 100 should leave the grey checker grey";
}

TEST_F(GlassScene, GlassOfIndexOneIsInvisible) {
  // Exact Fresnel reflects nothing at eta = 1 and nothing bends: wherever the cubes or the pills are,
  // the picture is the backdrop's (a smooth one: the original's LOD rule blurs a checker at rims).
  const ImageRgba cubes = render({{"optics", "physical"}, {"ior", "1"}, {"shape", "cube"}, {"background", "gradient"}});
  const ImageRgba pills = render({{"optics", "physical"}, {"ior", "1"}, {"shape", "pill"}, {"background", "gradient"}});
  EXPECT_LT(meanDifference(cubes, pills), 2e-4);
  const ImageRgba glass = render({{"optics", "physical"}, {"ior", "1.5"}, {"shape", "cube"}, {"background", "gradient"}});
  EXPECT_GT(meanDifference(cubes, glass), 2e-3) << "real glass must change the picture";
}

}  // namespace
}  // namespace vitrine::test
