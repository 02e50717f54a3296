#pragma once
// What throughput_bench and particle_bench share to measure a step against the memory bound: the
// memcpy bandwidth out of every cache (bytes processed = read + written, the step's convention)
// and a reporter that keeps each run's rates for the summary printed after the table.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <vector>

namespace rbsim::bench {

inline constexpr std::size_t kKiB = 1024, kMiB = 1024 * kKiB;

// The last-level cache as the system reports it (a virtual machine may report the host's).
inline std::size_t lastLevelCacheBytes() {
  for (int name : {_SC_LEVEL4_CACHE_SIZE, _SC_LEVEL3_CACHE_SIZE, _SC_LEVEL2_CACHE_SIZE}) {
    const long bytes = sysconf(name);
    if (bytes > 0) return static_cast<std::size_t>(bytes);
  }
  return 0;
}

// Out of cache: at least 256 MiB and twice what the last-level cache is said to hold.
inline std::size_t outOfCacheBytes() { return std::max<std::size_t>(256 * kMiB, 2 * lastLevelCacheBytes()); }

// memcpy of state.range(0) bytes, registered by copyBenchmarkName's name.
inline void copyBuffer(benchmark::State& state) {
  const std::size_t size = static_cast<std::size_t>(state.range(0));
  std::vector<char> source(size, 1), destination(size, 0);
  for (auto _ : state) {
    std::memcpy(destination.data(), source.data(), size);
    benchmark::DoNotOptimize(destination.data());
    benchmark::ClobberMemory();
  }
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(2 * size));
}

inline std::string copyBenchmarkName(std::size_t bytes) { return "memcpy/" + std::to_string(bytes); }

// Keeps every run's rates (the median when repetitions are aggregated) for the summary.
class SummaryReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      if (run.error_occurred) continue;
      if (run.run_type == Run::RT_Aggregate && run.aggregate_name != "median") continue;
      for (const char* rate : {"items_per_second", "bytes_per_second"}) {
        const auto it = run.counters.find(rate);
        if (it != run.counters.end()) rates_[run.run_name.str()] = it->second.value;
      }
    }
  }
  double rate(const std::string& name) const {
    const auto it = rates_.find(name);
    return it == rates_.end() ? 0.0 : it->second;
  }

 private:
  std::map<std::string, double> rates_;
};

}  // namespace rbsim::bench
