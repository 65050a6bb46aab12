#pragma once
// Seed states. The paper asked a person for the seed (the state with the most contacts) and
// notes that a complete graph needs one seed per local maximum of cardinality (Section IV).
// pcsg finds candidates itself: A is pushed toward B from a fixed, deterministic set of
// directions and orientations and settles by a compliant motion that keeps every contact it
// makes and lowers its potential along the push (like a body coming to rest under a force);
// resting states collect contacts, concave elements collect the most.
#include <vector>

#include "engine/contact/contact_formation.h"
#include "engine/generator/transition_motion.h"

namespace pcsg {

struct SeedCandidate {
  ContactFormation cf;
  Pose pose;
  std::vector<PointContact> contacts;
  bool off_centre = false;  // from a push off B's centre (find_seed_candidates)
};

// Candidates of the pushes at B's centre, then of the off-centre pushes (seeds.cc; marked
// off_centre), each sorted by cardinality (highest first), then by CF; one per distinct CF and pose
// region is not guaranteed (the generator merges them). The pushes run on `threads` threads;
// the result does not depend on their number.
std::vector<SeedCandidate> find_seed_candidates(const SceneGeometry& scene,
                                                MotionCounters& counters, int threads = 1);

// A listed seed pose, projected onto the CF it touches in, or, when it is apart by less than
// the detection band (1e-3 L), onto the CF of the distance minima within the band. Throws
// SceneError (the seed's place in the scene file) when it penetrates or nothing is that near.
SeedCandidate seed_from_pose(const SceneGeometry& scene, const SeedSpec& seed,
                             MotionCounters& counters);

}  // namespace pcsg
