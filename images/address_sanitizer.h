// Defines LUCENT_ASAN when this translation unit is compiled with AddressSanitizer.
#pragma once

// Clang says __has_feature(address_sanitizer); GCC defines __SANITIZE_ADDRESS__.
#if defined(__SANITIZE_ADDRESS__)
#define LUCENT_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define LUCENT_ASAN 1
#endif
#endif
