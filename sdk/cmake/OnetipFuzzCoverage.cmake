# libFuzzer's coverage instrumentation (-fsanitize=fuzzer-no-link), with ONETIP_FUZZ only, for the
# code the harnesses of tests/fuzz parse and decode: core (calibration, pattern, options files),
# capture (frames), haptics (datasets, queries), os_outputs (the spnav protocol), the shared library's
# option entry points and C ABI, the simulator's scenario parser and the DDS link's readers (dds, when
# built; sdk/src/dds/CMakeLists.txt). The harnesses learn from
# coverage there alone. The rest (the vision front end, contact, pose, the simulator's contact solver
# and renderer) is reached by no harness; instrumented, it made the sanitizer leg's tests 1.7 times
# slower (measured on the pose accuracy tests: 3.6 s under ASan + UBSan, 6.2 s with the coverage
# instrumentation as well) for no coverage a harness uses.
#   onetip_fuzz_coverage(TARGETS target... [SOURCES dir:file...])
function(onetip_fuzz_coverage)
  if(NOT ONETIP_FUZZ)
    return()
  endif()
  cmake_parse_arguments(F "" "" "TARGETS;SOURCES" ${ARGN})
  foreach(target ${F_TARGETS})
    target_compile_options(${target} PRIVATE -fsanitize=fuzzer-no-link)
  endforeach()
  foreach(entry ${F_SOURCES})
    string(REPLACE ":" ";" parts ${entry})
    list(GET parts 0 target)
    list(GET parts 1 file)
    set_source_files_properties(${file} TARGET_DIRECTORY ${target} PROPERTIES COMPILE_OPTIONS -fsanitize=fuzzer-no-link)
  endforeach()
endfunction()
