#pragma once
// GROTTO_ASAN is 1 in a unit compiled with AddressSanitizer, else 0 (GCC defines
// __SANITIZE_ADDRESS__; clang answers __has_feature instead).
#if defined(__SANITIZE_ADDRESS__)
#define GROTTO_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define GROTTO_ASAN 1
#endif
#endif
#ifndef GROTTO_ASAN
#define GROTTO_ASAN 0
#endif
