#pragma once
// Is an edge a circle? A least-squares circle through an edge's samples, for reports
// (`pcsg inspect` prints the radius and centre of circular edges).
#include <Eigen/Geometry>

#include "engine/geometry/solid.h"

namespace pcsg {

struct CircleFit {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // of the best-fit plane
  double radius = 0;
  // Largest distance of a sample from the fitted circle: ~0 for a true circle.
  double max_deviation = 0;
};

// Plane by principal components, then an algebraic (Kasa) circle fit in that plane.
CircleFit fit_circle(const Edge& edge);

}  // namespace pcsg
