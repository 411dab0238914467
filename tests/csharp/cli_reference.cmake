# The C++ reference of the C# test (run by ctest as a fixture):
#   cmake -DCLI=onetip -DSCENARIO=press.yaml -DOUT=dir -P cli_reference.cmake
# writes OUT/pose.csv and OUT/markers.csv with `onetip process` over
# "sim:SCENARIO", using the simulator's exact calibration and pattern (from
# `onetip sim --field-only`, which writes them without rendering).
file(REMOVE_RECURSE ${OUT}/sim)
file(MAKE_DIRECTORY ${OUT})  # `onetip sim --out` creates only the last folder
execute_process(COMMAND ${CLI} sim --scenario ${SCENARIO} --out ${OUT}/sim --field-only --frames 1 --quiet
                RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "onetip sim failed (${status})")
endif()
execute_process(COMMAND ${CLI} process --calib ${OUT}/sim/calib.yaml --pattern ${OUT}/sim/pattern.yaml
                        --input sim:${SCENARIO} --out ${OUT}/pose.csv --markers ${OUT}/markers.csv --quiet
                RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "onetip process failed (${status})")
endif()
