// lucent-mpi: `lucent render` over the ranks of an MPI job (docs/distributed.md).
//
//   mpirun -np N lucent-mpi render SCENE [the options of lucent render]
//
// Every rank reads the same command line. Rank 0 does what `lucent render` does (it reads
// the scene and its files, keeps the checkpoint and writes the image) with its tiles
// handed out over the ranks (tile_dispatch.h); the others are workers (worker.h). A
// separate executable, so that `lucent` itself never pays for loading and starting MPI.
#include "command_line.h"
#include "commands.h"
#include "messages.h"
#include "tile_dispatch.h"
#include "worker.h"

#include "lang/file_access.h"

#include <fmt/core.h>
#include <mpi.h>
#include <CLI/CLI.hpp>

#include <cstdio>
#include <functional>

using namespace lucent;
using namespace lucent::cli;

namespace {

int run(int argc, char** argv, mpi::TileDispatch*& dispatch) {
  const bool first = mpi::rank() == 0;
  CLI::App app{
      "lucent-mpi: lucent render over the ranks of an MPI job (mpirun -np N lucent-mpi render "
      "SCENE)"};
  setHelp(&app);
  app.require_subcommand(1);
  app.set_version_flag("--version", "lucent-mpi 0.1");
  RenderOptions render;
  std::vector<std::string> defines, allowPaths;
  CLI::App* renderCmd =
      app.add_subcommand("render", "Render a scene to an image over the job's ranks");
  setHelp(renderCmd);
  addRenderOptions(renderCmd, render);
  addCommonOptions(renderCmd, defines, allowPaths);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // Every rank sees the same words; rank 0 says what is wrong.
    if (!first) return e.get_exit_code() == 0 ? kOk : kUsage;
    const int status = app.exit(e);
    return status == 0 ? kOk : kUsage;
  }
  try {
    if (std::vector<std::string> extras = renderCmd->remaining(); !extras.empty())
      throw UsageError(unexpectedArguments(renderCmd, extras) +
                       "\nRun 'lucent-mpi render --help' for more information.");
    CommonOptions common;
    takeCommonOptions(defines, allowPaths, common);
    if (!first) return mpi::runWorker(render, common);
    static mpi::TileDispatch tiles(canonicalPath(render.scene));
    dispatch = &tiles;
    return runRender(render, common, TileExecutor(std::ref(tiles)), &tiles);
  } catch (...) {
    if (!first) return kUsage;  // rank 0 reports the same usage error
    return reportFailure(std::current_exception());
  }
}

}  // namespace

int main(int argc, char** argv) {
  int provided = 0;
  // Only the main thread of each rank calls MPI (rank 0's render thread does not).
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  mpi::TileDispatch* dispatch = nullptr;
  const int status = run(argc, argv, dispatch);
  if (mpi::rank() == 0 && dispatch) {
    // A worker still rendering (a render interrupted, or a failure mid-frame) cannot be
    // told to stop in between: the job is ended. Otherwise every worker is told, and exits.
    if (!dispatch->workersIdle()) MPI_Abort(MPI_COMM_WORLD, status == 0 ? 3 : status);
    dispatch->stopWorkers();
  }
  MPI_Finalize();
  return status;
}
