# A C# program whose Proxima.dll has no libproxima beside it must fail with a
# message that says what is missing and where it belongs, not a bare
# DllNotFoundException. Run with -DMONO=... -DDIR=(the build's bindings/csharp) -DWORK=(a scratch dir).
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
file(COPY "${DIR}/Proxima.dll" "${DIR}/hello.exe" DESTINATION "${WORK}")
execute_process(COMMAND "${MONO}" "${WORK}/hello.exe" mesh.obj RESULT_VARIABLE result OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
file(REMOVE_RECURSE "${WORK}")
if(result EQUAL 0)
  message(FATAL_ERROR "hello.exe succeeded without libproxima")
endif()
if(NOT "${out}${err}" MATCHES "native library \\(libproxima\\) could not be loaded.*fill_plugins.sh")
  message(FATAL_ERROR "the failure does not say what is missing:\n${out}${err}")
endif()
message(STATUS "refused as expected: exit ${result}")
