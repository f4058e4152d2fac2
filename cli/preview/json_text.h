// The little JSON the preview's events are made of, and base64 for the PNG bytes in them.
#pragma once

#include <string>

namespace lucent::preview {

// `text` as a JSON string literal, quotes included; never a line break in it.
std::string jsonString(const std::string& text);

// RFC 4648 base64 of `bytes`, with padding.
std::string base64(const std::string& bytes);

}  // namespace lucent::preview
