#pragma once
// From light signals to DMX: each fixture's colours (its signal's, after the master dimmer), then the
// bytes of every universe the patch uses. Pure; the lights thread runs it (lights/lights.h).
#include "lights/patch.h"
#include "lights/signals.h"

#include <array>
#include <cstdint>
#include <map>
#include <vector>

namespace vitrine::lights {

using Universe = std::array<uint8_t, kUniverseChannels>;  // channel 1 is [0]
using Universes = std::map<uint32_t, Universe>;

// Every light of the patch in order (a strip's pixels one by one), linear RGB 0..1 times `master`. A
// fixture shows its signal's colours from `index` on: one colour, or a strip's pixels spread over the
// rest of the signal (an 8x1 grid on a 60-pixel strip: each region over 7 or 8 pixels). A signal not
// published this frame, or an index past its colours, leaves the light dark.
std::vector<glm::vec3> lightColours(const Patch& patch, const Signals& signals, float master);

// The DMX values of each universe the patch uses, from lightColours' order: RGB as three channels,
// RGBW with the white the three share taken out onto W, a dimmer the colour's relative luminance.
// Channels no fixture uses are 0.
Universes pack(const Patch& patch, const std::vector<glm::vec3>& colours);

// A channel's value for a level 0..1, rounded.
uint8_t dmxLevel(float level);
// A 16-bit pair (coarse at channel C, fine at C+1) as a source's 0..1, and a level as such a pair.
float pairLevel(uint8_t coarse, uint8_t fine);
std::array<uint8_t, 2> levelPair(float level);

}  // namespace vitrine::lights
