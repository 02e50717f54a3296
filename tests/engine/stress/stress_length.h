#pragma once
// The stress suite's two lengths and its memory probes. `ctest -L stress` runs the suite; it runs
// short by default (CI runs it so, under the sanitizers too) and at the lengths the issue asks
// for when RBSIM_STRESS=long is set:  RBSIM_STRESS=long ctest --test-dir build -L stress
#include <malloc.h>

#include <cstdlib>
#include <fstream>
#include <string>

namespace rbsim::test {

inline bool longStress() {
  const char* length = std::getenv("RBSIM_STRESS");
  return length != nullptr && std::string(length) == "long";
}

inline long stressSteps(long shortRun, long longRun) { return longStress() ? longRun : shortRun; }

// AddressSanitizer keeps freed blocks in quarantine and its allocator bypasses glibc's, so the
// process's memory measures nothing about the engine there; LeakSanitizer checks leaks instead.
#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kMemoryIsMeasurable = false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kMemoryIsMeasurable = false;
#else
inline constexpr bool kMemoryIsMeasurable = true;
#endif
#else
inline constexpr bool kMemoryIsMeasurable = true;
#endif

// Peak resident set size of this process so far [KiB] (VmHWM in /proc/self/status), 0 if unknown.
inline long peakRssKiB() {
  std::ifstream status("/proc/self/status");
  std::string key;
  long value = 0;
  while (status >> key) {
    if (key == "VmHWM:") {
      status >> value;
      return value;
    }
    std::getline(status, key);
  }
  return 0;
}

// Bytes the program holds from malloc right now (glibc's count of allocated chunks).
inline long heapInUse() { return static_cast<long>(mallinfo2().uordblks); }

}  // namespace rbsim::test
