// The one map from a failure to the contract's exit statuses (0 ok, 1 wrong usage,
// 2 invalid scene, 3 input/output or runtime failure), and the failures the commands throw.
#pragma once

#include <exception>
#include <stdexcept>
#include <string>

namespace lucent::cli {

// The contract's exit statuses.
enum ExitCode { kOk = 0, kUsage = 1, kInvalidScene = 2, kRuntimeFailure = 3 };

// A request the scene cannot satisfy or an option out of range (exit 1).
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// An input or output the command cannot read or write (exit 3), said in the message.
struct IoFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A failure already printed (the parser's diagnostics), carrying only its status.
struct ReportedFailure {
  int status;
};

// A failure's exit status and the message the command line reports it with ("" for a
// ReportedFailure, already printed).
struct Failure {
  int status;
  std::string message;
};
Failure describeFailure(const std::exception_ptr& failure);

// Prints the failure as the command line reports it and returns its exit status:
// LocatedError as "file:line:col: error: ..." (2, or 3 for a file the scene names that
// cannot be read), everything else as "lucent: error: ...".
int reportFailure(const std::exception_ptr& failure);

}  // namespace lucent::cli
