# The git revision printed in the application banners is found at build
# time (not configure time), so it is never stale after a commit:
# gitRevision.C is rewritten only when the revision changes.
find_package(Git QUIET)
set(NMM_GIT_REVISION_SOURCE "${PROJECT_BINARY_DIR}/generated/gitRevision.C")
add_custom_target(nmmGitRevision
    COMMAND "${CMAKE_COMMAND}"
        "-DGIT_EXECUTABLE=${GIT_EXECUTABLE}"
        "-DSOURCE_DIR=${PROJECT_SOURCE_DIR}"
        "-DOUTPUT=${NMM_GIT_REVISION_SOURCE}"
        -P "${PROJECT_SOURCE_DIR}/cmake/nmmWriteGitRevision.cmake"
    BYPRODUCTS "${NMM_GIT_REVISION_SOURCE}"
    COMMENT "Checking the git revision"
    VERBATIM)
# Written once now as well, so the source exists when the targets are made
execute_process(COMMAND "${CMAKE_COMMAND}"
    "-DGIT_EXECUTABLE=${GIT_EXECUTABLE}"
    "-DSOURCE_DIR=${PROJECT_SOURCE_DIR}"
    "-DOUTPUT=${NMM_GIT_REVISION_SOURCE}"
    -P "${PROJECT_SOURCE_DIR}/cmake/nmmWriteGitRevision.cmake")
