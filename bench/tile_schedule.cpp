// Predicted parallel efficiency of a distributed (MPI) render, from a tile-cost trace or a
// synthetic cost map: a discrete-event simulation of rank 0 handing tiles out on request
// (bench/tile_schedule_model.h) for 2 ... 1024 ranks and tile sizes that are multiples of
// the recorded one. Prints a table (ranks × tile size → efficiency = ideal / makespan,
// ideal = total render seconds / ranks), the best tile size per rank count and where the
// model is optimistic; --tsv writes the rows for bench/tile_schedule.sh's plot.
//
//   tile_schedule TRACE [options]          (TRACE from lucent render --tile-costs FILE -t 1)
//   tile_schedule --synthetic W H [--pixel-cost S] [--hot x0,y0,x1,y1,factor]... [options]
// The model and its defaults: docs/distributed.md, "Simulated efficiency".
#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <fstream>

#include "bench_util.h"
#include "tile_cost_trace.h"
#include "tile_schedule_model.h"

using namespace lucent::bench;

namespace {

HotRegion parseHot(const std::string& s) {
  std::vector<double> v;
  bool numbers = true;
  std::istringstream in(s);
  for (std::string part; std::getline(in, part, ',');) {
    double d = 0;
    numbers = numbers && detail::toNumber(part, d);
    v.push_back(d);
  }
  if (!numbers || v.size() != 5)
    throw std::invalid_argument("--hot needs x0,y0,x1,y1,factor (five numbers), got '" + s + "'");
  return {v[0], v[1], v[2], v[3], v[4]};
}

std::string what(const CostGrid& g, const std::string& source) {
  return fmt::format("{}: {}x{}, {} tiles of {} px, {:.4g} s in all on {} thread{}", source,
                     g.width, g.height, g.count(), g.tile, g.total(), g.threads,
                     g.threads == 1 ? "" : "s");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Predicted efficiency of a distributed render from tile costs"};
  std::string tracePath, tsvPath;
  std::vector<int> synthetic, ranksList, tileList;
  int recordTile = 16;
  double pixelCost = 1.1e-4;
  std::vector<std::string> hotSpecs;
  bool noHot = false, noPrefetch = false, rank0Idle = false;
  double threadsPerRank = 0;
  NetworkModel net;
  double latencyUs = net.latency * 1e6, bandwidthGBs = net.bandwidth / 1e9;
  double rank0FixedUs = net.rank0Fixed * 1e6, rank0MemGBs = net.rank0MemBandwidth / 1e9;
  double sceneMB = net.sceneBytes / 1e6, load = -1;
  double costScale = 1.0;

  app.add_option("trace", tracePath, "Tile-cost trace (lucent render --tile-costs FILE)");
  auto* synth =
      app.add_option("--synthetic", synthetic, "Synthetic image of W H pixels instead of a trace")
          ->expected(2);
  app.add_option("--record-tile", recordTile, "Synthetic: recorded tile size in pixels")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--pixel-cost", pixelCost,
                 "Synthetic: one-thread seconds per pixel (about the showcase at 16 samples)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  app.add_option("--hot", hotSpecs,
                 "Synthetic: x0,y0,x1,y1,factor: a region (fractions of the image) costing factor "
                 "times more; repeatable (default 0.25,0.6,0.75,1,8)");
  app.add_flag("--no-hot", noHot, "Synthetic: a uniform cost");
  app.add_option("--ranks", ranksList, "Rank counts, comma-separated (default 2,4,...,1024)")
      ->delimiter(',')
      ->check(CLI::PositiveNumber);
  app.add_option(
         "--tiles", tileList,
         "Tile sizes in pixels, multiples of the recorded one (default recorded x 1,2,4,8,16)")
      ->delimiter(',')
      ->check(CLI::PositiveNumber);
  app.add_option("--threads-per-rank", threadsPerRank,
                 "Threads of each rank (default: the recording's); tiles scale ideally")
      ->check(CLI::PositiveNumber);
  app.add_option("--latency-us", latencyUs, "Per-message latency, microseconds (Ethernet-class)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  app.add_option("--bandwidth-gbs", bandwidthGBs, "Link bandwidth, GB/s (10 Gb/s)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--rank0-fixed-us", rank0FixedUs,
                 "Rank 0's cost per message it handles, microseconds")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  app.add_option("--rank0-mem-gbs", rank0MemGBs,
                 "Rank 0's copy of tile pixels into the image, GB/s")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--scene-mb", sceneMB, "Scene bytes broadcast to the ranks, MB")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  app.add_option("--load", load,
                 "Seconds a rank takes to load the scene (default: the trace's 'load' key, else 0)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--cost-scale", costScale,
                 "Multiply every recorded tile cost (a trace at 4 samples a pixel, --cost-scale 4: "
                 "16 samples; rendering time grows linearly with the samples)")
      ->check(CLI::PositiveNumber);
  app.add_flag("--no-prefetch", noPrefetch,
               "A rank asks for its next tile only when it finishes one");
  app.add_flag("--rank0-idle", rank0Idle, "Rank 0 only coordinates and renders no tile");
  app.add_option("--tsv", tsvPath, "Write ranks, tile, efficiency, ... as tab-separated rows");
  CLI11_PARSE(app, argc, argv);

  CostGrid grid;
  std::string source;
  try {
    if (tracePath.empty() == synth->empty())
      throw std::invalid_argument("give either a trace file or --synthetic W H");
    if (!tracePath.empty()) {
      std::ifstream in(tracePath);
      if (!in) throw std::runtime_error(tracePath + ": cannot open");
      grid = parseTileCosts(in, tracePath);
      source = "trace " + tracePath;
      if (costScale != 1.0) {
        for (double& c : grid.cost) c *= costScale;
        source += fmt::format(", costs x {}", costScale);
      }
    } else {
      std::vector<HotRegion> hot;
      if (!noHot) {
        if (hotSpecs.empty()) hotSpecs.push_back("0.25,0.6,0.75,1,8");
        for (const std::string& h : hotSpecs) hot.push_back(parseHot(h));
      }
      if (synthetic[0] < 1 || synthetic[1] < 1 || long(synthetic[0]) * synthetic[1] > 400000000L)
        throw std::invalid_argument(
            "--synthetic needs W and H of at least 1 (at most 400 Mpixels)");
      grid = syntheticGrid(synthetic[0], synthetic[1], recordTile, pixelCost, hot);
      std::string hots;
      for (const HotRegion& h : hot)
        hots += fmt::format(", {}x in x {}-{} y {}-{}", h.factor, h.x0, h.x1, h.y0, h.y1);
      source = fmt::format("synthetic ({:.3g} s a pixel{})", pixelCost, hots);
    }
    if (ranksList.empty())
      for (int r = 2; r <= 1024; r *= 2) ranksList.push_back(r);
    if (tileList.empty())
      for (int f = 1; f <= 16; f *= 2) tileList.push_back(grid.tile * f);
    for (int t : tileList)
      if (t % grid.tile)
        throw std::invalid_argument(
            fmt::format("tile size {} is not a multiple of the recorded {}", t, grid.tile));
    for (int r : ranksList)
      if (r == 1 && rank0Idle)
        throw std::invalid_argument("one rank with --rank0-idle renders nothing");
  } catch (const std::exception& e) {
    fmt::print(stderr, "tile_schedule: error: {}\n", e.what());
    return 2;
  }

  net.latency = latencyUs * 1e-6;
  net.bandwidth = bandwidthGBs * 1e9;
  net.rank0Fixed = rank0FixedUs * 1e-6;
  net.rank0MemBandwidth = rank0MemGBs * 1e9;
  net.sceneBytes = sceneMB * 1e6;
  net.loadSeconds = load >= 0 ? load : grid.loadSeconds;
  ScheduleModel model;
  model.recordThreads = grid.threads;
  model.threadsPerRank = threadsPerRank > 0 ? threadsPerRank : grid.threads;
  model.prefetch = !noPrefetch;
  model.rank0Renders = !rank0Idle;

  fmt::print("# tile_schedule: {}\n", what(grid, source));
  fmt::print(
      "# network: {:g} us latency per message (Ethernet-class), {:g} GB/s per link ({:g} Gb/s); "
      "rank 0 handles a message in {:g} us + 12 bytes per pixel at {:g} GB/s\n",
      latencyUs, bandwidthGBs, bandwidthGBs * 8, rank0FixedUs, rank0MemGBs);
  fmt::print(
      "# start: {:g} MB scene broadcast (binomial tree), {:g} s load per rank; {:g} thread{} "
      "per rank; prefetch {}; rank 0 {}\n",
      sceneMB, net.loadSeconds, model.threadsPerRank, model.threadsPerRank == 1 ? "" : "s",
      model.prefetch ? "on" : "off", model.rank0Renders ? "renders tiles too" : "only coordinates");
  fmt::print("# efficiency = (total render seconds / ranks) / predicted makespan\n\n");

  TsvFile tsv(tsvPath);
  if (!tsvPath.empty() && !std::ifstream(tsvPath)) {
    fmt::print(stderr, "tile_schedule: error: cannot write {}\n", tsvPath);
    return 2;
  }
  tsv.row("# ranks\ttile\ttiles\tefficiency\tmakespan_s\tideal_s\tstart_s\trank0_busy");
  std::vector<CostGrid> grids;
  for (int t : tileList) grids.push_back(coarsen(grid, t / grid.tile));

  // TSV rows grouped by tile size, so that a plot draws each size as one line.
  std::vector<std::string> rows(grids.size());
  std::string head = "| ranks |", rule = "| --- |";
  for (int t : tileList) head += fmt::format(" {} px |", t), rule += " --- |";
  fmt::print("{} best tile | its makespan | rank 0 busy |\n{} --- | --- | --- |\n", head, rule);
  for (int r : ranksList) {
    model.ranks = r;
    std::string line = fmt::format("| {} |", r);
    int bestTile = 0;
    ScheduleResult best;
    for (size_t k = 0; k < grids.size(); ++k) {
      const CostGrid& g = grids[k];
      std::vector<long> pixels(size_t(g.count()));
      for (int i = 0; i < g.count(); ++i) pixels[size_t(i)] = g.pixels(i);
      const ScheduleResult res = simulateSchedule(g.cost, pixels, model, net);
      line += fmt::format(" {:.3f} |", res.efficiency);
      rows[k] +=
          fmt::format("{}\t{}\t{}\t{:.6f}\t{:.6g}\t{:.6g}\t{:.6g}\t{:.4f}\n", r, g.tile, g.count(),
                      res.efficiency, res.makespan, res.ideal, res.start, res.rank0Busy);
      if (!bestTile || res.efficiency > best.efficiency) bestTile = g.tile, best = res;
    }
    fmt::print("{} {} px ({:.3f}) | {:.4g} s | {:.0f}% |\n", line, bestTile, best.efficiency,
               best.makespan, 100 * best.rank0Busy);
  }
  for (const std::string& block : rows) tsv.row("{}", block.substr(0, block.size() - 1));

  fmt::print(
      "\nWhere this model is optimistic (each point makes the prediction better than a real run on "
      "the same parameters):\n"
      "- rank 0's network link has no contention: results arriving together share no bandwidth;\n"
      "  only rank 0's serial handling of each message (fixed cost + copy) queues them.\n"
      "- a rank's threads scale ideally inside a tile (cost x recorded threads / threads per "
      "rank).\n"
      "- no stragglers or noisy neighbours: every rank runs at the recorded speed, with no "
      "jitter.\n"
      "- no tile-edge overhead: the margin that adaptive supersampling renders around a tile,\n"
      "  and the per-tile set-up, are only in the costs as far as the recorded tiles hold them;\n"
      "  a larger tile is the sum of its recorded tiles.\n"
      "- rank 0's coordinator takes no time from its own rendering; writing the image is left "
      "out.\n"
      "- the network is the stated latency + bytes / bandwidth, with no loss, retries or other "
      "jobs.\n");
  return 0;
}
