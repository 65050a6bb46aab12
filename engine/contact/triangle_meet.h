// Whether two triangles meet, decided where floating point cannot change the answer: the
// contact context's leaf test (contact_context.cc) answers most triangle pairs with it and
// leaves the rest to FCL's separating-axis test, so that its verdicts stay FCL's.
#pragma once

#include <Eigen/Core>

namespace pcsg {

enum class TriangleMeet { Apart, Intersect, Unsure };

// Triangles P = (p1, p2, p3) and Q = (q1, q2, q3), in one frame. Apart: every vertex of one
// clearly on one side of the other's plane, or the segments the two cut from each other's
// plane clearly disjoint. Intersect: those segments clearly overlap. Unsure otherwise (a
// vertex within round-off of the other plane, nearly parallel planes, segments ending within
// round-off of each other, degenerate triangles).
TriangleMeet triangles_meet(const Eigen::Vector3d& p1, const Eigen::Vector3d& p2,
                            const Eigen::Vector3d& p3, const Eigen::Vector3d& q1,
                            const Eigen::Vector3d& q2, const Eigen::Vector3d& q3);

}  // namespace pcsg
