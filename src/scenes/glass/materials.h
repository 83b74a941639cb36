#pragma once
// The glass scene's material table: eleven real media, then four invented ones that disperse far more
// than anything transparent does, for the look. n_d is the index at the helium d line (587.56 nm), V_d the
// Abbe number (n_d - 1) / (n_F - n_C). Where a Sellmeier law is published it is carried too, and the
// table's n_d and V_d are what that law gives (the unit tests hold them to it).
#include "scenes/glass/optics.h"

#include <array>
#include <optional>
#include <string_view>

namespace vitrine::glass {

struct Material {
  std::string_view key;    // lowercase, for settings and the command line
  std::string_view label;  // for the panel
  float nd;
  float vd;
  std::optional<Sellmeier> sellmeier;
  bool fantasy = false;
};

// Sellmeier coefficients. Malitson's papers give sqrt(C_i) in um; they are squared here to the digits printed.
// SCHOTT optical glass catalogue (2017 data sheets).
inline constexpr Sellmeier kSellmeierBk7{{1.03961212f, 0.231792344f, 1.01046945f},
                                         {0.00600069867f, 0.0200179144f, 103.560653f}};
inline constexpr Sellmeier kSellmeierF2{{1.34533359f, 0.209073176f, 0.937357162f},
                                        {0.00997743871f, 0.0470450767f, 111.886764f}};
inline constexpr Sellmeier kSellmeierSf11{{1.73759695f, 0.313747346f, 1.89878101f},
                                          {0.013188707f, 0.0623068142f, 155.23629f}};
// I. H. Malitson, "Interspecimen comparison of the refractive index of fused silica", JOSA 55, 1965.
inline constexpr Sellmeier kSellmeierFusedSilica{
    {0.6961663f, 0.4079426f, 0.8974794f}, {0.0684043f * 0.0684043f, 0.1162414f * 0.1162414f, 9.896161f * 9.896161f}};
// I. H. Malitson, "Refraction and dispersion of synthetic sapphire", JOSA 52, 1962: the ordinary ray.
inline constexpr Sellmeier kSellmeierSapphire{
    {1.4313493f, 0.65054713f, 5.3414021f}, {0.0726631f * 0.0726631f, 0.1193242f * 0.1193242f, 18.028251f * 18.028251f}};
// Cubic zirconia (yttria-stabilised): D. L. Wood and K. Nassau, Applied Optics 21, 1982.
inline constexpr Sellmeier kSellmeierCubicZirconia{
    {1.347091f, 2.117788f, 9.452943f}, {0.062543f * 0.062543f, 0.166739f * 0.166739f, 24.320570f * 24.320570f}};
// Diamond: F. Peter, Zeitschrift fuer Physik 15, 1923, the usual two-term form (third term empty).
inline constexpr Sellmeier kSellmeierDiamond{{0.3306f, 4.3356f, 0.0f}, {0.1750f * 0.1750f, 0.1060f * 0.1060f, 0.0f}};

// Ordered by n_d within each group. Values without a Sellmeier law are handbook figures: water at 20 C,
// PMMA and polycarbonate as optical-plastic suppliers list them. Moissanite (6H-SiC, ordinary ray):
// n_d 2.648, and V_d from its usual gem dispersion n_G - n_B = 0.104 (430.8 / 686.7 nm) carried through
// the same Cauchy law, which gives n_F - n_C = 0.061 and V_d = 27.
inline constexpr std::array<Material, 15> kMaterials{{
    {"water", "Water", 1.333f, 55.7f, std::nullopt},
    {"fused_silica", "Fused silica", 1.4585f, 67.82f, kSellmeierFusedSilica},
    {"acrylic", "Acrylic (PMMA)", 1.491f, 57.4f, std::nullopt},
    {"bk7", "Crown glass N-BK7", 1.5168f, 64.17f, kSellmeierBk7},
    {"polycarbonate", "Polycarbonate", 1.585f, 29.9f, std::nullopt},
    {"f2", "Flint glass F2", 1.62004f, 36.37f, kSellmeierF2},
    {"sapphire", "Sapphire", 1.7682f, 72.31f, kSellmeierSapphire},
    {"sf11", "Dense flint N-SF11", 1.78472f, 25.68f, kSellmeierSf11},
    {"cubic_zirconia", "Cubic zirconia", 2.1588f, 33.54f, kSellmeierCubicZirconia},
    {"diamond", "Diamond", 2.4175f, 55.3f, kSellmeierDiamond},
    {"moissanite", "Moissanite", 2.648f, 27.0f, std::nullopt},
    // Invented: only the Cauchy law applies. Opaline is the original demo's cube look.
    {"opaline", "Opaline", 1.272f, 2.0f, std::nullopt, true},
    {"hyperflint", "Hyperflint", 1.8f, 4.0f, std::nullopt, true},
    {"starglass", "Starglass", 2.8f, 8.0f, std::nullopt, true},
    {"void_crystal", "Void crystal", 3.5f, 2.0f, std::nullopt, true},
}};

// The material with this key, or nullptr.
inline const Material* findMaterial(std::string_view key) {
  for (const Material& m : kMaterials)
    if (m.key == key) return &m;
  return nullptr;
}

// The material's index at lambda: its Sellmeier law when asked for and published, else Cauchy from (n_d, V_d).
inline float materialIor(const Material& m, float lambdaNm, bool useSellmeier) {
  return useSellmeier && m.sellmeier ? sellmeierIor(lambdaNm, *m.sellmeier) : cauchyIor(lambdaNm, m.nd, m.vd);
}

}  // namespace vitrine::glass
