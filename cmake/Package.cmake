# Installing Vitrine (cmake --install, which scripts/start runs into /usr/local) and its Debian package
# (scripts/package: CPack's DEB generator over these same rules). What goes where:
#   bin/vitrine                                   the binary (finds its data at ../share/vitrine)
#   share/vitrine/{fonts,hdri,photos}/            the fetched assets, each folder with its licence
#   share/applications, share/metainfo, share/icons/hicolor    found like an app
#   share/man/man1/vitrine.1.gz, share/bash-completion/completions/vitrine     from the flag table
#   lib/systemd/user/vitrine-kiosk.service        the kiosk's user unit, not enabled
#   share/doc/vitrine/copyright, changelog.gz     what Debian wants of every package
include(GNUInstallDirs)

# The desktop entry's, the icon's and the AppStream component's name (reverse DNS, as AppStream wants).
set(VITRINE_APP_ID org.vitrine.Vitrine)
set(VITRINE_HOMEPAGE "https://vitrine.example.org" CACHE STRING
  "The project's public home: AppStream's homepage and the base of its screenshots' addresses")
set(VITRINE_SCREENSHOT_BASE "${VITRINE_HOMEPAGE}/docs/gallery" CACHE STRING
  "Where the contact sheet's thumbnails (docs/gallery) are published, for AppStream's screenshots")
set(VITRINE_PACKAGING_DIR ${CMAKE_BINARY_DIR}/packaging)
set(VITRINE_DATA_DIR ${CMAKE_INSTALL_DATADIR}/vitrine)

install(TARGETS vitrine RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

# The assets scripts/setup fetched (assets/cache); scripts/package refuses to package without them.
set(assets ${CMAKE_SOURCE_DIR}/assets/cache)
install(DIRECTORY ${assets}/fonts/ DESTINATION ${VITRINE_DATA_DIR}/fonts OPTIONAL
  FILES_MATCHING PATTERN "*.woff2" PATTERN "OFL-*.txt")
install(DIRECTORY ${assets}/hdri/ DESTINATION ${VITRINE_DATA_DIR}/hdri OPTIONAL FILES_MATCHING PATTERN "*.exr")
install(DIRECTORY ${assets}/photos/ DESTINATION ${VITRINE_DATA_DIR}/photos OPTIONAL
  FILES_MATCHING PATTERN "*.jpg" PATTERN "COPYRIGHT")

# The desktop entry, the AppStream metadata (its release is the project's version, dated by the commit
# it is built from) and the icon.
execute_process(COMMAND git -C ${CMAKE_SOURCE_DIR} log -1 --format=%cs
  OUTPUT_VARIABLE VITRINE_RELEASE_DATE OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(NOT VITRINE_RELEASE_DATE)
  string(TIMESTAMP VITRINE_RELEASE_DATE "%Y-%m-%d" UTC)
endif()
set(VITRINE_METAINFO_SCREENSHOTS "")
foreach(shot "glass_diamond|A round brilliant diamond splitting white light into colour"
             "bloom_default|The vapochromic crystal at its climax, crimson inside rose and amber"
             "neon_default|Neon tubes over a facade at night, mirrored in the wet ground"
             "kifs_final|The emission-only volumetric fractal"
             "noodles_default|Curl-noise streamlines as round tubes")
  string(REPLACE "|" ";" shot "${shot}")
  list(GET shot 0 file)
  list(GET shot 1 caption)
  set(kind "")
  if(NOT VITRINE_METAINFO_SCREENSHOTS)
    set(kind " type=\"default\"")
  endif()
  string(APPEND VITRINE_METAINFO_SCREENSHOTS "    <screenshot${kind}>\n      <caption>${caption}</caption>\n"
    "      <image type=\"source\" width=\"480\" height=\"270\">${VITRINE_SCREENSHOT_BASE}/${file}.png</image>\n"
    "    </screenshot>\n")
endforeach()
configure_file(${CMAKE_SOURCE_DIR}/packaging/vitrine.desktop.in ${VITRINE_PACKAGING_DIR}/${VITRINE_APP_ID}.desktop @ONLY)
configure_file(${CMAKE_SOURCE_DIR}/packaging/vitrine.metainfo.xml.in
  ${VITRINE_PACKAGING_DIR}/${VITRINE_APP_ID}.metainfo.xml @ONLY)
install(FILES ${VITRINE_PACKAGING_DIR}/${VITRINE_APP_ID}.desktop DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
install(FILES ${VITRINE_PACKAGING_DIR}/${VITRINE_APP_ID}.metainfo.xml DESTINATION ${CMAKE_INSTALL_DATADIR}/metainfo)
install(FILES packaging/vitrine.svg DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps
  RENAME ${VITRINE_APP_ID}.svg)
# PNG sizes for menus that take no SVG, drawn from the SVG by librsvg when it is installed.
find_program(RSVG_CONVERT rsvg-convert)
if(RSVG_CONVERT)
  set(icons "")
  foreach(size 48 64 128 256)
    set(png ${VITRINE_PACKAGING_DIR}/icons/${size}/${VITRINE_APP_ID}.png)
    add_custom_command(OUTPUT ${png}
      COMMAND ${CMAKE_COMMAND} -E make_directory ${VITRINE_PACKAGING_DIR}/icons/${size}
      COMMAND ${RSVG_CONVERT} -w ${size} -h ${size} -o ${png} ${CMAKE_SOURCE_DIR}/packaging/vitrine.svg
      DEPENDS ${CMAKE_SOURCE_DIR}/packaging/vitrine.svg VERBATIM)
    list(APPEND icons ${png})
    install(FILES ${png} DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/${size}x${size}/apps)
  endforeach()
  add_custom_target(vitrine_icons ALL DEPENDS ${icons})
endif()

# The kiosk's systemd user unit, where the user manager finds it; no unit is enabled by the package
# (docs/INSTALLATIONS.md, "Running under a service manager", says how to turn it on).
# Its ExecStart names the binary under the prefix installed into (/usr/bin for the package), decided
# when installing, since `cmake --install --prefix` and CPack choose the prefix then.
install(CODE "
  file(READ \"${CMAKE_SOURCE_DIR}/docs/vitrine-kiosk.service\" unit)
  string(REPLACE \"ExecStart=/usr/bin/vitrine\" \"ExecStart=\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_BINDIR}/vitrine\" unit \"\${unit}\")
  file(WRITE \"${VITRINE_PACKAGING_DIR}/vitrine-kiosk.service\" \"\${unit}\")")
install(FILES ${VITRINE_PACKAGING_DIR}/vitrine-kiosk.service DESTINATION lib/systemd/user)

# The man page: written from the flag table by the binary, never by hand, and installed compressed as
# Debian wants it (gzip -n: the same bytes every build).
function(vitrine_install_man_page roff)
  get_filename_component(name ${roff} NAME)
  set(gz ${VITRINE_PACKAGING_DIR}/${name}.gz)
  add_custom_command(OUTPUT ${gz} COMMAND sh -c "gzip -9nc \"$1\" > \"$2\"" sh ${roff} ${gz} DEPENDS ${roff} VERBATIM)
  add_custom_target(vitrine_man_page_gz ALL DEPENDS ${gz})
  install(FILES ${gz} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
endfunction()
# The flag table's generator (target vitrine_docs) writes VITRINE_DOCS_DIR/vitrine.1.
if(TARGET vitrine_docs AND DEFINED VITRINE_DOCS_DIR)
  vitrine_install_man_page(${VITRINE_DOCS_DIR}/vitrine.1)
endif()

# Debian's copyright file (every file's licence, the assets' authors) and a changelog naming the version.
set(doc ${CMAKE_INSTALL_DATADIR}/doc/vitrine)
install(FILES packaging/copyright DESTINATION ${doc})
execute_process(COMMAND git -C ${CMAKE_SOURCE_DIR} log -1 --format=%ad "--date=format:%a, %d %b %Y %H:%M:%S %z"
  OUTPUT_VARIABLE VITRINE_RELEASE_TIME OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(NOT VITRINE_RELEASE_TIME)
  string(TIMESTAMP VITRINE_RELEASE_TIME "%a, %d %b %Y %H:%M:%S +0000" UTC)
endif()
configure_file(packaging/changelog.in ${VITRINE_PACKAGING_DIR}/changelog.Debian @ONLY)
set(changelog ${VITRINE_PACKAGING_DIR}/changelog.Debian.gz)
add_custom_command(OUTPUT ${changelog}
  COMMAND sh -c "gzip -9nc \"$1\" > \"$2\"" sh ${VITRINE_PACKAGING_DIR}/changelog.Debian ${changelog}
  DEPENDS ${VITRINE_PACKAGING_DIR}/changelog.Debian VERBATIM)
add_custom_target(vitrine_changelog ALL DEPENDS ${changelog})
install(FILES ${changelog} DESTINATION ${doc})
install(FILES packaging/lintian-overrides DESTINATION ${CMAKE_INSTALL_DATADIR}/lintian/overrides RENAME vitrine)

# Everything the install rules copy that a build makes, so scripts/package builds no more than that.
add_custom_target(vitrine_installed)
add_dependencies(vitrine_installed vitrine vitrine_changelog)
foreach(made vitrine_icons vitrine_docs vitrine_man_page_gz)
  if(TARGET ${made})
    add_dependencies(vitrine_installed ${made})
  endif()
endforeach()

# --- The Debian package: `cpack -G DEB` in the build folder (scripts/package runs it and lintian).
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME vitrine)
set(CPACK_PACKAGE_VENDOR "The Vitrine authors")
set(CPACK_PACKAGE_CONTACT "The Vitrine authors <vitrine@vitrine.example.org>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "gallery of real-time GPU pieces")
set(CPACK_PACKAGE_DESCRIPTION "Vitrine shows real-time pieces drawn by the GPU through Vulkan: a
vapochromic crystal, spectral dispersion through glass, neon tubes, a
volumetric fractal, curl-noise streamlines and a test card for projectors.
It runs as a desktop application or as an unattended kiosk with a playlist,
several outputs and a remote control.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_RELEASE 1)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_HOMEPAGE ${VITRINE_HOMEPAGE})
# Dependencies read from the binary's own libraries by dpkg-shlibdeps; the rest are what it loads at
# run time: a Vulkan driver (Mesa's, or the GPU vendor's, which Provides vulkan-icd).
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "mesa-vulkan-drivers | vulkan-icd")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "xdg-user-dirs")
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
include(CPack)
