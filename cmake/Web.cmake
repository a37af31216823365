# The book's live demos: the core compiled to WebAssembly (web/, a project of its own configured with Emscripten's
# emcmake in build/web) when Emscripten is installed (Debian package emscripten, installed by .ci/setup). The `docs`
# target then builds it and copies build/web/cloth_web.js beside the pages; without it the pages say, where a demo
# would be, that this copy of the book was built without them. The demos' check (tools/check_demos.sh) opens each
# demo in headless Chromium and compares its final state with ch10_cloth's final.dat.
option(CLOTH_WEB "Build the book's live demos (web/) with Emscripten when it is installed" ON)
find_program(CLOTH_EMCMAKE emcmake)
set(CLOTH_WEB_DIR ${CMAKE_BINARY_DIR}/web)
set(CLOTH_WEB_MODULE "")
if(CLOTH_WEB AND CLOTH_EMCMAKE AND NOT CLOTH_SANITIZE)
  set(CLOTH_WEB_MODULE ${CLOTH_WEB_DIR}/cloth_web.js)
  # Emscripten's JavaScript tools need acorn; Debian's node finds its packages in /usr/share/nodejs, another
  # node (NodeSource's) is told where they are.
  add_custom_target(web
    COMMAND ${CMAKE_COMMAND} -E env NODE_PATH=/usr/share/nodejs
            ${CLOTH_EMCMAKE} ${CMAKE_COMMAND} -S ${PROJECT_SOURCE_DIR}/web -B ${CLOTH_WEB_DIR} -DCMAKE_BUILD_TYPE=Release
    COMMAND ${CMAKE_COMMAND} -E env NODE_PATH=/usr/share/nodejs ${CMAKE_COMMAND} --build ${CLOTH_WEB_DIR} -j2
    BYPRODUCTS ${CLOTH_WEB_MODULE}
    COMMENT "web: the core compiled to WebAssembly (Emscripten)"
    VERBATIM)
elseif(CLOTH_WEB AND NOT CLOTH_EMCMAKE)
  message(STATUS "emcmake not found: the book's live demos are left out (install the Debian package emscripten)")
endif()
