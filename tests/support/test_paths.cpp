// The paths of test_paths.hpp, given by CMake as definitions of this file alone.
#include "test_paths.hpp"

namespace onetip::test {

const char* sourceDir() { return ONETIP_SOURCE_DIR; }
const char* testDataDir() { return ONETIP_TEST_DATA_DIR; }
const char* cliPath() { return ONETIP_CLI; }

}  // namespace onetip::test
