#pragma once
// The one place the engine names a compiler's extension (issue 57): each behind a test of the
// compiler, with a standard fallback, so GCC, Clang, MSVC and mingw-w64 build the same sources.
// tests/layers/check_portability.py keeps every other engine file to standard C++17.
#if defined(_MSC_VER) && !defined(__clang__) && (defined(_M_X64) || defined(_M_IX86))
#include <xmmintrin.h>
#endif

namespace rbsim {

// Asks the core to start loading the cache line at `address` for writing; a hint that changes no
// result, so the fallback does nothing.
inline void prefetchForWriting(const void* address) {
#if defined(__GNUC__) || defined(__clang__)
  __builtin_prefetch(address, /*for writing*/ 1);
#elif defined(_MSC_VER) && (defined(_M_X64) || defined(_M_IX86))
  _mm_prefetch(static_cast<const char*>(address), _MM_HINT_T0);
#else
  static_cast<void>(address);
#endif
}

}  // namespace rbsim
