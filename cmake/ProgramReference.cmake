# Writes a program's flags as Markdown tables (`PROGRAM --help-markdown`, from its cloth::CommandLine) into OUT,
# for the book's appendix on the programs (docs/back_matter/appendix_programs.md), so that the appendix lists
# each program's flags from the one place that declares them.
#   cmake -DPROGRAM=exe -DOUT=file.md -P ProgramReference.cmake
execute_process(COMMAND "${PROGRAM}" --help-markdown RESULT_VARIABLE status OUTPUT_VARIABLE text ERROR_VARIABLE error)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${PROGRAM} --help-markdown exited with ${status}: ${error}")
endif()
file(WRITE "${OUT}" "${text}")
