# cmake -DPROGRAM=... "-DARGUMENTS=a b" -DOUTPUT=file -P write_output.cmake
# Runs PROGRAM ARGUMENTS and writes what it prints to OUTPUT (written whole, or not at all), failing the build if
# the program fails. Used for the bash completion script, which the program generates from its own flags.
separate_arguments(arguments UNIX_COMMAND "${ARGUMENTS}")
execute_process(COMMAND ${PROGRAM} ${arguments} OUTPUT_VARIABLE text RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${PROGRAM} ${ARGUMENTS} failed (${result})")
endif()
get_filename_component(folder "${OUTPUT}" DIRECTORY)
file(MAKE_DIRECTORY "${folder}")
file(WRITE "${OUTPUT}.tmp" "${text}")
file(RENAME "${OUTPUT}.tmp" "${OUTPUT}")
