#pragma once
// The reference geometry of a body's elements (shape-function gradients and det J × weight at the Gauss points and
// the centre), kept between Newton assemblies: a Lagrangian run's reference coordinates never move, and computing
// them at every assembly took 6 % of the 2D rolling pass. An element's entry is recomputed whenever its coordinates
// differ from those it was computed at (an ALE step or a remesh moves them), so a stale entry is never used.
#include <cstddef>
#include <vector>

#include "fem/SolidElement.h"

namespace rollsim {

/// The memory a body's element caches may take each (this one, FiniteStrainElement's PointUpdates): above it — some
/// 130 000 hexahedra here, 70 000 there — the kernel computes what they would keep, as it did without them.
inline constexpr size_t kElementCacheBytes = size_t{256} << 20;

template <int D>
class ElementGeometryCache {
 public:
  using El = SolidElement<D>;

  /// Room for `elements` entries (none beyond kElementCacheBytes); call before elements are asked for concurrently.
  void resize(int elements) {
    const size_t wanted = static_cast<size_t>(elements) * sizeof(Entry) <= kElementCacheBytes ? elements : 0;
    if (entries_.size() == wanted) return;
    entries_.clear();
    entries_.resize(wanted);  // each entry marked not computed
  }
  /// Element e's geometry at its reference coordinates x, or null where det J ≤ 0 at a Gauss point (inverted); in
  /// `scratch` when the cache holds no entries. Different elements may be asked from different threads at once; one
  /// element from one thread at a time.
  const typename El::Geometry* at(int e, const typename El::Coords& x, typename El::Geometry& scratch) {
    if (entries_.empty()) return El::gradients(x, scratch) ? &scratch : nullptr;
    Entry& entry = entries_[static_cast<size_t>(e)];
    if (!entry.computed || entry.x != x) {
      entry.x = x;
      entry.valid = El::gradients(x, entry.geometry);
      entry.computed = true;
    }
    return entry.valid ? &entry.geometry : nullptr;
  }

 private:
  struct Entry {
    typename El::Coords x;
    typename El::Geometry geometry;
    bool computed = false, valid = false;
  };
  std::vector<Entry> entries_;
};

}  // namespace rollsim
