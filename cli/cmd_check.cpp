#include "commands.h"

namespace lucent::cli {

int runCheck(const std::string&, const CommonOptions&) { return kRuntimeFailure; }

}  // namespace lucent::cli
