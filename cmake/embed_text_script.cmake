# Run by vitrine_embed_text (cmake -P): writes OUTPUT, a C++ source returning SOURCE's text as a raw
# string literal. Fails if the text contains the literal's closing delimiter.
file(READ ${SOURCE} text)
set(delimiter "vitrine_embedded")
string(FIND "${text}" ")${delimiter}\"" clash)
if(NOT clash EQUAL -1)
  message(FATAL_ERROR "${SOURCE} contains )${delimiter}\" and cannot be embedded as a raw string")
endif()
file(WRITE ${OUTPUT}.tmp "// Generated from ${SOURCE} by cmake/embed_text_script.cmake; edit the source.
#include <string_view>
namespace ${NAMESPACE} {
std::string_view ${FUNCTION}() {
  static constexpr std::string_view text = R\"${delimiter}(${text})${delimiter}\";
  return text;
}
}  // namespace ${NAMESPACE}
")
file(COPY_FILE ${OUTPUT}.tmp ${OUTPUT} ONLY_IF_DIFFERENT)
file(REMOVE ${OUTPUT}.tmp)
