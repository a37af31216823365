# The `docs` target: Doxygen builds the book (main page, one page per chapter, API reference of src/) into
# build/docs/html/, with the figures of the `plots` target, the tables and sentences the chapter programs measured
# (their fragments, src/program/fragment.hpp), and formulas rendered by Debian's MathJax, offline.
# The `check_book` target then opens every page in headless Chromium (tools/check_book/check_book.sh).

# The browser check's own test: on a small folder of pages with one defect of each kind, it must find every one
# and nothing else (tools/check_book/fixture/, tools/check_book/check_book_selftest.sh). It needs Chromium and
# MathJax, and no compiled code, so the sanitizer build leaves it out.
set(CLOTH_MATHJAX_DIR /usr/share/javascript/mathjax CACHE PATH "Debian's MathJax 2 (package libjs-mathjax)")
find_program(CLOTH_CHROMIUM chromium)
if(CLOTH_CHROMIUM AND NOT CLOTH_SANITIZE)
  add_test(NAME check_book_finds_each_defect
           COMMAND bash ${PROJECT_SOURCE_DIR}/tools/check_book/check_book_selftest.sh ${CLOTH_MATHJAX_DIR})
  set_tests_properties(check_book_finds_each_defect PROPERTIES LABELS docs TIMEOUT 300)
elseif(NOT CLOTH_CHROMIUM)
  message(STATUS "chromium not found: the browser check of the book (tools/check_book/check_book.sh) and its test are left out")
endif()
find_package(Doxygen)
if(NOT DOXYGEN_FOUND)
  message(WARNING "Doxygen not found: the `docs` target needs it. Install the Debian package doxygen (apt-get install doxygen graphviz).")
  return()
endif()
if(NOT EXISTS ${CLOTH_MATHJAX_DIR}/MathJax.js)
  message(WARNING "MathJax not found in ${CLOTH_MATHJAX_DIR}: install the Debian package libjs-mathjax.")
endif()

set(CLOTH_DOCS_DIR ${CMAKE_BINARY_DIR}/docs)
configure_file(${PROJECT_SOURCE_DIR}/docs/Doxyfile.in ${CLOTH_DOCS_DIR}/Doxyfile @ONLY)
file(GLOB_RECURSE CLOTH_DOC_INPUTS CONFIGURE_DEPENDS
  ${PROJECT_SOURCE_DIR}/docs/*.md ${PROJECT_SOURCE_DIR}/chapters/*.md ${PROJECT_SOURCE_DIR}/chapters/*.cpp
  ${PROJECT_SOURCE_DIR}/src/*.hpp ${PROJECT_SOURCE_DIR}/src/*.cpp ${PROJECT_SOURCE_DIR}/web/*.js)

add_custom_target(docs
  COMMAND ${CMAKE_COMMAND} -E rm -rf ${CLOTH_DOCS_DIR}/html
  COMMAND ${DOXYGEN_EXECUTABLE} ${CLOTH_DOCS_DIR}/Doxyfile
  # A copy, not a link, so the html folder can be moved or served and still render formulas offline.
  COMMAND ${CMAKE_COMMAND} -E copy_directory ${CLOTH_MATHJAX_DIR} ${CLOTH_DOCS_DIR}/html/mathjax
  # The live demos' module, when it was built (cmake/Web.cmake); the pages load it from beside themselves.
  COMMAND ${CMAKE_COMMAND} -E $<IF:$<BOOL:${CLOTH_WEB_MODULE}>,copy,true> ${CLOTH_WEB_MODULE} ${CLOTH_DOCS_DIR}/html/
  COMMAND ${CMAKE_COMMAND} -E echo "book: ${CLOTH_DOCS_DIR}/html/index.html"
  DEPENDS ${CLOTH_DOC_INPUTS}
  WORKING_DIRECTORY ${CLOTH_DOCS_DIR}
  COMMENT "docs: Doxygen"
  VERBATIM)
add_dependencies(docs plots)
if(CLOTH_WEB_MODULE)
  add_dependencies(docs web)
endif()

# The browser check of the book (tools/check_book/check_book.sh): every page opened in headless Chromium, failing
# on a formula error, a missing image, a broken link or a figure or table wider than the page. It builds the book
# first.
add_custom_target(check_book
  COMMAND bash ${PROJECT_SOURCE_DIR}/tools/check_book/check_book.sh ${CLOTH_DOCS_DIR}/html
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
  COMMENT "check_book: every page of the book in headless Chromium"
  VERBATIM)
add_dependencies(check_book docs)
