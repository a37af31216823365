# The `docs` target: Doxygen builds the book (main page, one page per chapter, API reference of src/) into
# build/docs/html/, with the figures of the `plots` target and formulas rendered by Debian's MathJax, offline.
find_package(Doxygen)
if(NOT DOXYGEN_FOUND)
  message(WARNING "Doxygen not found: the `docs` target needs it. Install the Debian package doxygen (apt-get install doxygen graphviz).")
  return()
endif()
set(CLOTH_MATHJAX_DIR /usr/share/javascript/mathjax CACHE PATH "Debian's MathJax 2 (package libjs-mathjax)")
if(NOT EXISTS ${CLOTH_MATHJAX_DIR}/MathJax.js)
  message(WARNING "MathJax not found in ${CLOTH_MATHJAX_DIR}: install the Debian package libjs-mathjax.")
endif()

set(CLOTH_DOCS_DIR ${CMAKE_BINARY_DIR}/docs)
configure_file(${PROJECT_SOURCE_DIR}/docs/Doxyfile.in ${CLOTH_DOCS_DIR}/Doxyfile @ONLY)
file(GLOB_RECURSE CLOTH_DOC_INPUTS CONFIGURE_DEPENDS
  ${PROJECT_SOURCE_DIR}/docs/*.md ${PROJECT_SOURCE_DIR}/chapters/*.md ${PROJECT_SOURCE_DIR}/chapters/*.cpp
  ${PROJECT_SOURCE_DIR}/src/*.hpp ${PROJECT_SOURCE_DIR}/src/*.cpp)

add_custom_target(docs
  COMMAND ${CMAKE_COMMAND} -E rm -rf ${CLOTH_DOCS_DIR}/html
  COMMAND ${DOXYGEN_EXECUTABLE} ${CLOTH_DOCS_DIR}/Doxyfile
  # A copy, not a link, so the html folder can be moved or served and still render formulas offline.
  COMMAND ${CMAKE_COMMAND} -E copy_directory ${CLOTH_MATHJAX_DIR} ${CLOTH_DOCS_DIR}/html/mathjax
  COMMAND ${CMAKE_COMMAND} -E echo "book: ${CLOTH_DOCS_DIR}/html/index.html"
  DEPENDS ${CLOTH_DOC_INPUTS}
  WORKING_DIRECTORY ${CLOTH_DOCS_DIR}
  COMMENT "docs: Doxygen"
  VERBATIM)
add_dependencies(docs plots)
