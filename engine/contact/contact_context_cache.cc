// A small process-wide cache of contact contexts, so that the SceneGeometry overloads of the
// contact API (detect_contacts, project_onto_cf) build each scene's BVHs once.
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <mutex>

#include "engine/contact/contact_context.h"

namespace pcsg {
namespace {

// Entries kept: a program holds a few scenes at a time (a scene and its scaled and moved
// copies in the invariance tests); older ones are dropped.
constexpr size_t kCacheEntries = 8;
// Mesh vertices folded into the fingerprint: enough to tell meshes of different scenes apart,
// few enough to cost well under a microsecond per query.
constexpr size_t kSampledVertices = 64;

// FNV-1a over 64-bit words (one multiply per value rather than per byte).
struct Fingerprint {
  std::uint64_t h = 1469598103934665603ull;
  void add_word(std::uint64_t w) { h = (h ^ w) * 1099511628211ull; }
  void add(double x) {
    std::uint64_t w;
    std::memcpy(&w, &x, sizeof w);
    add_word(w);
  }
  void add(size_t x) { add_word(static_cast<std::uint64_t>(x)); }
};

void add_solid(Fingerprint& f, const Solid& s, const SolidMesh& m) {
  f.add(s.surfaces.size());
  f.add(s.faces.size());
  f.add(s.edges.size());
  f.add(s.vertices.size());
  for (const Polynomial& g : s.surfaces) {
    for (double c : g.coeffs()) f.add(c);
    for (int k = 0; k < 3; ++k) f.add(g.origin()[k]);
  }
  f.add(m.positions.size());
  f.add(m.triangles.size());
  f.add(m.chordal_error);
  if (!m.positions.empty()) {
    const size_t step = std::max<size_t>(1, m.positions.size() / kSampledVertices);
    for (size_t i = 0; i < m.positions.size(); i += step)
      for (int k = 0; k < 3; ++k) f.add(m.positions[i][k]);
  }
}

std::uint64_t fingerprint(const SceneGeometry& scene) {
  Fingerprint f;
  f.add(scene.tol.length_scale);
  f.add(scene.tol.candidate_band);
  add_solid(f, scene.A, scene.mesh_A);
  add_solid(f, scene.B, scene.mesh_B);
  return f.h;
}

struct Entry {
  const SceneGeometry* scene;
  std::uint64_t fingerprint;
  std::shared_ptr<const ContactContext> context;
};

}  // namespace

std::shared_ptr<const ContactContext> cached_contact_context(const SceneGeometry& scene) {
  static std::mutex mutex;
  static std::vector<Entry> entries;  // most recently used first
  const std::uint64_t fp = fingerprint(scene);
  std::lock_guard<std::mutex> lock(mutex);
  for (size_t i = 0; i < entries.size(); ++i)
    if (entries[i].scene == &scene && entries[i].fingerprint == fp) {
      std::rotate(entries.begin(), entries.begin() + i, entries.begin() + i + 1);
      return entries.front().context;
    }
  auto context = std::make_shared<const ContactContext>(scene);
  entries.insert(entries.begin(), Entry{&scene, fp, context});
  if (entries.size() > kCacheEntries) entries.pop_back();
  return context;
}

}  // namespace pcsg
