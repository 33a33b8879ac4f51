# Installs the locus build into a scratch prefix, then builds and runs tests/package twice:
# once via find_package(locus) against that prefix, once via add_subdirectory(locus source).
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "command failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
endfunction()
run(${CMAKE_COMMAND} --install ${LOCUS_BUILD_DIR} --prefix ${prefix})
foreach(mode find_package add_subdirectory)
  set(bdir ${WORK_DIR}/${mode})
  # add_subdirectory compiles the library again: only the core sources the consumer links
  # (LOCUS_SOURCE_ONLY) and without optimisation, since the packaging is what this test checks
  # (the whole library took 60 s here, unoptimised, on 2 cores).
  if(mode STREQUAL "find_package")
    set(build_type Release)
  else()
    set(build_type "")
  endif()
  run(${CMAKE_COMMAND} -S ${LOCUS_SOURCE_DIR}/tests/package -B ${bdir} -G ${GENERATOR}
      -DCMAKE_BUILD_TYPE=${build_type} -DCMAKE_PREFIX_PATH=${prefix} -DLOCUS_CONSUMER_MODE=${mode}
      -DLOCUS_SOURCE_DIR=${LOCUS_SOURCE_DIR} -DLOCUS_SOURCE_ONLY=src/core/)
  run(${CMAKE_COMMAND} --build ${bdir} -j2)
  run(${bdir}/consumer)
  message(STATUS "package consumer via ${mode}: ok")
endforeach()
