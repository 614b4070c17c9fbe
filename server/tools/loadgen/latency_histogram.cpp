#include "server/tools/loadgen/latency_histogram.hpp"

#include <algorithm>
#include <cmath>

namespace mc::loadgen {

void LatencyHistogram::record(double ms) {
  // Clock skew between stamping and receipt is impossible on one machine but
  // rounding can give -0.0x ms: count it as zero.
  ms = std::max(0.0, ms);
  const auto i = std::min<std::size_t>(static_cast<std::size_t>(ms * kBucketsPerMs),
                                       buckets_.size() - 1);
  ++buckets_[i];
  ++count_;
  max_ = std::max(max_, ms);
}

void LatencyHistogram::merge(const LatencyHistogram& o) {
  for (std::size_t i = 0; i < buckets_.size(); ++i) buckets_[i] += o.buckets_[i];
  count_ += o.count_;
  max_ = std::max(max_, o.max_);
}

double LatencyHistogram::quantile(double q) const {
  if (count_ == 0) return 0;
  const auto target = static_cast<std::uint64_t>(std::ceil(q * static_cast<double>(count_)));
  std::uint64_t seen = 0;
  for (std::size_t i = 0; i < buckets_.size(); ++i) {
    seen += buckets_[i];
    if (seen >= std::max<std::uint64_t>(target, 1))
      return static_cast<double>(i + 1) / kBucketsPerMs;
  }
  return max_;
}

}  // namespace mc::loadgen
