# Third-party libraries, all from Debian 12 packages (see README.md).
find_package(Threads REQUIRED)
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(glm REQUIRED)
find_package(nlohmann_json 3.10 REQUIRED)
# The fuzz tree (STYLOS_FUZZ, cmake/StylosFuzzBuild.cmake) builds only the core: no stylos-cli, no Qt.
if(NOT STYLOS_FUZZ)
  find_package(CLI11 2.1 CONFIG REQUIRED) # stylos-cli's argument parser (header-only, libcli11-dev)
endif()
find_package(PkgConfig REQUIRED)
# Debian's OpenImageIO CMake config is broken (wants /usr/bin/iconvert and OpenCV headers): use pkg-config.
pkg_check_modules(OIIO REQUIRED IMPORTED_TARGET OpenImageIO)
# XXH64, the .poct section checksum: Debian's libxxhash (libxxhash-dev ships libxxhash.pc).
pkg_check_modules(XXHASH REQUIRED IMPORTED_TARGET libxxhash)
# The E57 reader's XML section: Debian's libpugixml-dev (CMake config, target pugixml::pugixml).
find_package(pugixml 1.11 CONFIG REQUIRED)
find_path(NANOFLANN_INCLUDE_DIR nanoflann.hpp REQUIRED)
add_library(stylos_nanoflann INTERFACE)
target_include_directories(stylos_nanoflann SYSTEM INTERFACE ${NANOFLANN_INCLUDE_DIR})

if(STYLOS_FUZZ)
  return()
endif()
# Qt Gui and Svg draw and write plates (stylos_plate), also for stylos-cli; the widgets only for the workbench.
find_package(Qt6 6.4 REQUIRED COMPONENTS Core Gui Svg)
if(STYLOS_BUILD_GUI)
  find_package(Qt6 6.4 REQUIRED COMPONENTS Core Gui Svg Widgets OpenGL OpenGLWidgets Concurrent LinguistTools Test)
endif()
