#include "mesh_file_check.h"

#include "mesh_error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace lucent {

namespace fs = std::filesystem;

MeshFormat meshFormatOf(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".obj") return MeshFormat::Obj;
  if (ext == ".ply") return MeshFormat::Ply;
  if (ext == ".off") return MeshFormat::Off;
  if (ext == ".stl") return MeshFormat::Stl;
  if (ext.empty())
    throw MeshError("the file name has no extension; expected .obj, .ply, .off or .stl");
  throw MeshError(fmt::format("unknown mesh format '{}'; expected .obj, .ply, .off or .stl",
                              fs::path(path).extension().string()));
}

const char* meshFormatName(MeshFormat format) {
  switch (format) {
    case MeshFormat::Obj:
      return "OBJ";
    case MeshFormat::Ply:
      return "PLY";
    case MeshFormat::Off:
      return "OFF";
    case MeshFormat::Stl:
      return "STL";
  }
  return "?";
}

std::string readMeshFile(const std::string& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (status.type() == fs::file_type::not_found) throw MeshError("the file does not exist");
  if (ec) throw MeshError(fmt::format("the file cannot be examined: {}", ec.message()));
  if (status.type() == fs::file_type::directory) throw MeshError("this is a folder, not a file");
  if (status.type() != fs::file_type::regular) throw MeshError("this is not a regular file");
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) throw MeshError(fmt::format("the file size cannot be read: {}", ec.message()));
  if (size == 0) throw MeshError("the file is empty");
  if (size > kMaxMeshFileBytes)
    throw MeshError(fmt::format("the file is too large ({} bytes; the limit is {} bytes)", size,
                                kMaxMeshFileBytes));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw MeshError(fmt::format("the file cannot be opened: {}", std::strerror(errno)));
  std::string bytes(static_cast<std::size_t>(size), '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(size));
  if (static_cast<std::uintmax_t>(in.gcount()) != size)
    throw MeshError("the file could not be read completely (it changed or an I/O error occurred)");
  return bytes;
}

// CGAL reads an STL as ASCII when it starts (after white space) with "solid" and a space or
// line break, else as binary, and when that fails it tries the other way WITHOUT clearing
// what the failed attempt stored: the soup then mixes both (seen with a tab after "solid").
// So the layout is settled here and the buffer adjusted so that CGAL's first attempt is the
// right one. A binary layout needs 84 + 50 N bytes; text can never satisfy that within the
// size limit (its count bytes are at least 0x09, so N > 1.5e8), so it decides.
void checkStlBytes(std::string& bytes) {
  std::size_t start = 0;
  while (start < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[start]))) ++start;
  const bool startsWithSolid = bytes.compare(start, 5, "solid") == 0;
  uint32_t count = 0;
  if (bytes.size() >= 84)
    std::memcpy(&count, bytes.data() + 80, 4);  // little-endian, like the host
  const unsigned long long needed = 84ull + 50ull * count;

  if (bytes.size() < 84 || needed > bytes.size()) {  // can only be ASCII
    if (!startsWithSolid) {
      if (bytes.size() < 84)
        throw MeshError(
            fmt::format("the file is too short ({} bytes) for a binary STL, which has "
                        "an 84-byte header, and does not start with 'solid' like an "
                        "ASCII STL",
                        bytes.size()));
      throw MeshError(
          fmt::format("the binary STL is truncated: its header announces {} triangles "
                      "({} bytes), but the file has {} bytes",
                      count, needed, bytes.size()));
    }
    const std::size_t after = start + 5;
    if (after < bytes.size()) {
      if (!std::isspace(static_cast<unsigned char>(bytes[after])))
        throw MeshError("an ASCII STL must start with the word 'solid' followed by a space");
      bytes[after] = ' ';  // CGAL only recognises a space or a line break here
    }
    return;
  }
  // Binary. Its 80-byte header is free text; one starting with "solid" would send CGAL to
  // the ASCII reader first.
  if (startsWithSolid && start < 80) bytes[start] = 'S';
  if (count > kMaxMeshFaces)
    throw MeshError(
        fmt::format("the binary STL has {} triangles; the limit is {}", count, kMaxMeshFaces));
  for (uint32_t t = 0; t < count; ++t) {
    const char* record = bytes.data() + 84 + 50ull * t;
    for (int k = 3; k < 12; ++k) {  // skip the facet normal, which CGAL ignores
      float v;
      std::memcpy(&v, record + 4 * k, 4);
      if (!std::isfinite(v))
        throw MeshError(
            fmt::format("binary STL triangle {} (counting from 0) has a non-finite "
                        "vertex coordinate",
                        t));
    }
  }
}

}  // namespace lucent
