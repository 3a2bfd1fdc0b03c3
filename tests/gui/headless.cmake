# `alp85 gui` without a display: exit status 2 and a message naming the headless commands.
execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=DISPLAY --unset=WAYLAND_DISPLAY ${ALP85} gui
                RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_VARIABLE out)
if(NOT rc EQUAL 2)
  message(FATAL_ERROR "expected exit status 2, got ${rc}: ${err}")
endif()
if(NOT err MATCHES "alp85 run" OR NOT err MATCHES "alp85 script")
  message(FATAL_ERROR "the message does not name alp85 run and alp85 script: ${err}")
endif()
message(STATUS "status 2: ${err}")
# A --signals pin the board does not have is refused before any window opens (2, naming the pin).
execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=DISPLAY --unset=WAYLAND_DISPLAY ${ALP85} gui --signals PA0 PA9
                RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_VARIABLE out)
if(NOT rc EQUAL 2 OR NOT err MATCHES "--signals: no pin 'PA9' on the board")
  message(FATAL_ERROR "--signals PA9: expected status 2 naming PA9, got ${rc}: ${err}")
endif()
