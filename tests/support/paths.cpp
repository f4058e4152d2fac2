// The one test file compiled with the absolute paths of this build (tests/CMakeLists.txt), so
// no other test object depends on where the tree was cloned and ccache can reuse them all
// in a fresh clone elsewhere on the machine.
#include "paths.h"

const char* lucentSourceDir() { return LUCENT_SOURCE_DIR; }
const char* lucentBinaryPath() { return LUCENT_BINARY; }
