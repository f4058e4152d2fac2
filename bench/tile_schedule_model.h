// A discrete-event model of Lucent's distributed render: rank 0 hands out tiles in row
// order on request, every rank renders them, workers send the pixels back (float RGB,
// 12 bytes per pixel) and rank 0 stores them. It predicts the makespan, and so the
// parallel efficiency, of one configuration; bench/tile_schedule.cpp sweeps ranks and tile
// sizes. The model and where it is optimistic are described in docs/distributed.md.
//
// Timeline of a worker (rank r >= 1):
//   - it is ready after the scene broadcast (a binomial tree: ceil(log2 ranks) rounds of
//     latency + sceneBytes / bandwidth) and its scene load;
//   - it asks for a tile (a small message: latency + bytes / bandwidth), rank 0's
//     coordinator serves the request (fixed cost) and replies (latency + bytes / bandwidth);
//   - with prefetch, it asks for the next tile as soon as it starts one, so one request is
//     in flight while it renders; without, it asks when it finishes one;
//   - a finished tile goes back as one message (latency + 12·pixels / bandwidth); each
//     rank's outgoing messages leave one after another (its own link), the request first;
//   - rank 0's coordinator is one serial resource: every request costs the fixed cost,
//     every result the fixed cost + 12·pixels / memory bandwidth, first come first served.
// Rank 0 renders tiles too (unless rank0Renders is off), taking the next one from the
// queue itself with no message and storing its pixels for free; the coordinator uses none
// of its threads. A tile renders in cost · recordThreads / threadsPerRank.
// The makespan ends when rank 0 holds every tile's pixels; writing the image is not in it.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>
#include <queue>
#include <stdexcept>
#include <vector>

namespace lucent::bench {

// Bytes of one tile pixel sent back: float RGB.
constexpr double kPixelBytes = 12.0;
// Bytes of a tile request and of its reply (a few integers).
constexpr double kRequestBytes = 16.0;

struct NetworkModel {
  double latency = 50e-6;          // seconds per message, Ethernet-class (10 GbE, TCP)
  double bandwidth = 1.25e9;       // bytes per second of a link, 10 Gb/s
  double rank0Fixed = 2e-6;        // rank 0's cost per message it handles
  double rank0MemBandwidth = 5e9;  // bytes per second rank 0 copies pixels into the image
  double sceneBytes = 1e6;         // bytes of the scene broadcast to every rank
  double loadSeconds = 0.0;        // seconds each rank spends loading the scene
};

struct ScheduleModel {
  int ranks = 2;
  double recordThreads = 1;   // threads the tile costs were recorded on
  double threadsPerRank = 1;  // threads of each simulated rank
  bool prefetch = true;       // keep one request in flight ahead of the tile being rendered
  bool rank0Renders = true;   // rank 0 renders tiles beside coordinating
};

struct ScheduleResult {
  double makespan = 0;    // seconds until rank 0 holds every tile
  double ideal = 0;       // total render seconds / ranks
  double efficiency = 0;  // ideal / makespan
  double start = 0;       // seconds of broadcast and load before the first tile
  double rank0Busy = 0;   // fraction of the makespan rank 0's coordinator was busy
  int maxTilesPerRank = 0;
};

// Simulates rendering tiles (row order; `cost[i]` seconds on recordThreads threads,
// `pixels[i]` pixels) on the model's ranks.
inline ScheduleResult simulateSchedule(const std::vector<double>& cost,
                                       const std::vector<long>& pixels, const ScheduleModel& s,
                                       const NetworkModel& net) {
  if (cost.size() != pixels.size()) throw std::invalid_argument("cost and pixel counts differ");
  if (s.ranks < 1) throw std::invalid_argument("at least one rank");
  if (s.ranks == 1 && !s.rank0Renders) throw std::invalid_argument("one rank that does not render");
  if (!(s.recordThreads > 0) || !(s.threadsPerRank > 0))
    throw std::invalid_argument("thread counts must be positive");
  if (!(net.latency >= 0) || !(net.bandwidth > 0) || !(net.rank0Fixed >= 0) ||
      !(net.rank0MemBandwidth > 0) || !(net.sceneBytes >= 0) || !(net.loadSeconds >= 0))
    throw std::invalid_argument("network parameters must be at least 0 (bandwidths above 0)");

  const int n = int(cost.size());
  const double speed = s.recordThreads / s.threadsPerRank;
  auto renderTime = [&](int t) { return cost[size_t(t)] * speed; };
  auto wire = [&](double bytes) { return net.latency + bytes / net.bandwidth; };

  enum Kind : uint8_t {
    Ready,
    RequestArrives,
    RequestServed,
    TileArrives,
    RenderDone,
    ResultArrives
  };
  struct Event {
    double t;
    uint64_t seq;  // ties keep the order they were made in
    Kind kind;
    int rank, tile;
    bool operator>(const Event& o) const { return t != o.t ? t > o.t : seq > o.seq; }
  };
  std::priority_queue<Event, std::vector<Event>, std::greater<Event>> events;
  uint64_t seq = 0;
  auto at = [&](double t, Kind k, int rank, int tile = -1) {
    events.push({t, seq++, k, rank, tile});
  };

  struct Rank {
    std::deque<int> queued;
    bool rendering = false, noMore = false;
    int outstanding = 0, tiles = 0;
    double linkFree = 0;
  };
  std::vector<Rank> rank(size_t(s.ranks));
  int next = 0;          // the next tile rank 0 hands out
  double coordFree = 0;  // when rank 0's coordinator is next free
  double coordBusy = 0;
  double done = 0;  // when the last tile reached rank 0
  int stored = 0;

  auto send = [&](int r, double now, double bytes, Kind k, int tile) {
    Rank& w = rank[size_t(r)];
    const double leave = std::max(now, w.linkFree) + bytes / net.bandwidth;
    w.linkFree = leave;
    at(leave + net.latency, k, r, tile);
  };
  auto coordinate = [&](double now, double seconds) {
    const double end = std::max(now, coordFree) + seconds;
    coordFree = end;
    coordBusy += seconds;
    return end;
  };
  auto request = [&](int r, double now) {
    rank[size_t(r)].outstanding++;
    send(r, now, kRequestBytes, RequestArrives, -1);
  };
  auto startNext = [&](int r, double now) {
    Rank& w = rank[size_t(r)];
    if (w.queued.empty()) return;
    const int t = w.queued.front();
    w.queued.pop_front();
    w.rendering = true;
    w.tiles++;
    at(now + renderTime(t), RenderDone, r, t);
    // Rank 0 takes its tiles from the queue; a worker asks ahead for the next one.
    if (r != 0 && s.prefetch && !w.noMore && w.outstanding == 0 && w.queued.empty())
      request(r, now);
  };

  const int rounds = s.ranks > 1 ? int(std::ceil(std::log2(double(s.ranks)) - 1e-12)) : 0;
  const double start = rounds * wire(net.sceneBytes) + net.loadSeconds;
  if (s.rank0Renders) at(start, Ready, 0);
  for (int r = 1; r < s.ranks; ++r) at(start, Ready, r);

  while (!events.empty()) {
    const Event e = events.top();
    events.pop();
    Rank& w = rank[size_t(e.rank)];
    switch (e.kind) {
      case Ready:
      case RenderDone:
        if (e.kind == RenderDone) w.rendering = false;
        if (e.rank == 0) {
          if (e.kind == RenderDone) done = std::max(done, e.t), ++stored;
          if (next < n) w.queued.push_back(next++);
          startNext(0, e.t);
          break;
        }
        // The request for the next tile leaves before this tile's pixels.
        startNext(e.rank, e.t);
        if (!w.rendering && !w.noMore && w.outstanding == 0) request(e.rank, e.t);
        if (e.kind == RenderDone)
          send(e.rank, e.t, kPixelBytes * double(pixels[size_t(e.tile)]), ResultArrives, e.tile);
        break;
      case RequestArrives:
        at(coordinate(e.t, net.rank0Fixed), RequestServed, e.rank);
        break;
      case RequestServed: {
        const int t = next < n ? next++ : -1;
        at(e.t + wire(kRequestBytes), TileArrives, e.rank, t);
        break;
      }
      case TileArrives:
        w.outstanding--;
        if (e.tile < 0) w.noMore = true;
        else w.queued.push_back(e.tile);
        if (!w.rendering) startNext(e.rank, e.t);
        break;
      case ResultArrives:
        done = std::max(
            done, coordinate(e.t, net.rank0Fixed + kPixelBytes * double(pixels[size_t(e.tile)]) /
                                                       net.rank0MemBandwidth));
        ++stored;
        break;
    }
  }
  if (stored != n) throw std::logic_error("tile schedule lost tiles");

  ScheduleResult out;
  double total = 0;
  for (int t = 0; t < n; ++t) total += renderTime(t);
  out.makespan = std::max(done, start);
  out.ideal = total / s.ranks;
  out.efficiency = out.makespan > 0 ? out.ideal / out.makespan : 1.0;
  out.start = start;
  out.rank0Busy = out.makespan > 0 ? coordBusy / out.makespan : 0.0;
  for (const Rank& r : rank) out.maxTilesPerRank = std::max(out.maxTilesPerRank, r.tiles);
  return out;
}

}  // namespace lucent::bench
