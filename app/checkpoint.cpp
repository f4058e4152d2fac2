#include "checkpoint.h"

#include "scenegraph/digest.h"

#include <fmt/core.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fcntl.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace lucent {

namespace {

constexpr const char* kMagic = "lucent checkpoint 1\n";
constexpr uint32_t kRecordMark = 0x4c435231;  // "LCR1"
enum RecordKind : uint32_t { kFrameBegin = 1, kTile = 2, kFrameWritten = 3 };
// A record holds at most one tile of kMaxTileSize a side, so a damaged length cannot make
// the reader allocate without bound.
constexpr uint64_t kMaxRecordBytes = 64 + uint64_t(kMaxTileSize) * kMaxTileSize * sizeof(Color);

std::string errnoText() { return std::strerror(errno); }

void put32(std::string& out, uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); }
void put64(std::string& out, uint64_t v) { out.append(reinterpret_cast<const char*>(&v), 8); }

std::string identityText(const Identity& id) {
  std::string out;
  for (const auto& [key, value] : id) {
    // Keys and values are single lines: a newline would split one into two.
    std::string v = value;
    for (char& c : v)
      if (c == '\n') c = ' ';
    out += key + '\t' + v + '\n';
  }
  return out;
}

Identity parseIdentity(const std::string& text) {
  Identity id;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    const size_t tab = line.find('\t');
    if (tab == std::string::npos) continue;
    id.emplace_back(line.substr(0, tab), line.substr(tab + 1));
  }
  return id;
}

// kind, payload length, payload, digest of the three.
void putRecord(std::string& out, uint32_t kind, const std::string& payload) {
  std::string record;
  put32(record, kRecordMark);
  put32(record, kind);
  put64(record, payload.size());
  record += payload;
  Digest d;
  d.add(record);
  put64(record, d.value());
  out += record;
}

// Fixed-size fields of a payload.
struct Fields {
  const std::string& bytes;
  size_t at = 0;
  bool has(size_t n) const { return bytes.size() - at >= n; }
  uint32_t get32() {
    uint32_t v;
    std::memcpy(&v, bytes.data() + at, 4);
    at += 4;
    return v;
  }
};

}  // namespace

std::vector<std::string> identityDifferences(const Identity& saved, const Identity& current) {
  std::vector<std::string> out;
  auto find = [](const Identity& id, const std::string& key) -> const std::string* {
    for (const auto& [k, v] : id)
      if (k == key) return &v;
    return nullptr;
  };
  for (const auto& [key, value] : current) {
    const std::string* old = find(saved, key);
    if (!old)
      out.push_back(fmt::format("{}: not in the checkpoint, '{}' in this render", key, value));
    else if (*old != value)
      out.push_back(
          fmt::format("{}: '{}' in the checkpoint, '{}' in this render", key, *old, value));
  }
  for (const auto& [key, value] : saved)
    if (!find(current, key))
      out.push_back(fmt::format("{}: '{}' in the checkpoint, not in this render", key, value));
  return out;
}

std::string checkpointPathFor(const std::string& output) { return output + ".checkpoint"; }

CheckpointContents readCheckpoint(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw CheckpointError(fmt::format("cannot read the checkpoint '{}': {}", path, errnoText()));
  const auto notOne = [&] {
    return CheckpointError(fmt::format("'{}' is not a Lucent checkpoint", path));
  };
  std::string line;
  if (!std::getline(in, line) || line + "\n" != kMagic) throw notOne();
  std::string header;
  for (int lines = 0;; ++lines) {
    if (!std::getline(in, line) || lines > 100000) throw notOne();
    if (line == "end") break;
    header += line + '\n';
  }
  CheckpointContents c;
  c.run = parseIdentity(header);
  c.validBytes = static_cast<long long>(in.tellg());
  // Records one by one, to the first that is cut short or damaged.
  std::string record, payload;
  for (;;) {
    record.resize(16);
    if (!in.read(record.data(), 16)) break;
    uint32_t mark, kind;
    uint64_t length;
    std::memcpy(&mark, record.data(), 4);
    std::memcpy(&kind, record.data() + 4, 4);
    std::memcpy(&length, record.data() + 8, 8);
    if (mark != kRecordMark || length > kMaxRecordBytes) break;
    payload.resize(length);
    uint64_t stored;
    if (!in.read(payload.data(), static_cast<std::streamsize>(length)) ||
        !in.read(reinterpret_cast<char*>(&stored), 8))
      break;
    Digest d;
    d.add(record).add(payload);
    if (stored != d.value()) break;
    Fields p{payload};
    if (kind == kFrameBegin && p.has(4)) {
      const int frame = static_cast<int>(p.get32());
      CheckpointContents::Frame& f = c.frames[frame];
      // A frame begun again (after a resume found it changed) starts over.
      f = {};
      f.identity = parseIdentity(payload.substr(4));
    } else if (kind == kTile && p.has(20)) {
      const int frame = static_cast<int>(p.get32());
      PixelRect rect;
      rect.x0 = static_cast<int>(p.get32());
      rect.y0 = static_cast<int>(p.get32());
      rect.x1 = static_cast<int>(p.get32());
      rect.y1 = static_cast<int>(p.get32());
      if (rect.empty() || payload.size() - 20 != static_cast<size_t>(rect.pixels()) * sizeof(Color))
        break;
      Image tile(rect.width(), rect.height());
      std::memcpy(tile.pixels.data(), payload.data() + 20, payload.size() - 20);
      c.frames[frame].tiles.emplace_back(rect, std::move(tile));
    } else if (kind == kFrameWritten && p.has(4)) {
      c.frames[static_cast<int>(p.get32())].written = true;
    } else {
      break;
    }
    c.validBytes = static_cast<long long>(in.tellg());
  }
  in.clear();
  in.seekg(0, std::ios::end);
  c.torn = c.validBytes < static_cast<long long>(in.tellg());
  return c;
}

CheckpointWriter::CheckpointWriter(std::string path, Identity run)
    : path_(std::move(path)), run_(std::move(run)) {}

CheckpointWriter CheckpointWriter::continuing(std::string path,
                                              const CheckpointContents& contents) {
  CheckpointWriter w;
  w.path_ = std::move(path);
  w.run_ = contents.run;
  w.started_ = true;
  w.keepBytes_ = contents.validBytes;
  return w;
}

CheckpointWriter::~CheckpointWriter() {
  if (file_) std::fclose(file_);
}

CheckpointWriter::CheckpointWriter(CheckpointWriter&& o) noexcept
    : path_(std::move(o.path_)),
      run_(std::move(o.run_)),
      queue_(std::move(o.queue_)),
      file_(o.file_),
      started_(o.started_),
      keepBytes_(o.keepBytes_) {
  o.file_ = nullptr;
}

void CheckpointWriter::beginFrame(int frame, const Identity& identity) {
  std::string payload;
  put32(payload, static_cast<uint32_t>(frame));
  payload += identityText(identity);
  putRecord(queue_, kFrameBegin, payload);
}

void CheckpointWriter::addTile(int frame, const PixelRect& rect, const Image& pixels) {
  std::string payload;
  put32(payload, static_cast<uint32_t>(frame));
  for (int v : {rect.x0, rect.y0, rect.x1, rect.y1}) put32(payload, static_cast<uint32_t>(v));
  payload.append(reinterpret_cast<const char*>(pixels.pixels.data()),
                 pixels.pixels.size() * sizeof(Color));
  putRecord(queue_, kTile, payload);
}

void CheckpointWriter::frameWritten(int frame) {
  std::string payload;
  put32(payload, static_cast<uint32_t>(frame));
  putRecord(queue_, kFrameWritten, payload);
}

void CheckpointWriter::open() {
  if (!started_) {
    // The header goes to a temporary file renamed over the old checkpoint: a crash leaves
    // either the old one or the new header, never half of one.
    const std::string temp = path_ + ".tmp";
    std::FILE* f = std::fopen(temp.c_str(), "wb");
    if (!f)
      throw CheckpointError(fmt::format("cannot write the checkpoint '{}': {}", temp, errnoText()));
    const std::string header = std::string(kMagic) + identityText(run_) + "end\n";
    const bool ok = std::fwrite(header.data(), 1, header.size(), f) == header.size() &&
                    std::fflush(f) == 0 && ::fsync(::fileno(f)) == 0;
    const std::string problem = errnoText();
    std::fclose(f);
    if (!ok || std::rename(temp.c_str(), path_.c_str()) != 0) {
      std::remove(temp.c_str());
      throw CheckpointError(
          fmt::format("cannot write the checkpoint '{}': {}", path_, ok ? errnoText() : problem));
    }
    started_ = true;
  }
  file_ = std::fopen(path_.c_str(), "r+b");
  if (!file_)
    throw CheckpointError(fmt::format("cannot write the checkpoint '{}': {}", path_, errnoText()));
  // Unbuffered: a write that fails is cut off below, with nothing of it left in a buffer.
  std::setvbuf(file_, nullptr, _IONBF, 0);
  // Continuing: a torn record at the end is cut off, so the new ones follow whole ones.
  if (keepBytes_ >= 0 && ::ftruncate(::fileno(file_), keepBytes_) != 0)
    throw CheckpointError(fmt::format("cannot write the checkpoint '{}': {}", path_, errnoText()));
  keepBytes_ = -1;
  std::fseek(file_, 0, SEEK_END);
}

void CheckpointWriter::save() {
  if (!file_) open();
  if (queue_.empty()) return;
  const long before = std::ftell(file_);
  const bool ok = std::fwrite(queue_.data(), 1, queue_.size(), file_) == queue_.size() &&
                  std::fflush(file_) == 0 && ::fsync(::fileno(file_)) == 0;
  if (!ok) {
    const std::string problem = errnoText();
    // Cut what was written of the failed records (a full disk), so that a later save
    // appends after whole records; the queue is kept for it.
    std::clearerr(file_);
    if (before >= 0 && ::ftruncate(::fileno(file_), before) == 0)
      std::fseek(file_, before, SEEK_SET);
    throw CheckpointError(fmt::format("cannot write the checkpoint '{}': {}", path_, problem));
  }
  queue_.clear();
}

void CheckpointWriter::remove() {
  if (file_) {
    std::fclose(file_);
    file_ = nullptr;
  }
  std::error_code ec;
  fs::remove(path_, ec);
  started_ = false;
}

}  // namespace lucent
