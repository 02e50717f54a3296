# Installs the built libraries into a fresh prefix, then configures, builds and runs
# examples/cpp against them with find_package(rbsim), as a user of the package would.
#   cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... [-DEXTRA_FLAGS=...] -P install_and_build.cmake
file(REMOVE_RECURSE "${WORK_DIR}")
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()
run(${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${WORK_DIR}/prefix")
# The package holds the public headers (engine/include) and nothing else: the private ones in
# engine/src stay out, and the example below compiles against what is there (issue 35).
file(GLOB_RECURSE installed RELATIVE "${WORK_DIR}/prefix/include" "${WORK_DIR}/prefix/include/*")
file(GLOB_RECURSE public RELATIVE "${SOURCE_DIR}/engine/include" "${SOURCE_DIR}/engine/include/*.h")
list(SORT installed)
list(SORT public)
if(NOT installed STREQUAL public)
  message(FATAL_ERROR "installed headers differ from engine/include:\n${installed}\nvs\n${public}")
endif()
run(${CMAKE_COMMAND} -S "${SOURCE_DIR}/examples/cpp" -B "${WORK_DIR}/build" -DCMAKE_BUILD_TYPE=Release
    "-DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix" "-DCMAKE_CXX_FLAGS=${EXTRA_FLAGS}" "-DCMAKE_EXE_LINKER_FLAGS=${EXTRA_FLAGS}")
run(${CMAKE_COMMAND} --build "${WORK_DIR}/build")
run("${WORK_DIR}/build/hello_rbsim")
message(STATUS "${last_output}")
if(NOT last_output MATCHES "\nok\n")
  message(FATAL_ERROR "the example did not print ok:\n${last_output}")
endif()
file(REMOVE_RECURSE "${WORK_DIR}")
