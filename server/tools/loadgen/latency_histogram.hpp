// A fixed-memory latency histogram: 0.1 ms buckets up to 10 s, so that tens
// of thousands of clients at 20 Hz can record every frame without sorting.
#pragma once

#include <array>
#include <cstdint>

namespace mc::loadgen {

class LatencyHistogram {
 public:
  static constexpr int kBucketsPerMs = 10;
  static constexpr int kMaxMs = 10000;

  void record(double ms);
  void merge(const LatencyHistogram& other);
  std::uint64_t count() const { return count_; }
  // Value at quantile q in [0, 1], in ms (bucket upper edge); 0 when empty.
  double quantile(double q) const;
  double max() const { return max_; }

 private:
  std::array<std::uint32_t, kMaxMs * kBucketsPerMs + 1> buckets_{};
  std::uint64_t count_ = 0;
  double max_ = 0;
};

}  // namespace mc::loadgen
