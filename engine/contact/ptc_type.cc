// The PtC types of paper Section II-B: names, kinds, codimensions, contact planes and lines.
#include <array>

#include "engine/contact/contact.h"

namespace pcsg {
namespace {

struct TypeInfo {
  PtcType type;
  const char* name;
  ElementKind a, b;
  int codimension;
  bool plane, line;
};

// Codimension: independent scalar conditions on the pose. Two smooth manifolds touching is one
// condition (the distance vanishes) for f-f, f-e, f-v and crossing edges; a vertex on an edge
// is two (a point on a curve); a vertex on a vertex is three; touching edges add the two
// conditions of parallel tangents to the one of meeting.
constexpr std::array<TypeInfo, 10> kTypes = {{
    {PtcType::FF, "f-f", ElementKind::Face, ElementKind::Face, 1, true, false},
    {PtcType::FE, "f-e", ElementKind::Face, ElementKind::Edge, 1, true, false},
    {PtcType::EF, "e-f", ElementKind::Edge, ElementKind::Face, 1, true, false},
    {PtcType::EECross, "e-e-cross", ElementKind::Edge, ElementKind::Edge, 1, true, false},
    {PtcType::EETouch, "e-e-touch", ElementKind::Edge, ElementKind::Edge, 3, false, true},
    {PtcType::FV, "f-v", ElementKind::Face, ElementKind::Vertex, 1, true, false},
    {PtcType::VF, "v-f", ElementKind::Vertex, ElementKind::Face, 1, true, false},
    {PtcType::EV, "e-v", ElementKind::Edge, ElementKind::Vertex, 2, false, true},
    {PtcType::VE, "v-e", ElementKind::Vertex, ElementKind::Edge, 2, false, true},
    {PtcType::VV, "v-v", ElementKind::Vertex, ElementKind::Vertex, 3, false, false},
}};

const TypeInfo& info(PtcType t) {
  for (const TypeInfo& i : kTypes)
    if (i.type == t) return i;
  return kTypes[0];
}

}  // namespace

const char* ptc_type_name(PtcType t) { return info(t).name; }

std::optional<PtcType> parse_ptc_type(const std::string& s) {
  for (const TypeInfo& i : kTypes)
    if (s == i.name) return i.type;
  return std::nullopt;
}

int ptc_codimension(PtcType t) { return info(t).codimension; }
ElementKind ptc_kind_a(PtcType t) { return info(t).a; }
ElementKind ptc_kind_b(PtcType t) { return info(t).b; }
bool has_contact_plane(PtcType t) { return info(t).plane; }
bool has_contact_line(PtcType t) { return info(t).line; }

PtcType ptc_type_between(ElementKind a, ElementKind b) {
  for (const TypeInfo& i : kTypes)
    if (i.a == a && i.b == b) return i.type;  // e-e: EECross comes first
  return PtcType::FF;
}

std::optional<ContactPlane> contact_plane(const PointContact& c) {
  if (!has_contact_plane(c.type)) return std::nullopt;
  // f-f: the common tangent plane; f-e, f-v: the face's tangent plane; e-e-cross: the plane of
  // both tangents. In every case its normal is the contact normal.
  return ContactPlane{c.point_B, c.normal_B};
}

std::optional<ContactLine> contact_line(const PointContact& c) {
  if (!has_contact_line(c.type)) return std::nullopt;
  // The tangent line of the edge (of B's edge for v-e and e-e-touch, of A's for e-v).
  return ContactLine{c.point_B, c.type == PtcType::EV ? c.tangent_a_B : c.tangent_b_B};
}

int crossing_sign(const PointContact& c) {
  return c.tangent_a_B.cross(c.tangent_b_B).dot(c.normal_B) > 0 ? 1 : -1;
}

}  // namespace pcsg
