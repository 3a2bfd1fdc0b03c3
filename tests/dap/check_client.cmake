# The DAP tests' client is there: node, and @vscode/debugadapter-testsupport in tests/dap.
#   cmake -DNODE=<node> -DCLIENT=<its package.json> -P check_client.cmake
if(NOT NODE OR NODE MATCHES "NOTFOUND")
  message(FATAL_ERROR "node is not installed: run scripts/setup.sh --tests (it installs nodejs and the DAP test client)")
endif()
if(NOT EXISTS "${CLIENT}")
  message(FATAL_ERROR "@vscode/debugadapter-testsupport is not installed in tests/dap: run scripts/setup.sh --tests")
endif()
