# Fails when LIBRARY needs the OpenXR loader: a NEEDED entry for it, or an
# undefined xr* symbol (every OpenXR call must go through the app's
# xrGetInstanceProcAddr). Run as cmake -DLIBRARY=... -P no_loader.cmake.
find_program(READELF readelf REQUIRED)
execute_process(COMMAND ${READELF} --dynamic ${LIBRARY} OUTPUT_VARIABLE dynamic RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "readelf --dynamic ${LIBRARY} failed")
endif()
if(dynamic MATCHES "NEEDED[^\n]*openxr")
  message(FATAL_ERROR "${LIBRARY} links the OpenXR loader:\n${dynamic}")
endif()
execute_process(COMMAND ${READELF} --dyn-syms --wide ${LIBRARY} OUTPUT_VARIABLE symbols RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "readelf --dyn-syms ${LIBRARY} failed")
endif()
string(REGEX MATCHALL "UND[ \t]+xr[A-Za-z0-9_]*" undefined "${symbols}")
if(undefined)
  message(FATAL_ERROR "${LIBRARY} calls OpenXR functions directly: ${undefined}")
endif()
# And it must export the OpenXR device's C API (or this test checks nothing).
if(NOT symbols MATCHES "proxWorld_CreateXrDevice")
  message(FATAL_ERROR "${LIBRARY} does not export proxWorld_CreateXrDevice: built without PROX_WITH_OPENXR?")
endif()
message(STATUS "${LIBRARY}: no OpenXR loader, no direct xr* call, the XR device exported")
