#include "engine/contact/contact_formation.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <tuple>

#include "engine/core/error.h"

namespace pcsg {
namespace {

auto key(const PtcCount& e) { return std::make_tuple(e.a, e.b, static_cast<int>(e.type)); }

const std::string& element_name(const Solid& solid, ElementId id) {
  switch (id.kind) {
    case ElementKind::Face: return solid.faces[id.index].name;
    case ElementKind::Edge: return solid.edges[id.index].name;
    case ElementKind::Vertex: break;
  }
  return solid.vertices[id.index].name;
}

ElementId find_element(const Solid& solid, const std::string& name) {
  for (int i = 0; i < static_cast<int>(solid.faces.size()); ++i)
    if (solid.faces[i].name == name) return {ElementKind::Face, i};
  for (int i = 0; i < static_cast<int>(solid.edges.size()); ++i)
    if (solid.edges[i].name == name) return {ElementKind::Edge, i};
  for (int i = 0; i < static_cast<int>(solid.vertices.size()); ++i)
    if (solid.vertices[i].name == name) return {ElementKind::Vertex, i};
  return {ElementKind::Face, -1};
}

// A small cursor over the CF text, with errors that quote the text and the column.
struct Reader {
  const std::string& text;
  size_t pos = 0;
  void skip() {
    while (pos < text.size() && std::isspace(static_cast<unsigned char>(text[pos]))) ++pos;
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw UsageError("contact formation \"" + text + "\": " + what + " at column " +
                     std::to_string(pos + 1) + " (expected e.g. \"{(fA-f1, 2)}\")");
  }
  bool accept(char c) {
    skip();
    if (pos < text.size() && text[pos] == c) {
      ++pos;
      return true;
    }
    return false;
  }
  void expect(char c) {
    if (!accept(c)) fail(std::string("expected '") + c + "'");
  }
  // Characters up to the next ',' or ')' with surrounding blanks removed.
  std::string field() {
    skip();
    const size_t start = pos;
    while (pos < text.size() && text[pos] != ',' && text[pos] != ')') ++pos;
    size_t end = pos;
    while (end > start && std::isspace(static_cast<unsigned char>(text[end - 1]))) --end;
    return text.substr(start, end - start);
  }
};

}  // namespace

std::string element_pair_name(const SceneGeometry& scene, ElementId a, ElementId b) {
  return element_name(scene.A, a) + "-" + element_name(scene.B, b);
}

ContactFormation ContactFormation::of(const std::vector<PointContact>& contacts) {
  ContactFormation cf;
  for (const PointContact& c : contacts) cf.add(c.a, c.b, c.type, 1);
  return cf;
}

void ContactFormation::add(ElementId a, ElementId b, PtcType type, int count) {
  if (count < 1) throw std::invalid_argument("ContactFormation::add: count must be >= 1");
  if (ptc_kind_a(type) != a.kind || ptc_kind_b(type) != b.kind)
    throw std::invalid_argument(std::string("ContactFormation::add: type ") +
                                ptc_type_name(type) + " does not join the elements' kinds");
  const PtcCount e{a, b, type, count};
  auto it = std::lower_bound(entries_.begin(), entries_.end(), e,
                             [](const PtcCount& x, const PtcCount& y) { return key(x) < key(y); });
  if (it != entries_.end() && key(*it) == key(e))
    it->count += count;
  else
    entries_.insert(it, e);
}

int ContactFormation::count(ElementId a, ElementId b, PtcType type) const {
  for (const PtcCount& e : entries_)
    if (e.a == a && e.b == b && e.type == type) return e.count;
  return 0;
}

int ContactFormation::cardinality() const {
  int n = 0;
  for (const PtcCount& e : entries_) n += e.count;
  return n;
}

std::string ContactFormation::str(const SceneGeometry& scene) const {
  // Entries by name, as the paper writes them ({(eA-f1, 1), (fA2-e1, 1)}); the order depends
  // only on the CF and the names.
  std::vector<std::pair<std::string, std::string>> parts;
  for (const PtcCount& e : entries_)
    parts.push_back({element_pair_name(scene, e.a, e.b),
                     ", " + std::to_string(e.count) + (e.type == PtcType::EETouch ? ", touch" : "")});
  std::sort(parts.begin(), parts.end());
  std::string s = "{";
  for (size_t i = 0; i < parts.size(); ++i)
    s += (i ? ", (" : "(") + parts[i].first + parts[i].second + ")";
  return s + "}";
}

std::uint64_t ContactFormation::hash() const {
  std::uint64_t h = 1469598103934665603ull;  // FNV-1a over the entries' integers
  auto mix = [&h](std::uint64_t x) {
    for (int k = 0; k < 8; ++k) h = (h ^ ((x >> (8 * k)) & 0xff)) * 1099511628211ull;
  };
  for (const PtcCount& e : entries_) {
    mix(static_cast<std::uint64_t>(e.a.kind));
    mix(static_cast<std::uint64_t>(e.a.index));
    mix(static_cast<std::uint64_t>(e.b.kind));
    mix(static_cast<std::uint64_t>(e.b.index));
    mix(static_cast<std::uint64_t>(e.type));
    mix(static_cast<std::uint64_t>(e.count));
  }
  return h;
}

bool ContactFormation::operator==(const ContactFormation& o) const {
  if (entries_.size() != o.entries_.size()) return false;
  for (size_t i = 0; i < entries_.size(); ++i)
    if (key(entries_[i]) != key(o.entries_[i]) || entries_[i].count != o.entries_[i].count)
      return false;
  return true;
}

bool ContactFormation::operator<(const ContactFormation& o) const {
  auto full = [](const PtcCount& e) { return std::tuple_cat(key(e), std::make_tuple(e.count)); };
  return std::lexicographical_compare(
      entries_.begin(), entries_.end(), o.entries_.begin(), o.entries_.end(),
      [&](const PtcCount& x, const PtcCount& y) { return full(x) < full(y); });
}

ContactFormation ContactFormation::parse(const std::string& text, const SceneGeometry& scene) {
  Reader in{text};
  ContactFormation cf;
  in.expect('{');
  if (!in.accept('}')) {
    do {
      in.expect('(');
      const size_t at = in.pos;
      const std::string pair = in.field();
      // Split "alpha_A-alpha_B" at the '-' that gives an element of A and one of B (names may
      // themselves hold '-').
      ElementId a{ElementKind::Face, -1}, b{ElementKind::Face, -1};
      for (size_t k = pair.find('-'); k != std::string::npos && b.index < 0;
           k = pair.find('-', k + 1)) {
        a = find_element(scene.A, pair.substr(0, k));
        b = a.index < 0 ? a : find_element(scene.B, pair.substr(k + 1));
      }
      if (a.index < 0 || b.index < 0) {
        in.pos = at;
        in.fail("\"" + pair + "\" is not a pair of an element of A and an element of B");
      }
      in.expect(',');
      const std::string count_text = in.field();
      int count = 0;
      try {
        size_t used = 0;
        count = std::stoi(count_text, &used);
        if (used != count_text.size()) count = 0;
      } catch (const std::exception&) {
        count = 0;
      }
      if (count < 1) in.fail("multiplicity \"" + count_text + "\" is not a positive integer");
      PtcType type = ptc_type_between(a.kind, b.kind);
      if (in.accept(',')) {
        const std::string kind = in.field();
        if (type != PtcType::EECross || (kind != "touch" && kind != "cross"))
          in.fail("\"" + kind + "\": only e-e pairs take a third field, \"touch\" or \"cross\"");
        if (kind == "touch") type = PtcType::EETouch;
      }
      in.expect(')');
      cf.add(a, b, type, count);
    } while (in.accept(','));
    in.expect('}');
  }
  in.skip();
  if (in.pos != text.size()) in.fail("unexpected text after '}'");
  return cf;
}

}  // namespace pcsg
