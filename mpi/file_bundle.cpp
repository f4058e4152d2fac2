#include "file_bundle.h"

#include "messages.h"

#include "exit_status.h"

#include <fmt/core.h>

#include <fstream>

namespace fs = std::filesystem;

namespace lucent::mpi {

FileBundle makeBundle(int frame, const fs::path& scene, const std::vector<FileGrant>& grants,
                      const std::vector<fs::path>& files, std::set<fs::path>& sent) {
  FileBundle b;
  b.frame = frame;
  b.scene = scene;
  b.grants = grants;
  for (const fs::path& f : files) {
    if (sent.count(f)) continue;
    // Read whole into a string of the file's size: a stream copy is many times slower,
    // and the workers wait for it.
    std::ifstream in(f, std::ios::binary | std::ios::ate);
    std::string bytes;
    if (in) {
      bytes.resize(static_cast<size_t>(in.tellg()));
      in.seekg(0);
      in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    }
    if (!in)
      throw cli::IoFailure(
          fmt::format("cannot read '{}' to send it to the other ranks", f.string()));
    b.files.emplace_back(f, std::move(bytes));
    sent.insert(f);
  }
  return b;
}

std::vector<char> pack(const FileBundle& b) {
  Writer w;
  size_t size = 64 + b.scene.native().size();
  for (const FileGrant& g : b.grants)
    size += 32 + g.written.size() + g.base.native().size() + g.canonical.native().size();
  for (const auto& [path, bytes] : b.files) size += 16 + path.native().size() + bytes.size();
  w.bytes.reserve(size);
  w.put<int32_t>(b.frame);
  w.putString(b.scene.string());
  w.put<uint64_t>(b.grants.size());
  for (const FileGrant& g : b.grants) {
    w.putString(g.written);
    w.putString(g.base.string());
    w.putString(g.canonical.string());
  }
  w.put<uint64_t>(b.files.size());
  for (const auto& [path, bytes] : b.files) {
    w.putString(path.string());
    w.putString(bytes);
  }
  return std::move(w.bytes);
}

FileBundle unpack(const std::vector<char>& bytes) {
  Reader r(bytes);
  FileBundle b;
  b.frame = r.get<int32_t>();
  b.scene = r.getString();
  for (uint64_t n = r.get<uint64_t>(); n > 0; --n) {
    FileGrant g;
    g.written = r.getString();
    g.base = r.getString();
    g.canonical = r.getString();
    b.grants.push_back(std::move(g));
  }
  for (uint64_t n = r.get<uint64_t>(); n > 0; --n) {
    fs::path path = r.getString();
    b.files.emplace_back(std::move(path), r.getString());
  }
  return b;
}

void materialise(const FileBundle& b, const fs::path& root) {
  for (const auto& [path, bytes] : b.files) {
    const fs::path copy = root / path.relative_path();
    std::error_code ec;
    fs::create_directories(copy.parent_path(), ec);
    std::ofstream out(copy, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out)
      throw cli::IoFailure(
          fmt::format("cannot write the copy '{}' of a scene file", copy.string()));
  }
}

}  // namespace lucent::mpi
