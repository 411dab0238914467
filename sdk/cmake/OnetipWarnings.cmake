# Warnings are errors in onetip's own code. Third-party headers come in through
# imported targets, which CMake marks SYSTEM, so they are not held to this.
# -Wno-restrict: GCC 12 reports false positives inside std::string at -O2
# (GCC bug 105329), which would otherwise fail Release builds; clang (the fuzz
# build, tests/fuzz) has no such option.
add_library(onetip_warnings INTERFACE)
target_compile_options(onetip_warnings INTERFACE
  $<$<COMPILE_LANGUAGE:CXX>:-Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Werror>
  $<$<AND:$<COMPILE_LANGUAGE:CXX>,$<CXX_COMPILER_ID:GNU>>:-Wno-restrict>
  $<$<COMPILE_LANGUAGE:C>:-Wall -Wextra -Wpedantic -Werror>)

# onetip_module(NAME SOURCES ... DEPS ...): one static, position-independent
# library per SDK module (sdk/src/<module>). Tests and the command-line tool
# link these directly; the shared library onetip::onetip links them and
# exports only the public API.
function(onetip_module name)
  cmake_parse_arguments(M "" "" "SOURCES;DEPS" ${ARGN})
  add_library(onetip_${name} STATIC ${M_SOURCES})
  target_include_directories(onetip_${name} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/sdk/src>
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/sdk/include>
    $<BUILD_INTERFACE:${PROJECT_BINARY_DIR}/sdk/include>)
  target_link_libraries(onetip_${name} PUBLIC ${M_DEPS} PRIVATE onetip_warnings)
endfunction()
