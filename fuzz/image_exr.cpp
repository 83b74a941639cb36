// EXR files as Vitrine reads them: readImage (panoramas, vitrine compare) and readPicture (a glass
// backdrop named by path). Any bytes are either read or refused with a vitrine::Error.
#include "support/image_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  vitrine::fuzz::readAsPanorama("input.exr", data, size);
  vitrine::fuzz::readAsBackdrop("input.exr", data, size);
  return 0;
}
