# Install rules: the library, its headers (with the generated version.H), the
# applications (installed by nmm_add_application) and a CMake package so that
# another project can
#     find_package(nmmSolid)
#     target_link_libraries(app PRIVATE nmmSolid::nmmSolid)
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(NMM_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/nmmSolid" CACHE STRING
    "Where the nmmSolid CMake package files are installed (relative to the prefix)")
mark_as_advanced(NMM_INSTALL_CMAKEDIR)

install(TARGETS nmmSolid
    EXPORT nmmSolidTargets
    ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}"
    LIBRARY DESTINATION "${CMAKE_INSTALL_LIBDIR}"
    RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}"
    INCLUDES DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}")

# The FMU binary, where nmmFmuExport (in bin/) looks for it
if(TARGET nmmSolidFmi3)
    install(TARGETS nmmSolidFmi3 LIBRARY DESTINATION "${CMAKE_INSTALL_LIBDIR}")
endif()

# Headers keep their layout: src/nmmSolid/io/dictionary/dictionary.H ->
# <prefix>/include/nmmSolid/io/dictionary/dictionary.H
install(DIRECTORY "${PROJECT_SOURCE_DIR}/src/nmmSolid/"
    DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/nmmSolid"
    FILES_MATCHING PATTERN "*.H")
install(FILES
    "${PROJECT_BINARY_DIR}/src/nmmSolid/include/nmmSolid/global/version.H"
    DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/nmmSolid/global")

# What nmmPoreFlow copies into its OpenFOAM cases, and the RunFunctions
# their Allrun sources
install(DIRECTORY "${PROJECT_SOURCE_DIR}/etc/templates"
    DESTINATION "${CMAKE_INSTALL_DATADIR}/nmmSolid")
install(FILES "${PROJECT_SOURCE_DIR}/bin/tools/RunFunctions"
    DESTINATION "${CMAKE_INSTALL_DATADIR}/nmmSolid/tools")

install(EXPORT nmmSolidTargets
    NAMESPACE nmmSolid::
    FILE nmmSolidTargets.cmake
    DESTINATION "${NMM_INSTALL_CMAKEDIR}")

configure_package_config_file(
    "${PROJECT_SOURCE_DIR}/cmake/nmmSolidConfig.cmake.in"
    "${PROJECT_BINARY_DIR}/cmake/nmmSolidConfig.cmake"
    INSTALL_DESTINATION "${NMM_INSTALL_CMAKEDIR}")
# Before 1.0 a minor version may change the interface
write_basic_package_version_file(
    "${PROJECT_BINARY_DIR}/cmake/nmmSolidConfigVersion.cmake"
    VERSION "${PROJECT_VERSION}"
    COMPATIBILITY SameMinorVersion)

install(FILES
    "${PROJECT_BINARY_DIR}/cmake/nmmSolidConfig.cmake"
    "${PROJECT_BINARY_DIR}/cmake/nmmSolidConfigVersion.cmake"
    # nmmSolidConfig.cmake looks for the library's private dependency
    # CHOLMOD with this module (SuiteSparse 5 has no CMake package)
    "${PROJECT_SOURCE_DIR}/cmake/FindCHOLMOD.cmake"
    DESTINATION "${NMM_INSTALL_CMAKEDIR}")
