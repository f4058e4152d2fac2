// The distributed-render model of bench/tile_schedule: cases whose makespan is known in
// closed form, and the tile-cost trace reader's answers to good and bad files.
#include <catch2/catch.hpp>
#include <limits>
#include <random>
#include <sstream>

#include "bench/tile_cost_trace.h"
#include "bench/tile_schedule_model.h"

using namespace lucent::bench;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// A network where messages, copies, broadcast and load cost nothing.
NetworkModel freeNetwork() {
  NetworkModel net;
  net.latency = 0;
  net.bandwidth = kInf;
  net.rank0Fixed = 0;
  net.rank0MemBandwidth = kInf;
  net.sceneBytes = 0;
  net.loadSeconds = 0;
  return net;
}

ScheduleResult simulate(const std::vector<double>& cost, const ScheduleModel& model,
                        const NetworkModel& net) {
  return simulateSchedule(cost, std::vector<long>(cost.size(), 256), model, net);
}

CostGrid parse(const std::string& text) {
  std::istringstream in(text);
  return parseTileCosts(in, "costs.txt");
}

const char* kHeader = "# lucent tile costs 1\n# image 40 20 tile 16 threads 2\n";

}  // namespace

TEST_CASE("equal tiles on a free network take ceil of tiles over ranks rounds") {
  for (bool prefetch : {true, false})
    for (int ranks : {2, 3, 4, 8, 16})
      for (int tiles : {1, 5, 7, 16, 33, 100}) {
        ScheduleModel model;
        model.ranks = ranks;
        model.prefetch = prefetch;
        const ScheduleResult r =
            simulate(std::vector<double>(size_t(tiles), 1.0), model, freeNetwork());
        const int rounds = (tiles + ranks - 1) / ranks;
        INFO("ranks " << ranks << ", tiles " << tiles << ", prefetch " << prefetch);
        CHECK(r.makespan == double(rounds));
        CHECK(r.efficiency == Approx(double(tiles) / (ranks * rounds)).epsilon(1e-12));
        CHECK(r.maxTilesPerRank == rounds);
      }
}

TEST_CASE("one huge tile bounds the makespan below by its cost") {
  std::vector<double> cost(60, 1.0);
  cost[17] = 100.0;
  for (int ranks : {2, 8, 64, 1024}) {
    ScheduleModel model;
    model.ranks = ranks;
    const ScheduleResult r = simulate(cost, model, NetworkModel{});
    INFO("ranks " << ranks);
    CHECK(r.makespan >= 100.0);
    CHECK(r.efficiency <= 1.0);
  }
  // On a free network and enough ranks, the huge tile is the whole makespan.
  ScheduleModel wide;
  wide.ranks = 64;
  CHECK(simulate(cost, wide, freeNetwork()).makespan == 100.0);
}

TEST_CASE("without prefetch each tile adds two latencies to its rank's time") {
  NetworkModel net = freeNetwork();
  net.latency = 0.125;
  ScheduleModel model;
  model.ranks = 2;
  model.rank0Renders = false;  // one worker renders every tile
  model.prefetch = false;
  const int n = 10;
  const std::vector<double> cost(n, 1.0);
  // The broadcast to 2 ranks is one message; then each tile is a request and its reply
  // (2L) and the render; the last result reaches rank 0 after L.
  const ScheduleResult waits = simulate(cost, model, net);
  CHECK(waits.start == 0.125);
  CHECK(waits.makespan == 0.125 + n * (2 * 0.125 + 1.0) + 0.125);
  // With prefetch the next request flies while a tile renders: only the first wait is left.
  model.prefetch = true;
  CHECK(simulate(cost, model, net).makespan == 0.125 + 2 * 0.125 + n * 1.0 + 0.125);
}

TEST_CASE("rank 0 handles requests and results one at a time") {
  NetworkModel net = freeNetwork();
  net.rank0Fixed = 1e-3;
  ScheduleModel model;
  model.ranks = 32;
  model.rank0Renders = false;
  const int n = 500;
  const ScheduleResult r = simulate(std::vector<double>(n, 1e-4), model, net);
  // Every tile is one request and one result at rank 0, whatever the rank count.
  CHECK(r.makespan >= 2 * n * 1e-3);
  CHECK(r.rank0Busy > 0.95);
  CHECK(r.efficiency < 0.1);
}

TEST_CASE("pixels cost their bytes over the link and rank 0's copy") {
  NetworkModel net = freeNetwork();
  net.bandwidth = 1000.0;
  net.rank0MemBandwidth = 4000.0;
  ScheduleModel model;
  model.ranks = 2;
  model.rank0Renders = false;
  // One tile of 100 pixels: request 16 bytes each way, 1200 bytes back, copied at rank 0.
  const ScheduleResult r = simulateSchedule({1.0}, {100}, model, net);
  CHECK(r.makespan == Approx(2 * 16 / 1000.0 + 1.0 + 1200 / 1000.0 + 1200 / 4000.0));
}

TEST_CASE("broadcast and load delay every rank's first tile") {
  NetworkModel net = freeNetwork();
  net.latency = 0.5;
  net.sceneBytes = 0;
  net.loadSeconds = 3.0;
  ScheduleModel model;
  model.ranks = 8;  // three rounds of a binomial tree
  const ScheduleResult r = simulate({2.0}, model, net);
  CHECK(r.start == 3 * 0.5 + 3.0);
  CHECK(r.makespan == 3 * 0.5 + 3.0 + 2.0);  // rank 0 renders the only tile, no message
}

TEST_CASE("more threads per rank render a tile faster in proportion") {
  ScheduleModel model;
  model.ranks = 1;
  model.recordThreads = 2;
  model.threadsPerRank = 8;
  CHECK(simulate({8.0, 4.0}, model, freeNetwork()).makespan == 3.0);
}

TEST_CASE("efficiency never exceeds one on random costs and networks") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<double> cost(size_t(1 + rng() % 300));
    for (double& c : cost) c = u(rng) < 0.1 ? 10 * u(rng) : u(rng);
    NetworkModel net;
    net.latency = 1e-3 * u(rng);
    net.rank0Fixed = 1e-3 * u(rng);
    net.loadSeconds = u(rng);
    ScheduleModel model;
    model.ranks = 1 + int(rng() % 200);
    model.prefetch = rng() % 2;
    model.rank0Renders = model.ranks == 1 || rng() % 2;
    const ScheduleResult r = simulate(cost, model, net);
    INFO("trial " << trial);
    REQUIRE(r.efficiency <= 1.0 + 1e-12);
    REQUIRE(r.makespan >= *std::max_element(cost.begin(), cost.end()));
  }
}

TEST_CASE("a larger tile costs the sum of the recorded tiles it covers") {
  CostGrid g;
  g.width = 70;  // 5 x 3 tiles of 16, the last column 6 wide and the last row 8 high
  g.height = 40;
  g.tile = 16;
  for (int i = 0; i < 15; ++i) g.cost.push_back(double(1 << i));
  const CostGrid c = coarsen(g, 2);
  REQUIRE(c.cols() == 3);
  REQUIRE(c.rows() == 2);
  CHECK(c.cost[0] == 1 + 2 + 32 + 64);
  CHECK(c.cost[2] == 16 + 512);
  CHECK(c.cost[3] == 1024 + 2048);
  CHECK(c.cost[5] == 16384);
  CHECK(c.total() == g.total());
  CHECK(c.pixels(0) == 32 * 32);
  CHECK(c.pixels(5) == 6 * 8);
}

TEST_CASE("a synthetic hot region costs its factor on the pixels it holds") {
  // 32 x 16 pixels, tiles of 16: the right half costs 3 times as much.
  const CostGrid g = syntheticGrid(32, 16, 16, 0.5, {{0.5, 0.0, 1.0, 1.0, 3.0}});
  REQUIRE(g.count() == 2);
  CHECK(g.cost[0] == 256 * 0.5);
  CHECK(g.cost[1] == 256 * 0.5 * 3.0);
}

TEST_CASE("a tile-cost trace is read with comments and header keys in any order") {
  const CostGrid g = parse(
      "# lucent tile costs 1\n"
      "# recorded on a quiet machine\n"
      "# threads 4 samples 16 scene my scenes/a.xml tile 16 colour blue image 40 20 load 1.5\n"
      "x0 y0 x1 y1 seconds\n"
      "0 0 16 16 0.5\n"
      "16 0 32 16 0.25\n"
      "\n"
      "32 0 40 16 1e-3\n"
      "# a comment between tiles\n"
      "0 16 16 20 2\n"
      "16 16 32 20 0\n"
      "32 16 40 20 0.125\r\n");
  CHECK(g.width == 40);
  CHECK(g.height == 20);
  CHECK(g.tile == 16);
  CHECK(g.threads == 4);
  CHECK(g.hasLoad);
  CHECK(g.loadSeconds == 1.5);
  CHECK(g.cost == std::vector<double>{0.5, 0.25, 1e-3, 2, 0, 0.125});
}

TEST_CASE("a malformed tile line is an error with its line number") {
  const std::string tiles =
      "0 0 16 16 1\n16 0 32 16 1\n32 0 40 16 1\n0 16 16 20 1\n16 16 32 20 1\n";
  CHECK_NOTHROW(parse(std::string(kHeader) + tiles + "32 16 40 20 1\n"));
  CHECK_THROWS_WITH(parse(std::string(kHeader) + tiles + "32 16 40 20 fast\n"),
                    Catch::StartsWith("costs.txt:8: expected 'x0 y0 x1 y1 seconds'"));
  CHECK_THROWS_WITH(parse(std::string(kHeader) + "0 0 16 16\n"),
                    Catch::StartsWith("costs.txt:3: expected"));
  CHECK_THROWS_WITH(parse(std::string(kHeader) + "0 0 16 16 -1\n"),
                    Catch::StartsWith("costs.txt:3: negative"));
  CHECK_THROWS_WITH(parse(std::string(kHeader) + "8 0 24 16 1\n"),
                    Catch::StartsWith("costs.txt:3: bounds 8 0 24 16 are not a tile"));
  CHECK_THROWS_WITH(parse(std::string(kHeader) + "0 0 16 16 1\n0 0 16 16 2\n"),
                    Catch::StartsWith("costs.txt:4: tile 0 0 already given on line 3"));
  CHECK_THROWS_WITH(parse(std::string(kHeader) + tiles),
                    Catch::Equals("costs.txt: 1 of 6 tiles have no line, the first at 32 16"));
  CHECK_THROWS_WITH(parse("0 0 16 16 1\n"), Catch::StartsWith("costs.txt:1: a tile line before"));
  CHECK_THROWS_WITH(parse("# lucent tile costs 1\n"), Catch::StartsWith("costs.txt: no '# image"));
  CHECK_THROWS_WITH(parse("# image 40 20 threads 1\n"),
                    Catch::Equals("costs.txt:1: the header has no 'tile' key"));
  CHECK_THROWS_WITH(parse("# image 40 x20 tile 16 threads 1\n"),
                    Catch::StartsWith("costs.txt:1: header key 'image' needs a positive integer"));
  CHECK_THROWS_WITH(parse("# tile 16 threads 1 image 40 20 load\n"),
                    Catch::Equals("costs.txt:1: header key 'load' has no value"));
  CHECK_THROWS_WITH(parse(std::string(kHeader) + "# tile 8\n"),
                    Catch::StartsWith("costs.txt:3: a second header line (the first is line 2)"));
}
