#include "messages.h"

#include <mpi.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>

namespace lucent::mpi {

namespace {
// The largest piece one MPI call moves (its counts are ints).
constexpr uint64_t kPiece = uint64_t(1) << 30;
}  // namespace

int rank() {
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

int ranks() {
  int n = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &n);
  return n;
}

void send(int dest, Tag tag, const std::vector<char>& bytes) {
  uint64_t size = bytes.size();
  MPI_Send(&size, 1, MPI_UINT64_T, dest, tag, MPI_COMM_WORLD);
  for (uint64_t at = 0; at < size; at += kPiece) {
    const int n = static_cast<int>(std::min(kPiece, size - at));
    MPI_Send(bytes.data() + at, n, MPI_BYTE, dest, tag, MPI_COMM_WORLD);
  }
}

namespace {
void waitPolling(MPI_Request& request) {
  for (int polls = 0;; ++polls) {
    int done = 0;
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done) return;
    if (polls > 100) std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
}

// The header and then the pieces, each broadcast from rank 0; `head` is [tag, size].
void broadcastParts(uint64_t head[2], std::vector<char>& bytes, bool root) {
  MPI_Request request;
  MPI_Ibcast(head, 2, MPI_UINT64_T, 0, MPI_COMM_WORLD, &request);
  waitPolling(request);
  if (!root) bytes.resize(head[1]);
  for (uint64_t at = 0; at < head[1]; at += kPiece) {
    const int n = static_cast<int>(std::min(kPiece, head[1] - at));
    // The pieces follow their header at once: waited for without naps, since a large
    // broadcast moves in segments that each need a call into MPI on both sides.
    MPI_Ibcast(bytes.data() + at, n, MPI_BYTE, 0, MPI_COMM_WORLD, &request);
    MPI_Wait(&request, MPI_STATUS_IGNORE);
  }
}
}  // namespace

void broadcast(Tag tag, const std::vector<char>& bytes) {
  uint64_t head[2] = {static_cast<uint64_t>(tag), bytes.size()};
  broadcastParts(head, const_cast<std::vector<char>&>(bytes), true);  // the root only reads it
}

void receiveBroadcast(Message& out) {
  uint64_t head[2] = {0, 0};
  broadcastParts(head, out.bytes, false);
  out.source = 0;
  out.tag = static_cast<int>(head[0]);
}

void PendingSend::start(int dest, Tag tag, std::vector<char> bytes) {
  wait();
  bytes_ = std::move(bytes);
  size_ = bytes_.size();
  requests_.emplace_back();
  MPI_Isend(&size_, 1, MPI_UINT64_T, dest, tag, MPI_COMM_WORLD, &requests_.back());
  for (uint64_t at = 0; at < size_; at += kPiece) {
    const int n = static_cast<int>(std::min(kPiece, size_ - at));
    requests_.emplace_back();
    MPI_Isend(bytes_.data() + at, n, MPI_BYTE, dest, tag, MPI_COMM_WORLD, &requests_.back());
  }
}

void PendingSend::wait() {
  if (requests_.empty()) return;
  MPI_Waitall(static_cast<int>(requests_.size()), requests_.data(), MPI_STATUSES_IGNORE);
  requests_.clear();
}

bool tryReceive(int source, Message& out) {
  int ready = 0;
  MPI_Status status;
  const int from = source < 0 ? MPI_ANY_SOURCE : source;
  MPI_Iprobe(from, MPI_ANY_TAG, MPI_COMM_WORLD, &ready, &status);
  if (!ready) return false;
  out.source = status.MPI_SOURCE;
  out.tag = status.MPI_TAG;
  uint64_t size = 0;
  MPI_Recv(&size, 1, MPI_UINT64_T, out.source, out.tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  out.bytes.resize(size);
  // The pieces follow the size from the same rank with the same tag, in order (MPI's
  // messages between two ranks do not overtake each other).
  for (uint64_t at = 0; at < size; at += kPiece) {
    const int n = static_cast<int>(std::min(kPiece, size - at));
    MPI_Recv(out.bytes.data() + at, n, MPI_BYTE, out.source, out.tag, MPI_COMM_WORLD,
             MPI_STATUS_IGNORE);
  }
  return true;
}

bool receive(int source, Message& out, const std::atomic<bool>* stop) {
  // A few quick polls first (a reply to a request comes within microseconds), then naps.
  for (int polls = 0;; ++polls) {
    if (tryReceive(source, out)) return true;
    if (stop && stop->load(std::memory_order_relaxed)) return false;
    if (polls > 100) std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
}

}  // namespace lucent::mpi
