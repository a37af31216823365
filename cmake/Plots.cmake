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
#                [FRAGMENTS table.md ...])
# Runs `exe ARGS --out build/plots/data/run_name`, then
# `gnuplot -e "data='<that folder>'; plots='build/plots'" file.gp`.
# FRAGMENTS are the files of that folder the chapter's page includes (`\include{doc} run_name/table.md`, see
# src/program/fragment.hpp): the run fails when the program did not write one of them.
function(cloth_add_plot)
  cmake_parse_arguments(P "" "NAME;TARGET;SCRIPT" "ARGS;FIGURES;FRAGMENTS" ${ARGN})
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
    COMMAND ${CMAKE_COMMAND} -E make_directory ${CLOTH_PLOT_DIR}
    COMMAND $<TARGET_FILE:${P_TARGET}> ${P_ARGS} --out ${data}
    COMMAND ${CMAKE_COMMAND} -DPROGRAM=${P_TARGET} "-DFILES=${fragment_list}"
            -P ${PROJECT_SOURCE_DIR}/cmake/RequireFragments.cmake
    COMMAND ${draw} "${draw_expression}" ${script}
    COMMAND ${CMAKE_COMMAND} -E touch ${stamp}
    DEPENDS ${P_TARGET} ${script} ${PROJECT_SOURCE_DIR}/cmake/RequireFragments.cmake
    WORKING_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}
    COMMENT "plots: ${P_NAME}"
    VERBATIM)
  add_custom_target(plot_${P_NAME} DEPENDS ${stamp})
  add_dependencies(plots plot_${P_NAME})
endfunction()
