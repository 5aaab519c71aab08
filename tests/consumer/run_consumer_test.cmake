# Installs the build into a private prefix, then builds and runs a consumer program against it,
# once through find_package(vorocrust) and once through pkg-config.
# Inputs: SOURCE_DIR, BUILD_DIR, WORK_DIR, MODEL.
file(REMOVE_RECURSE "${WORK_DIR}")
set(prefix "${WORK_DIR}/prefix")

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "failed (${code}): ${ARGN}\n${out}\n${err}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

run(${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${prefix}")

# find_package
run(${CMAKE_COMMAND} -S "${SOURCE_DIR}/tests/consumer" -B "${WORK_DIR}/build" -DCMAKE_PREFIX_PATH=${prefix}
    -DCMAKE_BUILD_TYPE=Release)
run(${CMAKE_COMMAND} --build "${WORK_DIR}/build")
run("${WORK_DIR}/build/consumer" "${MODEL}")
if(NOT last_output MATCHES "faces 446 genus 2" OR NOT last_output MATCHES "openmesh faces 446")
  message(FATAL_ERROR "unexpected consumer output: ${last_output}")
endif()

# pkg-config
file(GLOB_RECURSE pc_files "${prefix}/*/vorocrust.pc")
list(LENGTH pc_files n)
if(NOT n EQUAL 1)
  message(FATAL_ERROR "expected one installed vorocrust.pc, found: ${pc_files}")
endif()
get_filename_component(pc_dir "${pc_files}" DIRECTORY)
set(ENV{PKG_CONFIG_PATH} "${pc_dir}")
run(pkg-config --cflags --libs vorocrust)
string(STRIP "${last_output}" flags)
separate_arguments(flags UNIX_COMMAND "${flags}")
run(c++ -std=c++20 "${SOURCE_DIR}/tests/consumer/main.cpp" ${flags} -o "${WORK_DIR}/consumer_pc")
get_filename_component(libdir "${pc_dir}" DIRECTORY)
set(ENV{LD_LIBRARY_PATH} "${libdir}")
run("${WORK_DIR}/consumer_pc" "${MODEL}")
if(NOT last_output MATCHES "faces 446 genus 2")
  message(FATAL_ERROR "unexpected pkg-config consumer output: ${last_output}")
endif()

# The installed program finds its library without LD_LIBRARY_PATH.
unset(ENV{LD_LIBRARY_PATH})
run("${prefix}/bin/vorocrust" info "${MODEL}")
message(STATUS "consumer builds and runs through find_package and pkg-config")
