#include "model/Model.h"

namespace rollsim {

long Model::total_nodes() const {
  long n = 0;
  for (const Body& b : bodies) n += b.mesh.num_nodes();
  return n;
}

long Model::total_elements() const {
  long n = 0;
  for (const Body& b : bodies) n += b.mesh.num_elements();
  return n;
}

}  // namespace rollsim
