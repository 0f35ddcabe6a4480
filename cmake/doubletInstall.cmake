# `cmake --install` layout and the CMake/pkg-config packages.
#
#   include/doublet/*.hpp              the API and the header-only host helpers
#   lib/libdoublet.a, libdoublet.so*   doublet::doublet (static), doublet::doublet-shared
#                                      (doublet::headers: the headers alone)
#   bin/doublet                        doublet::doublet-cli
#   lib/cmake/doublet/                 doubletConfig.cmake, version file, targets,
#                                      doublet_lower_shaders() and its helper script
#   lib/pkgconfig/doublet.pc
include(CMakePackageConfigHelpers)

set(DOUBLET_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/doublet CACHE STRING
    "Where doubletConfig.cmake is installed, relative to the prefix")

# doublet::headers: split.hpp and pack.hpp (header-only host helpers) without the library.
add_library(doublet_headers INTERFACE)
target_include_directories(doublet_headers INTERFACE
  $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include> $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
target_compile_features(doublet_headers INTERFACE cxx_std_20)
set_target_properties(doublet_headers PROPERTIES EXPORT_NAME headers)

install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/doublet
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.hpp")
install(TARGETS doublet doublet_shared doublet_headers doublet-cli
        EXPORT doubletTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT doubletTargets
        NAMESPACE doublet::
        DESTINATION ${DOUBLET_INSTALL_CMAKEDIR})

configure_package_config_file(
  ${CMAKE_CURRENT_LIST_DIR}/doubletConfig.cmake.in
  ${PROJECT_BINARY_DIR}/package/doubletConfig.cmake
  INSTALL_DESTINATION ${DOUBLET_INSTALL_CMAKEDIR})
# 0.x: a new minor version may change the API.
write_basic_package_version_file(
  ${PROJECT_BINARY_DIR}/package/doubletConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES
          ${PROJECT_BINARY_DIR}/package/doubletConfig.cmake
          ${PROJECT_BINARY_DIR}/package/doubletConfigVersion.cmake
          ${CMAKE_CURRENT_LIST_DIR}/doubletLowerShaders.cmake
          ${CMAKE_CURRENT_LIST_DIR}/doublet_embed_shader.cmake
        DESTINATION ${DOUBLET_INSTALL_CMAKEDIR})

# pkg-config: `pkg-config --cflags --libs doublet` links libdoublet.so; with --static, the
# static archive and glslang's archives.
file(RELATIVE_PATH DOUBLET_PC_TO_PREFIX /prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig /prefix)
string(REGEX REPLACE "/$" "" DOUBLET_PC_TO_PREFIX "${DOUBLET_PC_TO_PREFIX}")
configure_file(${CMAKE_CURRENT_LIST_DIR}/doublet.pc.in ${PROJECT_BINARY_DIR}/package/doublet.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/package/doublet.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
