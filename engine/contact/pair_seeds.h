#pragma once
// Local distance minima of one element pair at a pose, whatever their gap: the starting points
// of a projection onto a contact formation when the start pose's detection does not already
// show the pair (paper Section II-C: the same pair may form several contacts, so all minima
// are wanted, not only the nearest).
#include <vector>

#include "engine/contact/contact_context.h"
#include "engine/contact/pair_solver.h"

namespace pcsg {

// Samples both elements (mesh vertices of faces, exact samples of edges, vertex points),
// ranks them by a first-order distance estimate, solves the pair from the best spatially
// separated ones and returns the distinct converged local minima with opposite normals, by
// increasing gap. The solutions are this pair's even where its points leave the elements
// (the projection needs the pair itself; detection decides the final classification).
std::vector<PointContact> pair_local_minima(const ContactContext& context, const Pose& X_BA,
                                            ElementId a, ElementId b, PtcType type);

}  // namespace pcsg
