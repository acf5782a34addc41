# Installing the SDK: libproxima.so with its SONAME links, the public headers,
# the CMake package (proxima::proxima, components for the optional parts) and
# a pkg-config file; and the Debian packages CPack makes from them
# (docs/install.md). Included by the top-level CMakeLists.txt.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(PROX_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/proxima" CACHE STRING
    "Where the CMake package files go, relative to the prefix")

# Two install components, which CPack turns into two Debian packages:
# 'runtime' (libproxima.so.MAJOR*) and 'development' (headers, the unversioned
# link, the CMake and pkg-config files).
install(TARGETS proxima_capi proxima_headers EXPORT proximaTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT runtime NAMELINK_COMPONENT development
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT development
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
# Headers of optional parts this build lacks are left out.
set(prox_header_excludes "")
if(NOT PROX_WITH_HIDAPI)
  list(APPEND prox_header_excludes PATTERN "proxima_hid.h" EXCLUDE)
endif()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/sdk/include/proxima DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
  COMPONENT development FILES_MATCHING PATTERN "*.h" ${prox_header_excludes}
  PATTERN "proxima_openxr.h" EXCLUDE)  # only with the openxr component, below
install(EXPORT proximaTargets NAMESPACE proxima:: DESTINATION ${PROX_INSTALL_CMAKEDIR}
  COMPONENT development)

# The optional parts compiled into this libproxima.so, as package components:
# find_package(proxima CONFIG REQUIRED COMPONENTS gltf) fails on a build
# without glTF loading; likewise hid and openxr below.
set(PROX_PACKAGE_COMPONENTS "")
if(PROX_WITH_GLTF)
  list(APPEND PROX_PACKAGE_COMPONENTS gltf)
endif()
# hid: HID devices through hidapi (proxima_hid.h).
if(PROX_WITH_HIDAPI)
  list(APPEND PROX_PACKAGE_COMPONENTS hid)
endif()
set(PROX_KNOWN_COMPONENTS gltf)
list(APPEND PROX_KNOWN_COMPONENTS hid)
# openxr: the OpenXR device (proxima_openxr.h, docs/openxr.md). Its header
# includes <openxr/openxr.h>, so the config finds OpenXR's headers when the
# component is asked for, the .pc requires openxr.pc (libopenxr-dev; its
# Cflags only: libproxima links no loader) and libproxima-dev depends on
# libopenxr-dev.
list(APPEND PROX_KNOWN_COMPONENTS openxr)
if(PROX_WITH_OPENXR)
  list(APPEND PROX_PACKAGE_COMPONENTS openxr)
  install(FILES ${PROJECT_SOURCE_DIR}/sdk/include/proxima/proxima_openxr.h
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/proxima COMPONENT development)
endif()
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/proximaConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/proximaConfig.cmake INSTALL_DESTINATION ${PROX_INSTALL_CMAKEDIR})
# 0.x releases promise nothing across minor versions, but SameMajorVersion is
# what a 1.0 will keep; the C API also checks the header's version at run time.
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/proximaConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMajorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/proximaConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/proximaConfigVersion.cmake
  DESTINATION ${PROX_INSTALL_CMAKEDIR} COMPONENT development)

# pkg-config. Relocatable (the prefix is found from the .pc's own place), so
# `cmake --install --prefix DIR` and the .deb both get a correct file.
# GLM and tinygltf are compiled in; the optional parts that link a
# pkg-config package (hidapi-hidraw) or need its headers (openxr) add it to
# PROX_PC_REQUIRES_PRIVATE below. Libs.private is for `pkg-config --static`.
file(RELATIVE_PATH prox_pc_to_prefix "/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/")
string(REGEX REPLACE "/$" "" prox_pc_to_prefix "${prox_pc_to_prefix}")
set(PROX_PC_REQUIRES_PRIVATE "" CACHE INTERNAL "pkg-config modules libproxima.so links")
set(PROX_PC_LIBS_PRIVATE "-lstdc++ -lm -pthread")
if(PROX_WITH_OPENXR)
  set(PROX_PC_REQUIRES_PRIVATE "${PROX_PC_REQUIRES_PRIVATE} openxr" CACHE INTERNAL "")
endif()
if(PROX_WITH_HIDAPI)
  set(PROX_PC_REQUIRES_PRIVATE "${PROX_PC_REQUIRES_PRIVATE} hidapi-hidraw" CACHE INTERNAL "")
endif()
configure_file(${CMAKE_CURRENT_LIST_DIR}/proxima.pc.in ${CMAKE_CURRENT_BINARY_DIR}/proxima.pc @ONLY)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/proxima.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig
  COMPONENT development)

# Windows (docs/install.md, "Windows"): MSVC links with proxima.lib, an import
# library made from the DLL's exports (sdk/CMakeLists.txt); MinGW with the
# libproxima.dll.a the export above installs.
if(WIN32 AND TARGET proxima_msvc_import_lib)
  install(FILES ${PROJECT_BINARY_DIR}/sdk/proxima.lib ${PROJECT_BINARY_DIR}/sdk/proxima.def
          DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT development)
endif()

# CPack: `cpack -G DEB` in the build directory makes
# proxima_VERSION_ARCH-libproxima0.deb and proxima_VERSION_ARCH-libproxima-dev.deb
# (the Debian package names are libproxima0 and libproxima-dev).
set(CPACK_PACKAGE_NAME proxima)
set(CPACK_PACKAGE_VENDOR "Proxima")
set(CPACK_PACKAGE_CONTACT "Proxima maintainers <proxima@invalid>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Multi-contact proximity haptics SDK")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
if(WIN32)
  # `cpack` makes proxima-VERSION-win64.zip: bin/proxima.dll, lib/ (the
  # import libraries, the CMake package), include/.
  set(CPACK_GENERATOR ZIP)
  set(CPACK_PACKAGE_FILE_NAME "proxima-${PROJECT_VERSION}-win64")
  set(CPACK_ARCHIVE_COMPONENT_INSTALL OFF)
else()
  set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
endif()
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL runtime development)
set(CPACK_DEBIAN_PACKAGE_SECTION libs)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME "libproxima${PROJECT_VERSION_MAJOR}")
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SECTION libs)
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_NAME "libproxima-dev")
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_SECTION libdevel)
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_DEPENDS "libproxima${PROJECT_VERSION_MAJOR} (= ${PROJECT_VERSION})")
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_SHLIBDEPS OFF)
# proxima.pc's Requires.private names hidapi-hidraw: its .pc comes with libhidapi-dev.
if(PROX_WITH_HIDAPI)
  string(APPEND CPACK_DEBIAN_DEVELOPMENT_PACKAGE_DEPENDS ", libhidapi-dev")
endif()
set(CPACK_COMPONENT_RUNTIME_DESCRIPTION "Proxima: multi-contact proximity haptics (shared library)")
set(CPACK_COMPONENT_DEVELOPMENT_DESCRIPTION
    "Proxima: multi-contact proximity haptics (C headers, CMake package, pkg-config file)")
if(NOT CPACK_DEBIAN_PACKAGE_ARCHITECTURE)
  find_program(PROX_DPKG dpkg)
  if(PROX_DPKG)
    execute_process(COMMAND ${PROX_DPKG} --print-architecture OUTPUT_VARIABLE CPACK_DEBIAN_PACKAGE_ARCHITECTURE
                    OUTPUT_STRIP_TRAILING_WHITESPACE)
  else()
    set(CPACK_DEBIAN_PACKAGE_ARCHITECTURE ${CMAKE_SYSTEM_PROCESSOR})
  endif()
endif()
set(prox_deb_stem "proxima_${PROJECT_VERSION}_${CPACK_DEBIAN_PACKAGE_ARCHITECTURE}")
set(CPACK_DEBIAN_RUNTIME_FILE_NAME "${prox_deb_stem}-libproxima${PROJECT_VERSION_MAJOR}.deb")
set(CPACK_DEBIAN_DEVELOPMENT_FILE_NAME "${prox_deb_stem}-libproxima-dev.deb")
if(PROX_WITH_OPENXR)
  string(APPEND CPACK_DEBIAN_DEVELOPMENT_PACKAGE_DEPENDS ", libopenxr-dev")
endif()
include(CPack)
