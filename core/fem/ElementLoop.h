#pragma once
// Loops over a body's elements with the element kernel of its dimension.
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

/// Calls f(e, Ke) with each element stiffness, column-major, node-major dof order.
template <class F>
void for_each_element_stiffness(const Body& b, F&& f) {
  const auto material = make_material(b.material);
  auto run = [&]<int D>() {
    typename SolidElement<D>::Stiffness Ke;
    for (int e = 0; e < b.mesh.num_elements(); ++e) {
      SolidElement<D>::stiffness(element_coords<D>(b.mesh, e), *material, b.formulation, Ke);
      f(e, Ke.data());
    }
  };
  if (b.mesh.dim == 2)
    run.template operator()<2>();
  else
    run.template operator()<3>();
}

}  // namespace rollsim
