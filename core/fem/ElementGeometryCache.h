#pragma once
// The reference geometry of a body's elements (shape-function gradients and det J × weight at the Gauss points and
// the centre), kept between Newton assemblies: a Lagrangian run's reference coordinates never move, and computing
// them at every assembly took 6 % of the 2D rolling pass. An element's entry is recomputed whenever its coordinates
// differ from those it was computed at (an ALE step or a remesh moves them), so a stale entry is never used.
#include <vector>

#include "fem/SolidElement.h"

namespace rollsim {

template <int D>
class ElementGeometryCache {
 public:
  using El = SolidElement<D>;

  /// Room for `elements` entries; call before elements are asked for concurrently.
  void resize(int elements) {
    if (entries_.size() == static_cast<size_t>(elements)) return;
    entries_.clear();
    entries_.resize(static_cast<size_t>(elements));  // each entry marked not computed
  }
  /// Element e's geometry at its reference coordinates x, or null where det J ≤ 0 at a Gauss point (inverted).
  /// Different elements may be asked from different threads at once; one element from one thread at a time.
  const typename El::Geometry* at(int e, const typename El::Coords& x) {
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
