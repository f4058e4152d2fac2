// A rank other than 0 of lucent-mpi: it waits for a frame (the scene's files, file_bundle.h),
// writes the files under a private temporary folder, parses the copy of the scene with the
// same command line as rank 0, renders the tiles rank 0 hands it with all its threads and
// sends their pixels back, until rank 0 says the run is over. It prints nothing of its own
// scene's warnings (rank 0 does) and removes its folder at the end, or on SIGTERM.
#pragma once

#include "commands.h"

namespace lucent::mpi {

int runWorker(const cli::RenderOptions& options, const cli::CommonOptions& common);

}  // namespace lucent::mpi
