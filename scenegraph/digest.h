// A 64-bit digest of bytes (FNV-1a): what a checkpoint keeps of the scene, the files it
// reads and the options that change pixels, to tell on --resume whether any of them changed.
// Not a cryptographic hash: it guards against mistakes, not against an adversary.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include <fmt/core.h>

namespace lucent {

class Digest {
 public:
  Digest& add(std::string_view bytes) {
    for (unsigned char c : bytes) {
      h_ ^= c;
      h_ *= 0x100000001b3ull;
    }
    return *this;
  }
  // A field, followed by a separator no field contains, so ("ab", "c") and ("a", "bc") differ.
  Digest& field(std::string_view bytes) {
    add(bytes);
    return add(std::string_view("\0\xff", 2));
  }
  uint64_t value() const { return h_; }
  std::string hex() const { return fmt::format("{:016x}", h_); }

 private:
  uint64_t h_ = 0xcbf29ce484222325ull;
};

}  // namespace lucent
