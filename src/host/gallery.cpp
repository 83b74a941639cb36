#include "gpu/check.h"
#include "host/modes.h"

namespace vitrine::host {
int runGallery(const Options&) { throw Error("The windowed gallery is not built yet."); }
}  // namespace vitrine::host
