#include "commands.h"

namespace lucent::cli {

int runRender(const RenderOptions&, const CommonOptions&) { return kRuntimeFailure; }

}  // namespace lucent::cli
