#[=======================================================================[.rst:
FindCHOLMOD
-----------

SuiteSparse 5.x (Debian bookworm) ships no CMake package configuration, so
CHOLMOD and the SuiteSparse libraries it calls are located here, with KLU
(and BTF, which it calls): the sparse LU of the contact-space solves.

Imported target ``CHOLMOD::CHOLMOD``; result variables ``CHOLMOD_FOUND``,
``CHOLMOD_INCLUDE_DIR``, ``CHOLMOD_LIBRARIES``, ``CHOLMOD_VERSION``.
#]=======================================================================]

find_path(CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)

set(_nmm_cholmod_parts cholmod klu btf amd camd colamd ccolamd suitesparseconfig)
set(CHOLMOD_LIBRARIES "")
foreach(_part IN LISTS _nmm_cholmod_parts)
    find_library(CHOLMOD_${_part}_LIBRARY NAMES ${_part})
    mark_as_advanced(CHOLMOD_${_part}_LIBRARY)
    if(CHOLMOD_${_part}_LIBRARY)
        list(APPEND CHOLMOD_LIBRARIES "${CHOLMOD_${_part}_LIBRARY}")
    else()
        set(_nmm_cholmod_missing "${_nmm_cholmod_missing} ${_part}")
    endif()
endforeach()

# The version macros live in cholmod_core.h in SuiteSparse 5.x
if(CHOLMOD_INCLUDE_DIR AND EXISTS "${CHOLMOD_INCLUDE_DIR}/cholmod_core.h")
    file(STRINGS "${CHOLMOD_INCLUDE_DIR}/cholmod_core.h" _nmm_ver
         REGEX "#define CHOLMOD_(MAIN|SUB|SUBSUB)_VERSION +[0-9]+")
    foreach(_kind MAIN SUB SUBSUB)
        string(REGEX REPLACE ".*CHOLMOD_${_kind}_VERSION +([0-9]+).*" "\\1"
               _nmm_${_kind} "${_nmm_ver}")
    endforeach()
    set(CHOLMOD_VERSION "${_nmm_MAIN}.${_nmm_SUB}.${_nmm_SUBSUB}")
endif()

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(CHOLMOD
    REQUIRED_VARS CHOLMOD_INCLUDE_DIR CHOLMOD_cholmod_LIBRARY
                  CHOLMOD_klu_LIBRARY CHOLMOD_btf_LIBRARY
                  CHOLMOD_suitesparseconfig_LIBRARY
    VERSION_VAR CHOLMOD_VERSION)
mark_as_advanced(CHOLMOD_INCLUDE_DIR)

if(CHOLMOD_FOUND AND NOT TARGET CHOLMOD::CHOLMOD)
    add_library(CHOLMOD::CHOLMOD INTERFACE IMPORTED)
    set_target_properties(CHOLMOD::CHOLMOD PROPERTIES
        INTERFACE_INCLUDE_DIRECTORIES "${CHOLMOD_INCLUDE_DIR}"
        INTERFACE_LINK_LIBRARIES "${CHOLMOD_LIBRARIES}")
endif()
