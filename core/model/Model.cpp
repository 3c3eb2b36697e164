#include "model/Model.h"

namespace rollsim {

long Model::total_nodes() const {
  long n = 0;
  for (const Body& b : bodies) n += b.mesh.num_nodes();
  return n;
}

bool Model::conducts_heat() const {
  for (const Body& b : bodies)
    if (b.material.conducts()) return true;
  return false;
}

long Model::total_elements() const {
  long n = 0;
  for (const Body& b : bodies) n += b.mesh.num_elements();
  return n;
}

}  // namespace rollsim
