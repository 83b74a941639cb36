#pragma once
// The one entry of the OpenImageIO picture module (picture_oiio.cpp): reads `path` at its own size
// into `picture` (8-bit sRGB RGBA), or returns false with the reason in `why`. A plain function with
// C linkage, so that the image module can find it by name in the module it loads.
#include "image/image_io.h"

#include <string>

extern "C" bool vitrine_read_picture_oiio(const char* path, vitrine::Picture* picture, std::string* why);
