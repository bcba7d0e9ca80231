# The git revision printed in the solver banner; "unknown" outside a checkout.
find_package(Git QUIET)
set(NMM_GIT_REVISION "unknown")
if(GIT_FOUND AND EXISTS "${PROJECT_SOURCE_DIR}/.git")
    execute_process(
        COMMAND "${GIT_EXECUTABLE}" describe --always --dirty --abbrev=12
        WORKING_DIRECTORY "${PROJECT_SOURCE_DIR}"
        OUTPUT_VARIABLE NMM_GIT_REVISION
        OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
    if(NOT NMM_GIT_REVISION)
        set(NMM_GIT_REVISION "unknown")
    endif()
endif()
