# Pack a tutorial case as an FMU (cmake -P, run by the build):
#   -DCASE=<tutorial case> -DFMU=<output .fmu> -DEXPORT=<nmmFmuExport>
#   -DBINARY=<nmmSolidFmi3.so>
# nmmFmuExport only reads the case; its log goes beside the FMU, and is
# shown when it fails.
get_filename_component(dir "${FMU}" DIRECTORY)
file(MAKE_DIRECTORY "${dir}")
set(log "${FMU}.log")
execute_process(COMMAND "${EXPORT}" -case "${CASE}" -o "${FMU}" -binary "${BINARY}"
    RESULT_VARIABLE rc OUTPUT_FILE "${log}" ERROR_FILE "${log}")
if(NOT rc EQUAL 0)
    file(READ "${log}" text)
    message(FATAL_ERROR "nmmFmuExport failed on ${CASE}:\n${text}")
endif()
