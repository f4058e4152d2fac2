// Where the tests find the source tree and the lucent binary under test.
#pragma once

// The folder of the sources (examples/, tests/data/, docs/).
const char* lucentSourceDir();
// The lucent program built beside the tests.
const char* lucentBinaryPath();
