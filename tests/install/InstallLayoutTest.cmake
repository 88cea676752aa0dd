# `cmake --install` into a fresh prefix: every file a desktop needs is there, and the installed programs run.
# Run with -DBUILD_DIR=build -DPREFIX=folder -DVERSION=x.y.z -DGUI=ON|OFF.
file(REMOVE_RECURSE ${PREFIX})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${PREFIX}
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${rc}): ${err}")
endif()

set(expected bin/stylos-cli lib/stylos/libstylos_oiio.so share/doc/stylos/README.md)
if(GUI)
  list(APPEND expected bin/stylos share/applications/stylos.desktop share/mime/packages/stylos.xml
       share/icons/hicolor/scalable/apps/stylos.svg share/stylos/translations/stylos_fr.qm
       share/stylos/translations/stylos_el.qm)
  foreach(size 16 22 24 32 48 64 128 256 512)
    list(APPEND expected share/icons/hicolor/${size}x${size}/apps/stylos.png)
  endforeach()
endif()
foreach(f IN LISTS expected)
  if(NOT EXISTS ${PREFIX}/${f})
    message(FATAL_ERROR "cmake --install did not lay out ${f} under ${PREFIX}")
  endif()
endforeach()

# A PNG icon is a PNG of its size: bytes 16..23 of the IHDR hold the width and height.
if(GUI)
  file(READ ${PREFIX}/share/icons/hicolor/48x48/apps/stylos.png head LIMIT 24 HEX)
  string(SUBSTRING "${head}" 0 16 magic)
  string(SUBSTRING "${head}" 32 16 size)
  if(NOT magic STREQUAL "89504e470d0a1a0a" OR NOT size STREQUAL "0000003000000030")
    message(FATAL_ERROR "the 48x48 icon is not a 48 x 48 PNG (header ${head})")
  endif()
  file(READ ${PREFIX}/share/applications/stylos.desktop desktop)
  foreach(line "Exec=stylos %F" "Icon=stylos" "MimeType=application/x-stylos-project;application/x-stylos-octree;")
    string(FIND "${desktop}" "${line}" at)
    if(at EQUAL -1)
      message(FATAL_ERROR "stylos.desktop lacks \"${line}\"")
    endif()
  endforeach()
endif()

execute_process(COMMAND ${PREFIX}/bin/stylos-cli --version RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(NOT rc EQUAL 0 OR NOT out MATCHES "stylos-cli ${VERSION}")
  message(FATAL_ERROR "the installed stylos-cli --version: exit ${rc}, \"${out}\"")
endif()
# The installed stylos-cli writes an image through the installed module (it looks in ../lib/stylos beside itself;
# the build tree's copy is only for programs inside the build tree).
execute_process(COMMAND ${PREFIX}/bin/stylos-cli generate drum -o ${PREFIX}/drum.ply --spacing 0.03
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the installed stylos-cli generate: exit ${rc}: ${err}")
endif()
execute_process(COMMAND ${PREFIX}/bin/stylos-cli unroll ${PREFIX}/drum.ply -o ${PREFIX}/drum.png
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT EXISTS ${PREFIX}/drum.png)
  message(FATAL_ERROR "the installed stylos-cli could not write an image: exit ${rc}: ${err}")
endif()
if(GUI)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=DISPLAY --unset=WAYLAND_DISPLAY --unset=QT_QPA_PLATFORM
                          ${PREFIX}/bin/stylos --version RESULT_VARIABLE rc OUTPUT_VARIABLE out)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "stylos ${VERSION}")
    message(FATAL_ERROR "the installed stylos --version: exit ${rc}, \"${out}\"")
  endif()
endif()
file(REMOVE_RECURSE ${PREFIX})
