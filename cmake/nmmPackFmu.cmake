# Pack a tutorial case as an FMU (cmake -P, run by the build):
#   -DCASE=<tutorial case> -DWORK=<scratch case> -DFMU=<output .fmu>
#   -DMESH=<nmmMesh> -DEXPORT=<nmmFmuExport> -DBINARY=<nmmSolidFmi3.so>
# The case is copied (its 0, constant and system) so that the source tree
# is not written to; the logs stay beside the scratch case.
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
foreach(dir 0 constant system)
    file(COPY "${CASE}/${dir}" DESTINATION "${WORK}"
        PATTERN "nmmMesh" EXCLUDE)
endforeach()
foreach(step "${MESH};-case;${WORK}" "${EXPORT};-case;${WORK};-o;${FMU};-binary;${BINARY}")
    list(GET step 0 exe)
    get_filename_component(name "${exe}" NAME)
    execute_process(COMMAND ${step} RESULT_VARIABLE rc
        OUTPUT_FILE "${WORK}/log.${name}" ERROR_FILE "${WORK}/log.${name}")
    if(NOT rc EQUAL 0)
        file(READ "${WORK}/log.${name}" log)
        message(FATAL_ERROR "${name} failed on ${CASE}:\n${log}")
    endif()
endforeach()
