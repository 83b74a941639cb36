// PNG files as Vitrine reads them: readPicture, for glass' backdrops (fetched photos or a path).
#include "support/image_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  vitrine::fuzz::readAsBackdrop("input.png", data, size);
  return 0;
}
