// The secret in the preview's address: any page on this machine (or, with --bind, on the
// network) could otherwise read the scene's render, or drive the server, through the
// browser. Every request must carry it.
#pragma once

#include <string>

namespace lucent::preview {

// 32 hexadecimal digits (128 bits) from std::random_device (the kernel's /dev/urandom on
// Linux).
std::string makeToken();

// Whether `given` is the token, compared in time independent of where they differ.
bool tokenAccepted(const std::string& given, const std::string& token);

}  // namespace lucent::preview
