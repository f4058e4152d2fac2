// Running the `povray` program: finding it, its command line for a comparison render
// (no display, 16-bit linear PNG), and a run with its messages captured in a log file.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace lucent {

// The povray executable: $LUCENT_POVRAY if set, else `povray` on the PATH.
std::optional<std::string> findPovray();

// What to tell a user who has no povray.
const char* povrayInstallHint();

struct PovrayRender {
  std::string input;   // .pov file
  std::string output;  // .png, written as 16-bit linear values
  int width = 0, height = 0;
  int samples = 1;  // 1: no antialiasing (pixel centres, as Lucent's single sample)
  // Lucent's adaptive-mode="corners" (samples is then not used): POV-Ray's own method 2.
  bool corners = false;
  double cornerThreshold = 0.3;
  int cornerDepth = 3;
  int threads = 0;  // 0: POV-Ray's default
  // File_Gamma: 1.0 writes linear values; a scene with another assumed_gamma needs that
  // gamma here to write its working values (pov_gamma.h).
  std::string fileGamma = "1.0";
  // POV-Ray's clock (+K): the clock of the frame compared, for a hand-written scene that
  // reads `clock`. Left out of the command when 0 (POV-Ray's own default).
  double clock = 0.0;
  // Further options, in order, after all of the above (a POV-Ray scene compared as it is:
  // its Declare=, +L folders and animation frames).
  std::vector<std::string> extra;
};

// povray +I.. +O.. +W +H -D -V -GS -GR +FN16 File_Gamma=G -A (or +A0.0 -J +AM1 +Rn, or for
// corners +AM2 +At -J +Rd), then +WTn and +Kc when asked:
// no preview window (Debian's povray.ini turns it on), warnings and errors kept, statistics
// and progress dropped, 16-bit PNG holding linear values (G = 1.0, the default).
std::vector<std::string> povrayArguments(const PovrayRender& render);

// "+Ipath", or "+I\"a path\"" when it holds a space (POV-Ray splits an option at its spaces
// otherwise); for +I, +O and +L.
std::string povrayPathOption(const std::string& flag, const std::string& path);

// "+A0.3": POV-Ray's antialiasing flag with that threshold.
std::string cornerThresholdFlag(double threshold);

struct ProcessResult {
  bool started = false;
  int exitStatus = -1;  // -1 when it did not exit normally
  double seconds = 0.0;
};

// Runs program with arguments in `workingDirectory`, its stdout and stderr appended to
// `logPath`. Waits for it to finish.
ProcessResult runProcess(const std::string& program, const std::vector<std::string>& arguments,
                         const std::string& workingDirectory, const std::string& logPath);

// The command as a user would type it (arguments with spaces quoted), for reports.
std::string commandLine(const std::string& program, const std::vector<std::string>& arguments);

}  // namespace lucent
