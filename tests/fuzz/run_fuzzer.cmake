# Runs the case-file fuzzer for SECONDS from the seeds in SEEDS, with a corpus in CORPUS:
#   cmake -DFUZZER=case_fuzzer -DSEEDS=dir -DCORPUS=dir -DSECONDS=60 -P run_fuzzer.cmake
# Fails on any finding (libFuzzer exits non-zero and writes the input as crash-*/leak-*/
# timeout-* in the corpus' parent directory).
file(MAKE_DIRECTORY "${CORPUS}")
get_filename_component(artifacts "${CORPUS}" DIRECTORY)
execute_process(
  COMMAND "${FUZZER}" "${CORPUS}" "${SEEDS}" -max_total_time=${SECONDS} -rss_limit_mb=2048
          -timeout=10 -print_final_stats=1 -artifact_prefix=${artifacts}/
  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(REGEX MATCH "Done [0-9]+ runs in [0-9]+ second" done "${err}")
if(NOT code EQUAL 0 OR NOT done)
  message(FATAL_ERROR "the fuzzer found a problem (exit ${code}):\n${err}")
endif()
message(STATUS "${done}s, no crash, leak, timeout or undefined behaviour")
