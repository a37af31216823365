# Checks a program's declared outputs (src/program/output_spec.hpp, printed by `--list-outputs`) against the book's
# pages and, when asked, against what a run wrote, failing with one line per difference:
#  - a page of the book includes (`\include{doc}` or `\verbinclude`) RUN/FILE and FILE is not a declared fragment;
#  - a declared fragment that no page includes under any of the program's plot runs (RUNS);
#  - with WRITTEN: a declared file the run did not write into WRITTEN, or a file it wrote there but did not declare.
# The plot runs call it after each run (cloth_add_plot), and CTest calls it as the test outputs_RUN.
# With REFERENCE it also writes the declaration as a Markdown table there, for the book's appendix on the programs.
#   cmake -DPROGRAM=exe "-DARGS=a|b" -DRUN=name "-DRUNS=name|name_60" -DSOURCE=<repo> [-DWRITTEN=<folder>]
#         [-DRUN_FIRST=ON] [-DREFERENCE=file.md] -P CheckOutputs.cmake
# With RUN_FIRST the script makes the run itself (`exe ARGS --out WRITTEN`, after emptying WRITTEN): the test's way.
string(REPLACE "|" ";" args "${ARGS}")
string(REPLACE "|" ";" runs "${RUNS}")
get_filename_component(program_name "${PROGRAM}" NAME)
set(out "${WRITTEN}")
if(NOT out)
  set(out "${CMAKE_CURRENT_BINARY_DIR}/${RUN}.listing")  # --list-outputs writes nothing: any folder name will do
endif()

if(RUN_FIRST)
  file(REMOVE_RECURSE "${out}")
  execute_process(COMMAND "${PROGRAM}" ${args} --out "${out}" RESULT_VARIABLE status OUTPUT_QUIET ERROR_VARIABLE error)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${program_name} ${ARGS} exited with ${status}: ${error}")
  endif()
endif()

execute_process(COMMAND "${PROGRAM}" ${args} --out "${out}" --list-outputs
                RESULT_VARIABLE status OUTPUT_VARIABLE listing ERROR_VARIABLE error)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${program_name} --list-outputs exited with ${status}: ${error}")
endif()
set(declared "")
set(fragments "")
set(table "| file | read by | holds |\n|---|---|---|\n")
string(REPLACE ";" "," listing "${listing}")  # a ';' in a description would split CMake's list
string(REPLACE "\n" ";" lines "${listing}")
foreach(line IN LISTS lines)
  if(line STREQUAL "")
    continue()
  endif()
  string(REPLACE "\t" ";" fields "${line}")
  list(GET fields 0 name)
  list(GET fields 1 kind)
  list(GET fields 2 holds)
  list(APPEND declared "${name}")
  set(reader "a page (fragment)")
  if(kind STREQUAL "figure_input")
    set(reader "a figure")
  elseif(kind STREQUAL "data")
    set(reader "the reader")
  endif()
  string(REPLACE "|" "\\|" holds "${holds}")  # a bare "|" would end the cell; Doxygen prints an escaped one
  string(REGEX REPLACE "(^|[ (])(--[a-z][a-z0-9-]*)" "\\1`\\2`" holds "${holds}")  # a flag as code, not a dash
  string(APPEND table "| `${name}` | ${reader} | ${holds} |\n")
  if(kind STREQUAL "fragment")
    list(APPEND fragments "${name}")
  endif()
endforeach()

set(problems "")

# The pages: every file included from this run's folder is one of its declared fragments, and every declared
# fragment is included from the folder of one of the program's runs.
file(GLOB_RECURSE pages "${SOURCE}/chapters/*.md" "${SOURCE}/docs/*.md")
list(FILTER pages EXCLUDE REGEX "/claims\\.md$")  # the claims tables are not pages of the book
set(included_here "")
set(included_anywhere "")
foreach(page IN LISTS pages)
  file(READ "${page}" text)
  foreach(run IN LISTS runs)
    string(REGEX MATCHALL "\\\\(include{doc}|verbinclude)[ \t]+${run}/[^ \t\r\n]+" hits "${text}")
    foreach(hit IN LISTS hits)
      string(REGEX REPLACE "^.*[ \t]${run}/" "" file_name "${hit}")
      list(APPEND included_anywhere "${file_name}")
      if(run STREQUAL RUN)
        list(APPEND included_here "${file_name}")
        list(FIND fragments "${file_name}" at)
        if(at EQUAL -1)
          get_filename_component(page_name "${page}" NAME)
          list(APPEND problems "${page_name} includes ${RUN}/${file_name}, which ${program_name} does not declare as a fragment")
        endif()
      endif()
    endforeach()
  endforeach()
endforeach()
foreach(name IN LISTS fragments)
  list(FIND included_anywhere "${name}" at)
  if(at EQUAL -1)
    list(APPEND problems "${program_name} declares the fragment ${name}, which no page includes (declare it as data or figure_input)")
  endif()
endforeach()

# The run: what it wrote is what it declared.
if(WRITTEN)
  foreach(name IN LISTS declared)
    if(NOT EXISTS "${out}/${name}")
      list(APPEND problems "${program_name} did not write ${name}, which it declares")
    endif()
  endforeach()
  file(GLOB_RECURSE written RELATIVE "${out}" "${out}/*")
  foreach(name IN LISTS written)
    list(FIND declared "${name}" at)
    if(at EQUAL -1)
      list(APPEND problems "${program_name} wrote ${name}, which it does not declare")
    endif()
  endforeach()
endif()

if(REFERENCE)
  file(WRITE "${REFERENCE}" "${table}")
endif()

if(problems)
  list(JOIN problems "\n  " text)
  message(FATAL_ERROR "${RUN}: the outputs differ from ${program_name}'s declaration (--list-outputs):\n  ${text}")
endif()
