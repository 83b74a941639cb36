// Radiance HDR files as Vitrine reads them: readPicture, for a glass backdrop named by path
// (--set glass.backdrop=FILE.hdr); EXR-only readImage refuses them by their first bytes.
#include "support/image_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  vitrine::fuzz::readAsBackdrop("input.hdr", data, size);
  vitrine::fuzz::readAsPanorama("input.hdr", data, size);
  return 0;
}
