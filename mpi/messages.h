// The messages of a distributed render (lucent-mpi): rank 0 hands out frames and tiles,
// the other ranks (workers) ask for tiles and send back their pixels. Every message is a
// byte buffer, sent as its size and then in pieces MPI's int counts can hold, so that a
// scene's files of any size go in one message.
#pragma once

#include <atomic>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <mpi.h>

namespace lucent::mpi {

// A frame: kFrame, then kFile for each file name as rank 0's parse is granted it (the
// worker parses meanwhile, waiting for a name it lacks), then kLoaded or, if rank 0 does
// not render that frame after all, kNoMore; then tiles. Each of the three carries a
// FileBundle (file_bundle.h).
enum Tag : int {
  kFrame = 1,   // 0 -> worker: a frame to load: its scene file
  kTile = 2,    // 0 -> worker: a tile of the frame to render
  kNoMore = 3,  // 0 -> worker: the frame has no more tiles for it (or is not rendered)
  kStop = 4,    // 0 -> worker: the run is over
  kReady = 5,   // worker -> 0: the frame is loaded; a tile, please
  kResult = 6,  // worker -> 0: a tile's pixels and counts (and a tile, please)
  kFailed = 7,  // worker -> 0: the frame could not be loaded (the reason)
  kFile = 8,    // 0 -> worker: a name the frame's parse was granted, and its file if new
  kLoaded = 9,  // 0 -> worker: the frame is loaded: every name, any file not sent yet
};

// Writes and reads the fields of a message in order (native byte order: the ranks of one
// job run the same build).
class Writer {
 public:
  template <class T>
  void put(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    const char* p = reinterpret_cast<const char*>(&v);
    bytes.insert(bytes.end(), p, p + sizeof(T));
  }
  void putBytes(const void* data, size_t n) {
    put<uint64_t>(n);
    const char* p = static_cast<const char*>(data);
    bytes.insert(bytes.end(), p, p + n);
  }
  void putString(const std::string& s) { putBytes(s.data(), s.size()); }
  std::vector<char> bytes;
};

class Reader {
 public:
  explicit Reader(const std::vector<char>& b) : bytes_(b) {}
  template <class T>
  T get() {
    T v;
    need(sizeof(T));
    std::memcpy(&v, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return v;
  }
  std::string getString() {
    const uint64_t n = get<uint64_t>();
    need(n);
    std::string s(bytes_.data() + at_, n);
    at_ += n;
    return s;
  }
  bool done() const { return at_ == bytes_.size(); }

 private:
  void need(uint64_t n) const {
    if (n > bytes_.size() - at_)
      throw std::runtime_error("a message from another rank is cut short");
  }
  const std::vector<char>& bytes_;
  size_t at_ = 0;
};

struct Message {
  int source = -1;
  int tag = 0;
  std::vector<char> bytes;
};

// Blocking send of a whole buffer.
void send(int dest, Tag tag, const std::vector<char>& bytes);

// Rank 0 to every worker at once, along MPI's broadcast (Open MPI's libnbc: a binomial
// tree, or a pipelined chain for large messages, so rank 0 does not send each byte once
// per worker): the scene's files as a frame loads, and the frame's and the run's ends.
// Every worker takes every broadcast, in order, with receiveBroadcast; both wait polling
// with naps, as receive() does. A worker does not stop waiting on SIGTERM: rank 0 then
// ends the run with kStop (or MPI ends the job).
void broadcast(Tag tag, const std::vector<char>& bytes);
void receiveBroadcast(Message& out);

// A send that returns at once, its buffer kept until MPI is done with it: a worker sends a
// tile's pixels and goes on to the next tile rather than wait for rank 0's polling thread
// to take them (a large message is not sent until the receiver asks for it). One at a
// time: start() first waits for the send before.
class PendingSend {
 public:
  PendingSend() = default;
  PendingSend(const PendingSend&) = delete;
  PendingSend& operator=(const PendingSend&) = delete;
  ~PendingSend() { wait(); }
  void start(int dest, Tag tag, std::vector<char> bytes);
  void wait();

 private:
  uint64_t size_ = 0;
  std::vector<char> bytes_;
  std::vector<MPI_Request> requests_;
};
// The next message from `source` (or any rank: -1), if one is there.
bool tryReceive(int source, Message& out);
// Waits for the next message from `source` (or any), polling with short sleeps: Open MPI's
// blocking receive spins a core, which a rank's render threads need. Returns false if
// `stop` became true first.
bool receive(int source, Message& out, const std::atomic<bool>* stop = nullptr);

int rank();
int ranks();

}  // namespace lucent::mpi
