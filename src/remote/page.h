#pragma once
// The control page (src/remote/page.html), embedded at build time by cmake/EmbedText.cmake.
#include <string_view>

namespace vitrine::remote {

std::string_view pageHtml();

}  // namespace vitrine::remote
