#include "preview_token.h"

#include <random>

namespace lucent::preview {

std::string makeToken() {
  std::random_device device;
  static constexpr char kHex[] = "0123456789abcdef";
  std::string token;
  for (int word = 0; word < 4; ++word) {
    const unsigned value = device();  // 32 bits each
    for (int shift = 28; shift >= 0; shift -= 4) token += kHex[(value >> shift) & 0xf];
  }
  return token;
}

bool tokenAccepted(const std::string& given, const std::string& token) {
  if (token.empty() || given.size() != token.size()) return false;
  unsigned char differ = 0;
  for (size_t i = 0; i < token.size(); ++i)
    differ |= static_cast<unsigned char>(given[i] ^ token[i]);
  return differ == 0;
}

}  // namespace lucent::preview
