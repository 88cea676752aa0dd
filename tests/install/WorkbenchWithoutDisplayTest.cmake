# `stylos` with no display: --version and --help answer, a plain start exits 1 with what to do (not Qt's
# abort, exit 134). Run with -DSTYLOS=path -DVERSION=x.y.z.
set(no_display ${CMAKE_COMMAND} -E env --unset=DISPLAY --unset=WAYLAND_DISPLAY --unset=QT_QPA_PLATFORM)

execute_process(COMMAND ${no_display} ${STYLOS} --version RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT out MATCHES "stylos ${VERSION}")
  message(FATAL_ERROR "--version without a display: exit ${rc}, stdout \"${out}\", stderr \"${err}\"")
endif()

execute_process(COMMAND ${no_display} ${STYLOS} --help RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT out MATCHES "--grab")
  message(FATAL_ERROR "--help without a display: exit ${rc}, stdout \"${out}\", stderr \"${err}\"")
endif()

execute_process(COMMAND ${no_display} ${STYLOS} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 1 OR NOT err MATCHES "no display to open the workbench on" OR NOT err MATCHES "xvfb-run -a stylos")
  message(FATAL_ERROR "a plain start without a display: exit ${rc} (want 1), stderr \"${err}\"")
endif()

execute_process(COMMAND ${no_display} ${STYLOS} --no-such-option RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc EQUAL 0 OR NOT err MATCHES "Unknown option 'no-such-option'" OR err MATCHES "no display")
  message(FATAL_ERROR "an unknown option without a display: exit ${rc}, stderr \"${err}\"")
endif()
