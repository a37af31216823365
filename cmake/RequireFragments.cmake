# Fails the plot run that should have written the book's fragments (cloth_add_plot's FRAGMENTS) when one is
# missing, naming it, so that a page never silently loses a measured table.
#   cmake -DPROGRAM=name "-DFILES=a|b" -P RequireFragments.cmake
string(REPLACE "|" ";" files "${FILES}")
foreach(file IN LISTS files)
  if(NOT EXISTS "${file}")
    message(FATAL_ERROR "${PROGRAM} did not write ${file}, a fragment its chapter's page includes")
  endif()
endforeach()
