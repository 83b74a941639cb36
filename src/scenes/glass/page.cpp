#include "scenes/glass/page.h"

namespace vitrine::glass {

const std::vector<std::string>& pageParagraphs() {
  static const std::vector<std::string> paragraphs{
      "Spectral Glass",
      "Light that enters glass slows down, and how much it slows depends on its colour: blue bends more "
      "than red. This page is what the glass in front of it refracts. Every pixel that the glass covers "
      "traces the light back through it at many wavelengths, each with its own index of refraction, and "
      "adds them up through the CIE colour matching functions.",
      "Where the glass does not spread the colours apart, the wavelengths land on the same spot and the "
      "page shows through unchanged. Where they part, along every edge and rim, white paper turns into a "
      "rainbow and black type gains fringes of violet and orange.",
      "A diamond bends light so strongly that most of what enters the crown is turned back by total "
      "internal reflection from the pavilion, and comes out through the top split into its colours: the "
      "fire of a brilliant cut.",
      "Drag a shape to move it. Space shuffles them, R shows the next photo, hold Z to see three bands "
      "instead of a spectrum, and T, S, B and F turn the diamond.",
  };
  return paragraphs;
}

}  // namespace vitrine::glass
