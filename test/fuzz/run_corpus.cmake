# Runs a fuzz target once on every file of FOLDERS (libFuzzer runs the files it is given and
# exits); fails when one crashes, leaks or times out.
set(files)
foreach(folder ${FOLDERS})
  file(GLOB found "${folder}/*")
  list(APPEND files ${found})
endforeach()
execute_process(COMMAND ${FUZZER} -timeout=10 -rss_limit_mb=2048 ${files}
  RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${FUZZER} failed (${result}):\n${out}")
endif()
