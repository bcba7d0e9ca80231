# nmm_add_application(<name> SOURCES <file>... [LIBRARIES <target>...])
#
# An nmmSolid application (solver or utility): an executable linked to
# nmmSolid::nmmSolid (plus any LIBRARIES), placed in NMM_RUNTIME_DIR and
# installed to <prefix>/bin. The names of all applications are collected in
# the global property NMM_APPLICATIONS.
include_guard(GLOBAL)
include(GNUInstallDirs)

function(nmm_add_application name)
    cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "SOURCES;LIBRARIES")
    if(arg_UNPARSED_ARGUMENTS)
        message(FATAL_ERROR
            "nmm_add_application(${name}): unknown arguments ${arg_UNPARSED_ARGUMENTS}")
    endif()
    if(NOT arg_SOURCES)
        message(FATAL_ERROR "nmm_add_application(${name}): no SOURCES given")
    endif()

    add_executable(${name} ${arg_SOURCES})
    target_link_libraries(${name} PRIVATE nmmSolid::nmmSolid ${arg_LIBRARIES})
    install(TARGETS ${name} RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}")
    set_property(GLOBAL APPEND PROPERTY NMM_APPLICATIONS ${name})
endfunction()
