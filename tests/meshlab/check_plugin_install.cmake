# Installs the build twice under DESTDIR folders of WORK_DIR (so nothing outside it is written):
# the meshlab_plugin component must put the plugin into PLUGIN_DIR, a plain install must not.
# Inputs: BUILD_DIR, WORK_DIR, PLUGIN_DIR, PLUGIN_NAME.
file(REMOVE_RECURSE "${WORK_DIR}")

function(install_into destdir)
  set(ENV{DESTDIR} "${destdir}")
  execute_process(COMMAND ${CMAKE_COMMAND} --install "${BUILD_DIR}" ${ARGN}
    RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  unset(ENV{DESTDIR})
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "cmake --install ${ARGN} failed (${code}):\n${out}\n${err}")
  endif()
endfunction()

install_into("${WORK_DIR}/component" --component meshlab_plugin)
set(installed "${WORK_DIR}/component${PLUGIN_DIR}/${PLUGIN_NAME}")
if(NOT EXISTS "${installed}")
  message(FATAL_ERROR "--component meshlab_plugin did not install ${PLUGIN_DIR}/${PLUGIN_NAME}")
endif()

install_into("${WORK_DIR}/plain" --prefix /usr/local)
file(GLOB_RECURSE stray "${WORK_DIR}/plain/*${PLUGIN_NAME}")
if(stray)
  message(FATAL_ERROR "a plain install put the plugin in: ${stray}")
endif()
message(STATUS "the plugin installs to ${PLUGIN_DIR}, and only as the meshlab_plugin component")
