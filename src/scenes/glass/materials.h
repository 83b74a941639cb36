#pragma once
// The glass scene's material table: the original's fifteen (eleven real media, water to moissanite, then
// four invented ones that disperse far more than anything transparent does, for the look), each with the
// original's n_d and V_d, and two more real glasses beside them. n_d is the index at the helium d line
// (587.56 nm), V_d the Abbe number (n_d - 1) / (n_F - n_C). Where a Sellmeier law is published it is
// carried too (dispersion=sellmeier); the original's rounded handbook figures agree with those laws to
// 1e-3 in n_d and 1.5 % in V_d, except cubic zirconia's gem-trade 2.150 / 30, which the single crystal
// Wood and Nassau measured (2.1588 / 33.5) does not quite match: yttria content moves both.
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

// The original's order (by n_d within each group), its figures as it printed them; then the extras.
// Moissanite (6H-SiC) and the plastics and lead crystal have no law here.
inline constexpr size_t kOriginalMaterials = 15;
inline constexpr std::array<Material, 17> kMaterials{{
    {"water", "Water", 1.333f, 55.7f, std::nullopt},
    {"fused_silica", "Fused silica", 1.458f, 67.7f, kSellmeierFusedSilica},
    {"acrylic", "PMMA (acrylic)", 1.491f, 58.0f, std::nullopt},
    {"bk7", "Crown (BK7)", 1.517f, 64.2f, kSellmeierBk7},
    {"polycarbonate", "Polycarbonate", 1.586f, 30.0f, std::nullopt},
    {"lead_crystal", "Lead crystal", 1.600f, 32.0f, std::nullopt},
    {"sf10", "Flint (SF10)", 1.728f, 28.4f, std::nullopt},
    {"sf11", "Dense flint (SF11)", 1.785f, 25.4f, kSellmeierSf11},
    {"cubic_zirconia", "Cubic zirconia", 2.150f, 30.0f, kSellmeierCubicZirconia},
    {"diamond", "Diamond", 2.418f, 55.0f, kSellmeierDiamond},
    {"moissanite", "Moissanite", 2.648f, 31.0f, std::nullopt},
    // Invented: only the Cauchy law applies. Rainbow soap is the original demo's cube look.
    {"rainbow_glass", "Rainbow glass", 1.55f, 8.0f, std::nullopt, true},
    {"fire_crystal", "Fire crystal", 2.2f, 12.0f, std::nullopt, true},
    {"unobtanium", "Unobtanium", 3.2f, 4.0f, std::nullopt, true},
    {"rainbow_soap", "Rainbow soap", 1.272f, 2.0f, std::nullopt, true},
    // Beside the original's: two more real glasses whose laws are published (their n_d and V_d are the laws').
    {"f2", "Flint glass F2", 1.62004f, 36.37f, kSellmeierF2},
    {"sapphire", "Sapphire", 1.7682f, 72.31f, kSellmeierSapphire},
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
