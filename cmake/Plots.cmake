# The `plots` target: every chapter program writes its data and its gnuplot script turns it into PNG figures
# in build/plots/. A chapter registers its figures with cloth_add_plot(); runs are independent custom commands,
# so `cmake --build build --target plots -j2` spreads them over both cores.
find_program(GNUPLOT_EXECUTABLE gnuplot)
if(NOT GNUPLOT_EXECUTABLE)
  message(WARNING "gnuplot not found: the `plots` and `docs` targets need it. Install the Debian package gnuplot-nox (apt-get install gnuplot-nox).")
endif()

set(CLOTH_PLOT_DIR ${CMAKE_BINARY_DIR}/plots CACHE INTERNAL "Where the figures go")
set(CLOTH_PLOT_DATA_DIR ${CMAKE_BINARY_DIR}/plots/data CACHE INTERNAL "Where the figures' data go")
add_custom_target(plots)

# cloth_add_plot(NAME run_name TARGET exe [SCRIPT file.gp] [ARGS program flags...] [FIGURES a.png ...]
#                [TEST_ARGS flags...] [FRAGMENTS table.md ...])
# Runs `exe ARGS --out build/plots/data/run_name`, then
# `gnuplot -e "data='<that folder>'; plots='build/plots'" file.gp`.
# A program that declares its outputs (src/program/output_spec.hpp: `exe ARGS --list-outputs`) is checked against
# that declaration after the run (cmake/CheckOutputs.cmake): a declared file it did not write, a file it wrote but
# did not declare, a page including a file of run_name/ that is not a declared fragment, or a declared fragment no
# page includes fails the run. The same check is the test outputs_run_name, on the declaration and the pages alone,
# or, given TEST_ARGS (a small, quick version of the run: `--grid 6x6 --t-end 0.05`), on a run with ARGS TEST_ARGS
# too. The program's plot runs are collected on its target (CLOTH_PLOT_RUNS), so that a fragment included only from
# another run's folder (ch07_stability_60/run_time.md) counts as included. The declaration is also written as a
# table for the book's appendix on the programs (build/plots/data/programs/run_name_outputs.md).
# FRAGMENTS, for a program that does not declare its outputs yet: the files of that folder the chapter's page
# includes (`\include{doc} run_name/table.md`, see src/program/fragment.hpp); the run fails when one is missing.
function(cloth_add_plot)
  cmake_parse_arguments(P "" "NAME;TARGET;SCRIPT" "ARGS;FIGURES;FRAGMENTS;TEST_ARGS" ${ARGN})
  set(data ${CLOTH_PLOT_DATA_DIR}/${P_NAME})
  set(stamp ${data}.stamp)
  set(figures "")
  foreach(f IN LISTS P_FIGURES)
    list(APPEND figures ${CLOTH_PLOT_DIR}/${f})
  endforeach()
  set(fragments "")
  foreach(f IN LISTS P_FRAGMENTS)
    list(APPEND fragments ${data}/${f})
  endforeach()
  list(JOIN fragments "|" fragment_list)  # one command-line argument; RequireFragments.cmake splits it
  list(JOIN P_ARGS "|" args_list)
  set_property(TARGET ${P_TARGET} APPEND PROPERTY CLOTH_PLOT_RUNS ${P_NAME})
  set(runs "$<JOIN:$<TARGET_PROPERTY:${P_TARGET},CLOTH_PLOT_RUNS>,|>")
  if(P_FRAGMENTS)
    set(check -DPROGRAM=${P_TARGET} "-DFILES=${fragment_list}" -P ${PROJECT_SOURCE_DIR}/cmake/RequireFragments.cmake)
  else()
    set(check -DPROGRAM=$<TARGET_FILE:${P_TARGET}> "-DARGS=${args_list}" -DRUN=${P_NAME} "-DRUNS=${runs}"
              -DSOURCE=${PROJECT_SOURCE_DIR} -DWRITTEN=${data}
              -DREFERENCE=${CLOTH_PLOT_DATA_DIR}/programs/${P_NAME}_outputs.md
              -P ${PROJECT_SOURCE_DIR}/cmake/CheckOutputs.cmake)
    list(JOIN P_TEST_ARGS "|" test_args_list)
    set(test_run "")
    if(P_TEST_ARGS)
      set(test_run "-DARGS=${args_list}|${test_args_list}" -DRUN_FIRST=ON
                   -DWRITTEN=${CMAKE_BINARY_DIR}/tests/outputs/${P_NAME})
    else()
      set(test_run "-DARGS=${args_list}")
    endif()
    add_test(NAME outputs_${P_NAME}
             COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:${P_TARGET}> ${test_run} -DRUN=${P_NAME}
                     "-DRUNS=${runs}" -DSOURCE=${PROJECT_SOURCE_DIR} -P ${PROJECT_SOURCE_DIR}/cmake/CheckOutputs.cmake)
    set_tests_properties(outputs_${P_NAME} PROPERTIES LABELS outputs)
  endif()
  # A run without SCRIPT writes only fragments for its page (a benchmark's measured table): no gnuplot step.
  if(P_SCRIPT)
    get_filename_component(script ${P_SCRIPT} ABSOLUTE)
    set(draw ${GNUPLOT_EXECUTABLE} -e)
    set(draw_expression "data='${data}'; plots='${CLOTH_PLOT_DIR}'")
  else()
    set(script "")
    set(draw ${CMAKE_COMMAND} -E)
    set(draw_expression true)
  endif()
  add_custom_command(
    OUTPUT ${stamp}
    BYPRODUCTS ${figures} ${fragments}
    COMMAND ${CMAKE_COMMAND} -E rm -rf ${data}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${CLOTH_PLOT_DIR} ${CLOTH_PLOT_DATA_DIR}/programs
    COMMAND $<TARGET_FILE:${P_TARGET}> ${P_ARGS} --out ${data}
    COMMAND ${CMAKE_COMMAND} ${check}
    COMMAND ${draw} "${draw_expression}" ${script}
    COMMAND ${CMAKE_COMMAND} -E touch ${stamp}
    DEPENDS ${P_TARGET} ${script} ${PROJECT_SOURCE_DIR}/cmake/RequireFragments.cmake
            ${PROJECT_SOURCE_DIR}/cmake/CheckOutputs.cmake
    WORKING_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}
    COMMENT "plots: ${P_NAME}"
    VERBATIM)
  add_custom_target(plot_${P_NAME} DEPENDS ${stamp})
  add_dependencies(plots plot_${P_NAME})
endfunction()
