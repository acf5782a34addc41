# Runs SAMPLE and fails when it fails or when the core validation layer
# wrote an error to LOG. cmake -DSAMPLE=... -DLOG=... -P run_sample.cmake
file(REMOVE ${LOG})
execute_process(COMMAND ${SAMPLE} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${SAMPLE} failed (${rc})")
endif()
if(EXISTS ${LOG})
  file(READ ${LOG} log)
  if(log MATCHES "VALID_ERROR")
    message(FATAL_ERROR "the core validation layer reported errors:\n${log}")
  endif()
endif()
