# Writes a program's flags as Markdown tables (`PROGRAM --help-markdown`, from its cloth::CommandLine) into OUT,
# for the book's appendix on the programs (docs/back_matter/appendix_programs.md), so that the appendix lists
# each program's flags from the one place that declares them.
#   cmake -DPROGRAM=exe -DOUT=file.md -P ProgramReference.cmake
# ARGUMENT replaces `--help-markdown` for tools/flag_tables, which prints the flags the programs share.
if(NOT DEFINED ARGUMENT)
  set(ARGUMENT --help-markdown)
endif()
execute_process(COMMAND "${PROGRAM}" ${ARGUMENT} RESULT_VARIABLE status OUTPUT_VARIABLE text ERROR_VARIABLE error)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${PROGRAM} ${ARGUMENT} exited with ${status}: ${error}")
endif()
file(WRITE "${OUT}" "${text}")
