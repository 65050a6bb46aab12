#pragma once
// Where each element's label points: candidate anchor points (image pixels), best first, at
// places where the element is visible, i.e. nearest to the eye in the element-id pass.
// Faces: the visible pixel farthest from the region's border (its "pole of inaccessibility"),
// then other well-separated interior pixels. Edges: visible curve points, the one farthest
// out from the objects' centre first, so that leader lines point outward.
#include <Eigen/Core>
#include <vector>

#include "render/camera.h"
#include "render/id_target.h"
#include "render/scene_element.h"

namespace pcsg::render {

struct ElementSamples {
  SceneElement element;
  // World points on the element: edge curve points, a vertex's point, or (for faces, used only
  // when the face is nowhere visible) a subset of its mesh vertices.
  std::vector<Eigen::Vector3d> points_W;
};

// One list of candidates per element (empty when the element is entirely off screen).
std::vector<std::vector<Eigen::Vector2d>> find_label_anchors(
    const IdImage& ids, const CameraView& view, const std::vector<ElementSamples>& elements);

}  // namespace pcsg::render
