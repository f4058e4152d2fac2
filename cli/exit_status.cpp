#include "exit_status.h"

#include "scenegraph/located_error.h"

#include <fmt/core.h>

#include <cstdio>
#include <new>

namespace lucent::cli {

int reportFailure(const std::exception_ptr& failure) {
  try {
    std::rethrow_exception(failure);
  } catch (const ReportedFailure& f) {
    return f.status;
  } catch (const LocatedError& e) {
    fmt::print(stderr, "{}\n", e.what());
    return e.kind() == LocatedError::Kind::Input ? kRuntimeFailure : kInvalidScene;
  } catch (const UsageError& e) {
    fmt::print(stderr, "lucent: error: {}\n", e.what());
    return kUsage;
  } catch (const std::bad_alloc&) {
    fmt::print(stderr, "lucent: error: not enough memory\n");
    return kRuntimeFailure;
  } catch (const std::exception& e) {
    // IoFailure, ImageIOError, ImagePluginError, and anything a library throws.
    fmt::print(stderr, "lucent: error: {}\n", e.what());
    return kRuntimeFailure;
  } catch (...) {
    fmt::print(stderr, "lucent: error: an unknown failure\n");
    return kRuntimeFailure;
  }
}

}  // namespace lucent::cli
