# Dear ImGui 1.86 from Debian: the core is libimgui.a; the GLFW and Vulkan backends ship as sources in
# the package's doc folder and are compiled here, unmodified, from where the package put them.
pkg_check_modules(IMGUI REQUIRED imgui)
set(IMGUI_BACKENDS /usr/share/doc/libimgui-dev/examples/backends)
if(NOT EXISTS ${IMGUI_BACKENDS}/imgui_impl_vulkan.cpp)
  message(FATAL_ERROR "Dear ImGui backends not found in ${IMGUI_BACKENDS}: apt-get install libimgui-dev")
endif()
add_library(vitrine_imgui STATIC ${IMGUI_BACKENDS}/imgui_impl_glfw.cpp ${IMGUI_BACKENDS}/imgui_impl_vulkan.cpp)
pkg_get_variable(IMGUI_INCLUDEDIR imgui includedir)
target_include_directories(vitrine_imgui SYSTEM PUBLIC ${IMGUI_INCLUDEDIR} ${IMGUI_INCLUDEDIR}/backends)
find_package(Freetype REQUIRED)  # libimgui.a carries the FreeType font builder the overlay uses
target_link_libraries(vitrine_imgui PUBLIC ${IMGUI_LINK_LIBRARIES} glfw Vulkan::Vulkan Freetype::Freetype)
target_compile_options(vitrine_imgui PRIVATE -w)
