#include "render/contact_roles.h"

#include <algorithm>
#include <map>
#include <tuple>

namespace pcsg::render {

namespace {

using PairKey = std::tuple<int, int, int, int, int>;  // a kind, a index, b kind, b index, type

PairKey key_of(const PointContact& c) {
  return {static_cast<int>(c.a.kind), c.a.index, static_cast<int>(c.b.kind), c.b.index,
          static_cast<int>(c.type)};
}
PairKey key_of(const PtcCount& e) {
  return {static_cast<int>(e.a.kind), e.a.index, static_cast<int>(e.b.kind), e.b.index,
          static_cast<int>(e.type)};
}

struct Track {
  PairKey start_pair, pair;
  Eigen::Vector3d point;
  bool from_start = false;
  bool alive = true;
  int changed_at = -1;  // first frame whose pair differs from the start's
  int lost_at = -1;     // first frame without it
};

}  // namespace

const char* contact_role_name(ContactRole role) {
  switch (role) {
    case ContactRole::Kept:
      return "kept";
    case ContactRole::Changing:
      return "changing";
    case ContactRole::Reached:
      return "reached";
    case ContactRole::Undecided:
      return "kept or changing";
    case ContactRole::Other:
      return "unplanned";
  }
  return "unplanned";
}

std::vector<std::vector<ContactRole>> assign_contact_roles(
    const std::vector<PointContact>& start, const std::vector<std::vector<PointContact>>& frames,
    const ContactFormation& target, double match_distance, bool ends_in_failure) {
  std::vector<Track> tracks;
  for (const PointContact& c : start)
    tracks.push_back({key_of(c), key_of(c), c.point_B, true, true, -1, -1});

  // 1. follow the contacts: track_of[k][i] is the track of frames[k][i]
  std::vector<std::vector<int>> track_of(frames.size());
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const std::vector<PointContact>& cs = frames[k].empty() ? start : frames[k];
    std::vector<int>& owner = track_of[k];
    owner.assign(cs.size(), -1);
    std::vector<bool> taken(tracks.size(), false);
    // same pair first, then a changed pair within reach; nearest pairs of points first
    for (bool same_pair : {true, false}) {
      std::vector<std::tuple<double, int, int>> options;  // distance, contact, track
      for (std::size_t i = 0; i < cs.size(); ++i) {
        if (owner[i] >= 0) continue;
        for (std::size_t t = 0; t < tracks.size(); ++t) {
          if (taken[t] || !tracks[t].alive) continue;
          const double d = (cs[i].point_B - tracks[t].point).norm();
          if (same_pair ? key_of(cs[i]) == tracks[t].pair : d <= match_distance)
            options.emplace_back(d, static_cast<int>(i), static_cast<int>(t));
        }
      }
      std::sort(options.begin(), options.end());
      for (const auto& [d, i, t] : options) {
        if (owner[i] >= 0 || taken[t]) continue;
        owner[i] = t;
        taken[t] = true;
      }
    }
    for (std::size_t i = 0; i < cs.size(); ++i) {
      if (owner[i] < 0) {  // a contact that appeared
        tracks.push_back({key_of(cs[i]), key_of(cs[i]), cs[i].point_B, false, true, -1, -1});
        taken.push_back(true);
        owner[i] = static_cast<int>(tracks.size()) - 1;
      }
      Track& t = tracks[owner[i]];
      t.pair = key_of(cs[i]);
      t.point = cs[i].point_B;
      if (t.from_start && t.changed_at < 0 && t.pair != t.start_pair) t.changed_at = static_cast<int>(k);
    }
    for (std::size_t t = 0; t < tracks.size(); ++t) {
      if (!taken[t] && tracks[t].alive) {
        tracks[t].alive = false;
        tracks[t].lost_at = static_cast<int>(k);
      }
    }
  }

  // 2. the role of each start contact in the whole motion: the kept multiset is what the start
  //    CF and the target CF share; contacts seen to change or vanish are not kept
  std::map<PairKey, int> target_count, kept_left;
  for (const PtcCount& e : target.entries()) target_count[key_of(e)] = e.count;
  std::map<PairKey, int> start_count;
  for (const PointContact& c : start) ++start_count[key_of(c)];
  for (const auto& [pair, n] : start_count) {
    const auto it = target_count.find(pair);
    kept_left[pair] = it == target_count.end() ? 0 : std::min(n, it->second);
  }
  // the frames whose changes count as the plan's: all, or all but the failure
  const int evidence_end = static_cast<int>(frames.size()) - (ends_in_failure ? 1 : 0);
  auto before_end = [&](int k) { return k >= 0 && k < evidence_end; };
  std::vector<ContactRole> base(tracks.size(), ContactRole::Other);
  std::map<PairKey, std::vector<int>> unchanged;  // start tracks that neither changed nor vanished
  for (std::size_t t = 0; t < tracks.size(); ++t) {
    if (!tracks[t].from_start) continue;
    if (before_end(tracks[t].changed_at) || before_end(tracks[t].lost_at)) {
      base[t] = ContactRole::Changing;
    } else {
      unchanged[tracks[t].start_pair].push_back(static_cast<int>(t));
    }
  }
  for (const auto& [pair, ts] : unchanged) {
    const int kept = kept_left[pair];
    const int changing = static_cast<int>(start_count[pair]) - kept;
    const int seen_changing = static_cast<int>(start_count[pair] - ts.size());
    for (int t : ts) {
      if (kept == 0) base[t] = ContactRole::Changing;
      else if (seen_changing >= changing) base[t] = ContactRole::Kept;  // the others changed
      else base[t] = ContactRole::Undecided;
    }
  }

  // 3. per frame: a changed contact is "reached" once it is on a pair of the target CF
  std::vector<std::vector<ContactRole>> roles(frames.size());
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const std::vector<PointContact>& cs = frames[k].empty() ? start : frames[k];
    for (std::size_t i = 0; i < cs.size(); ++i) {
      const int t = track_of[k][i];
      const Track& tr = tracks[t];
      const bool in_target = target_count.count(key_of(cs[i])) > 0;
      ContactRole r = base[t];
      if (tr.from_start && tr.changed_at >= 0 && static_cast<int>(k) >= tr.changed_at)
        r = in_target ? ContactRole::Reached : ContactRole::Other;
      if (!tr.from_start) r = in_target && start_count.count(key_of(cs[i])) == 0 ? ContactRole::Reached : ContactRole::Other;
      roles[k].push_back(r);
    }
  }
  return roles;
}

}  // namespace pcsg::render
