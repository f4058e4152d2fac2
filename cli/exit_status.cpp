#include "exit_status.h"

#include "scenegraph/located_error.h"

#include <fmt/core.h>

#include <cstdio>
#include <new>

namespace lucent::cli {

Failure describeFailure(const std::exception_ptr& failure) {
  try {
    std::rethrow_exception(failure);
  } catch (const ReportedFailure& f) {
    return {f.status, ""};
  } catch (const LocatedError& e) {
    return {e.kind() == LocatedError::Kind::Input ? kRuntimeFailure : kInvalidScene, e.what()};
  } catch (const UsageError& e) {
    return {kUsage, fmt::format("lucent: error: {}", e.what())};
  } catch (const std::bad_alloc&) {
    return {kRuntimeFailure, "lucent: error: not enough memory"};
  } catch (const std::exception& e) {
    // IoFailure, ImageIOError, ImagePluginError, and anything a library throws.
    return {kRuntimeFailure, fmt::format("lucent: error: {}", e.what())};
  } catch (...) {
    return {kRuntimeFailure, "lucent: error: an unknown failure"};
  }
}

int reportFailure(const std::exception_ptr& failure) {
  const Failure f = describeFailure(failure);
  if (!f.message.empty()) fmt::print(stderr, "{}\n", f.message);
  return f.status;
}

}  // namespace lucent::cli
