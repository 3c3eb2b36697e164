#pragma once
// Loops over a body's elements with the element kernel of its dimension.
#include <unordered_map>
#include <utility>

#include "fem/SolidElement.h"
#include "model/Model.h"

namespace rollsim {

template <int D>
typename SolidElement<D>::Coords element_coords(const Mesh& m, int e) {
  typename SolidElement<D>::Coords x;
  const int* conn = m.element(e);
  for (int a = 0; a < SolidElement<D>::NN; ++a)
    for (int i = 0; i < D; ++i) x(i, a) = m.nodes[conn[a]][i];
  return x;
}

/// Element stiffnesses by shape: K_e of coordinates relative to the first node, kept for the next element of the same
/// relative coordinates (bit for bit). At most kShapes shapes are kept (a graded or unstructured mesh has as many as
/// elements; the kept ones still serve their repeats), 4.6 KB each in 3D.
template <int D>
class SameShapeStiffness {
 public:
  static constexpr size_t kShapes = 1024;
  using El = SolidElement<D>;
  const typename El::Stiffness& of(const typename El::Coords& relative, const Material& material, Formulation f) {
    const size_t h = hash(relative);
    const auto range = kept_.equal_range(h);
    for (auto it = range.first; it != range.second; ++it)
      if (it->second.first == relative) return it->second.second;
    El::stiffness(relative, material, f, Ke_);
    if (kept_.size() < kShapes) kept_.emplace(h, std::make_pair(relative, Ke_));
    return Ke_;
  }

 private:
  static size_t hash(const typename El::Coords& x) {
    size_t h = 1469598103934665603ull;  // FNV-1a over the coordinates' bytes
    const auto* bytes = reinterpret_cast<const unsigned char*>(x.data());
    for (size_t i = 0; i < sizeof(double) * static_cast<size_t>(x.size()); ++i) h = (h ^ bytes[i]) * 1099511628211ull;
    return h;
  }
  std::unordered_multimap<size_t, std::pair<typename El::Coords, typename El::Stiffness>> kept_;
  typename El::Stiffness Ke_;
};

/// Calls f(e, Ke) with each element stiffness, column-major, node-major dof order. K_e is computed from the element's
/// coordinates relative to its first node, and congruent elements — a generated block's are all alike — share one
/// computation (SameShapeStiffness).
template <class F>
void for_each_element_stiffness(const Body& b, F&& f) {
  const auto material = make_material(b.material);
  auto run = [&]<int D>() {
    SameShapeStiffness<D> shapes;
    for (int e = 0; e < b.mesh.num_elements(); ++e) {
      typename SolidElement<D>::Coords x = element_coords<D>(b.mesh, e);
      const Eigen::Matrix<double, D, 1> first = x.col(0);
      x.colwise() -= first;
      f(e, shapes.of(x, *material, b.formulation).data());
    }
  };
  if (b.mesh.dim == 2)
    run.template operator()<2>();
  else
    run.template operator()<3>();
}

}  // namespace rollsim
