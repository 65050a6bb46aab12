#include "engine/contact/report_cache.h"

#include <algorithm>
#include <cstring>

namespace pcsg {

ReportCache::Key ReportCache::key(const Pose& X_BA, double near_margin) {
  Key k;
  const std::array<std::uint64_t, 7> pose = pose_bits(X_BA);
  std::copy(pose.begin(), pose.end(), k.begin());
  std::memcpy(&k[7], &near_margin, sizeof near_margin);
  return k;
}

size_t ReportCache::Hash::operator()(const Key& k) const {
  // FNV-1a over the words (one multiply per word)
  std::uint64_t h = 1469598103934665603ull;
  for (std::uint64_t w : k) h = (h ^ w) * 1099511628211ull;
  return static_cast<size_t>(h ^ (h >> 32));
}

std::optional<ContactReport> ReportCache::recall(const Key& key) const {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = reports_.find(key);
  if (it == reports_.end()) return std::nullopt;
  return it->second;
}

void ReportCache::remember(const Key& key, const ContactReport& report) {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto [it, added] = reports_.emplace(key, report);
  if (!added) {
    // another thread was first; a full report replaces one cut short at its first penetration
    if (it->second.cut_short && !report.cut_short) it->second = report;
    return;
  }
  order_.push_back(key);
  if (order_.size() > capacity_) {
    reports_.erase(order_.front());
    order_.pop_front();
  }
}

}  // namespace pcsg
