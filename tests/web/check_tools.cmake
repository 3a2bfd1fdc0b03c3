# What the web test needs is there: node, puppeteer-core in tests/web, chromium and emscripten.
#   cmake -DNODE=<node> -DCLIENT=<puppeteer-core's package.json> -DCHROMIUM=<path> -DEMCMAKE=<path> -P check_tools.cmake
if(NOT NODE OR NODE MATCHES "NOTFOUND")
  message(FATAL_ERROR "node is not installed: run scripts/setup.sh --tests")
endif()
if(NOT EXISTS "${CLIENT}")
  message(FATAL_ERROR "puppeteer-core is not installed in tests/web: run scripts/setup.sh --tests")
endif()
if(NOT EXISTS "${CHROMIUM}")
  message(FATAL_ERROR "chromium is not installed (${CHROMIUM}): run scripts/setup.sh --tests")
endif()
if(NOT EMCMAKE OR EMCMAKE MATCHES "NOTFOUND")
  message(FATAL_ERROR "emscripten is not installed (no emcmake): run scripts/setup.sh --tests")
endif()
