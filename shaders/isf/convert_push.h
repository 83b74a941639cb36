// The push block of shaders/isf/convert.comp, one declaration for both sides: isf/gpu/isf_runner.cpp fills it.
#ifndef ISF_CONVERT_PUSH_H
#define ISF_CONVERT_PUSH_H
#include "../common/interop.h"

VITRINE_SHARED_BEGIN
struct IsfConvertPush {
  uint toLinear;  // non-zero: ISF's values (sRGB-encoded, as a GL host shows them) to linear light; zero: back
};
VITRINE_SHARED_END

#endif
