# Runs SAMPLE and fails when it fails or when the core validation layer
# wrote an error to LOG.
#   cmake -DSAMPLE=... -DLOG=... [-DEXPECT_ERROR=regex] [-DMAX_SYNC_RATE=n] -P run_sample.cmake
# EXPECT_ERROR: the sample must fail instead, saying something that matches.
# MAX_SYNC_RATE: its frame loop must sync at most n times a second, as the
# mock runtime reports it (PROX_MOCK_XR_REPORT): a loop that does not pace
# itself runs at tens of thousands; a busy machine only lowers the rate.
file(REMOVE ${LOG})
execute_process(COMMAND ${SAMPLE} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(DEFINED EXPECT_ERROR)
  if(rc EQUAL 0)
    message(FATAL_ERROR "${SAMPLE} succeeded; it should have failed saying '${EXPECT_ERROR}'")
  endif()
  if(NOT err MATCHES "${EXPECT_ERROR}")
    message(FATAL_ERROR "${SAMPLE} failed (${rc}) without saying '${EXPECT_ERROR}'")
  endif()
elseif(NOT rc EQUAL 0)
  message(FATAL_ERROR "${SAMPLE} failed (${rc})")
endif()
if(DEFINED MAX_SYNC_RATE)
  if(NOT err MATCHES "mock runtime: ([0-9]+) xrSyncActions, [0-9]+ xrWaitFrame in ([0-9]+)\\.([0-9][0-9][0-9]) s")
    message(FATAL_ERROR "the mock runtime reported no call counts (is PROX_MOCK_XR_REPORT set?)")
  endif()
  math(EXPR ms "${CMAKE_MATCH_2} * 1000 + 1${CMAKE_MATCH_3} - 1000")
  math(EXPR rate "${CMAKE_MATCH_1} * 1000 / (${ms} + 1)")
  if(rate GREATER MAX_SYNC_RATE)
    message(FATAL_ERROR "the frame loop synced ${rate} times a second (at most ${MAX_SYNC_RATE}): it does not pace itself")
  endif()
endif()
if(EXISTS ${LOG})
  file(READ ${LOG} log)
  if(log MATCHES "VALID_ERROR")
    message(FATAL_ERROR "the core validation layer reported errors:\n${log}")
  endif()
endif()
