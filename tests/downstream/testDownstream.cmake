# cmake -P script run by the ctest test downstreamPackage:
#   1. install the nmmSolid build tree NMM_BINARY_DIR into a scratch prefix,
#   2. configure and build tests/downstream against that prefix only,
#   3. run the result and check it prints the expected version,
#   4. run an installed application, which finds libnmmSolid.so through
#      its install RPATH.
# Variables: NMM_BINARY_DIR NMM_DOWNSTREAM_SOURCE_DIR NMM_WORK_DIR
#            NMM_GENERATOR NMM_CXX_COMPILER NMM_BUILD_TYPE NMM_SANITIZE
#            NMM_EXPECTED_VERSION
cmake_minimum_required(VERSION 3.18)

foreach(_var NMM_BINARY_DIR NMM_DOWNSTREAM_SOURCE_DIR NMM_WORK_DIR
             NMM_EXPECTED_VERSION)
    if(NOT DEFINED ${_var} OR "${${_var}}" STREQUAL "")
        message(FATAL_ERROR "testDownstream.cmake: ${_var} not set")
    endif()
endforeach()
if(NOT NMM_BUILD_TYPE)
    set(NMM_BUILD_TYPE Release)
endif()

set(_prefix "${NMM_WORK_DIR}/prefix")
set(_build "${NMM_WORK_DIR}/build")
file(REMOVE_RECURSE "${NMM_WORK_DIR}")
file(MAKE_DIRECTORY "${NMM_WORK_DIR}")

function(nmm_run step)
    execute_process(COMMAND ${ARGN}
        RESULT_VARIABLE _rc
        OUTPUT_VARIABLE _out
        ERROR_VARIABLE _out)
    if(NOT _rc EQUAL 0)
        message(FATAL_ERROR "downstream test: ${step} failed (${_rc}):\n${_out}")
    endif()
    message(STATUS "downstream test: ${step}: ok")
    set(_nmm_last_output "${_out}" PARENT_SCOPE)
endfunction()

nmm_run("install to ${_prefix}"
    "${CMAKE_COMMAND}" --install "${NMM_BINARY_DIR}"
    --prefix "${_prefix}" --config "${NMM_BUILD_TYPE}")

if(NOT EXISTS "${_prefix}/include/nmmSolid/global/version.H")
    message(FATAL_ERROR "downstream test: generated version.H not installed")
endif()
foreach(_file nmmSolidConfig.cmake nmmSolidConfigVersion.cmake
              nmmSolidTargets.cmake FindCHOLMOD.cmake)
    file(GLOB_RECURSE _found "${_prefix}/${_file}")
    if(NOT _found)
        message(FATAL_ERROR "downstream test: ${_file} not installed")
    endif()
endforeach()

set(_configure
    "${CMAKE_COMMAND}" -S "${NMM_DOWNSTREAM_SOURCE_DIR}" -B "${_build}"
    "-DCMAKE_BUILD_TYPE=${NMM_BUILD_TYPE}"
    "-DCMAKE_PREFIX_PATH=${_prefix}"
    # Only the scratch prefix may provide nmmSolid
    "-DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON")
if(NMM_GENERATOR)
    list(APPEND _configure -G "${NMM_GENERATOR}")
endif()
if(NMM_CXX_COMPILER)
    list(APPEND _configure "-DCMAKE_CXX_COMPILER=${NMM_CXX_COMPILER}")
endif()
if(NMM_SANITIZE)
    # The library is instrumented: its consumer must link the runtimes
    list(APPEND _configure
        "-DCMAKE_CXX_FLAGS=-fsanitize=address,undefined"
        "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined")
endif()

nmm_run("configure" ${_configure})
nmm_run("build" "${CMAKE_COMMAND}" --build "${_build}")

find_program(_exe downstream
    PATHS "${_build}" "${_build}/${NMM_BUILD_TYPE}" NO_DEFAULT_PATH)
if(NOT _exe)
    message(FATAL_ERROR "downstream test: executable not found in ${_build}")
endif()
nmm_run("run" "${_exe}")

string(STRIP "${_nmm_last_output}" _printed)
if(NOT _printed STREQUAL "nmmSolid ${NMM_EXPECTED_VERSION}")
    message(FATAL_ERROR "downstream test: printed '${_printed}', "
        "expected 'nmmSolid ${NMM_EXPECTED_VERSION}'")
endif()

# The installed solver finds libnmmSolid.so in the prefix by its install
# RPATH, not by the build tree's nor by LD_LIBRARY_PATH; its help lists
# the contact law that registered itself
set(_solver "${_prefix}/bin/nmmSolidFoam")
if(NOT EXISTS "${_solver}")
    message(FATAL_ERROR "downstream test: ${_solver} not installed")
endif()
nmm_run("run installed nmmSolidFoam -help"
    "${CMAKE_COMMAND}" -E env --unset=LD_LIBRARY_PATH "${_solver}" -help)
if(NOT _nmm_last_output MATCHES "mohrCoulomb")
    message(FATAL_ERROR "downstream test: nmmSolidFoam -help lists no "
        "mohrCoulomb contact law:\n${_nmm_last_output}")
endif()

message(STATUS "downstream test: passed (${_printed})")
