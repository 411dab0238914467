// Where a test finds the checkout, its data and the `onetip` program of its build tree.
// The absolute paths are compiled into one small object (test_paths.cpp, library
// onetip_test_paths) rather than into every test object, so a compiler cache keyed on
// paths relative to the checkout (.ci/build-env.sh) serves a clone in another folder
// every test object but that one.
#pragma once

namespace onetip::test {

/// The checkout's root folder, absolute.
const char* sourceDir();
/// tests/data of the checkout, absolute.
const char* testDataDir();
/// The `onetip` command-line program of this build tree, absolute.
const char* cliPath();

}  // namespace onetip::test
