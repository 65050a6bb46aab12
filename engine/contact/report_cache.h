#pragma once
// The reports of one contact context's recent queries, by pose: the generator asks the same
// pose again and again (a motion's last step and its end check, a witness and the motions and
// connectivity checks that start from it): 2337 of Example 1's 14603 queries repeated a pose
// bit for bit, 1800 of them within the last 64 queries. A report is a pure function of the
// context and the query (pose, near margin, and whether it stops at its first penetration:
// detect_contacts cuts a recalled full report to that form), so a recalled report is the one
// the query would return, and results do not depend on what the cache holds (nor on threads).
#include <array>
#include <cstdint>
#include <deque>
#include <mutex>
#include <optional>
#include <unordered_map>

#include "engine/contact/contact.h"

namespace pcsg {

class ReportCache {
 public:
  // The pose's seven coordinates and the near margin, bit for bit.
  using Key = std::array<std::uint64_t, 8>;
  static Key key(const Pose& X_BA, double near_margin);

  explicit ReportCache(size_t capacity) : capacity_(capacity) {}
  std::optional<ContactReport> recall(const Key& key) const;
  // Keeps the report, dropping the oldest when full. A report cut short at its first
  // penetration (ContactReport::cut_short) answers only queries that stop there too, and a full
  // report of the same query replaces it.
  void remember(const Key& key, const ContactReport& report);

 private:
  struct Hash {
    size_t operator()(const Key& k) const;
  };
  size_t capacity_;
  mutable std::mutex mutex_;
  std::unordered_map<Key, ContactReport, Hash> reports_;
  std::deque<Key> order_;  // oldest first
};

}  // namespace pcsg
