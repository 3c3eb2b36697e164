#include "io/OutputFields.h"

#include <algorithm>

#include "material/Material.h"
#include "mesh/ElementQuality.h"

namespace rollsim {

namespace {
void displacement(const Model& m, size_t b, const BodyResults& r, int n, double* out) {
  const int dim = m.bodies[b].mesh.dim;
  for (int c = 0; c < 3; ++c) out[c] = c < dim ? r.displacement[n * dim + c] : 0.0;
}
void nodal_stress(const Model&, size_t, const BodyResults& r, int n, double* out) {
  std::copy(r.nodal_stress[n].begin(), r.nodal_stress[n].end(), out);
}
void nodal_von_mises(const Model&, size_t, const BodyResults& r, int n, double* out) {
  out[0] = von_mises(r.nodal_stress[n].data());
}
void contact_pressure(const Model&, size_t, const BodyResults& r, int n, double* out) {
  out[0] = n < r.contact_pressure.size() ? r.contact_pressure[n] : 0.0;
}
void contact_slip(const Model&, size_t, const BodyResults& r, int n, double* out) {
  out[0] = n < r.contact_slip.size() ? r.contact_slip[n] : 0.0;
}
void contact_shear(const Model& m, size_t b, const BodyResults& r, int n, double* out) {
  const int dim = m.bodies[b].mesh.dim;
  for (int c = 0; c < 3; ++c)
    out[c] = c < dim && n * dim + c < r.contact_shear.size() ? r.contact_shear[n * dim + c] : 0.0;
}
void element_stress(const Model&, size_t, const BodyResults& r, int e, double* out) {
  std::copy(r.element_stress[e].begin(), r.element_stress[e].end(), out);
}
void element_von_mises(const Model&, size_t, const BodyResults& r, int e, double* out) {
  out[0] = von_mises(r.element_stress[e].data());
}
void plastic_strain(const Model&, size_t, const BodyResults& r, int e, double* out) {
  out[0] = static_cast<size_t>(e) < r.plastic_strain.size() ? r.plastic_strain[e] : 0.0;
}
void temperature(const Model& m, size_t b, const BodyResults& r, int e, double* out) {
  out[0] = static_cast<size_t>(e) < r.temperature.size() ? r.temperature[e] : m.bodies[b].material.temperature;
}
void nodal_temperature(const Model& m, size_t b, const BodyResults& r, int n, double* out) {
  out[0] = n < r.nodal_temperature.size() ? r.nodal_temperature[n] : m.bodies[b].material.temperature;
}
void jacobian_ratio(const Model& m, size_t b, const BodyResults& r, int e, double* out) {
  const Mesh& mesh = m.bodies[b].mesh;
  const bool displaced = r.displacement.size() == static_cast<Eigen::Index>(mesh.num_nodes()) * mesh.dim;
  out[0] = displaced ? corner_jacobian_ratio(mesh, r.displacement.data(), e) : 1.0;
}
bool has_contact(const Model& m) { return !m.contacts.empty(); }
bool has_finite_strain(const Model& m) {
  return std::any_of(m.bodies.begin(), m.bodies.end(),
                     [](const Body& b) { return b.kinematics == Kinematics::Finite; });
}
bool has_plasticity(const Model& m) {
  return std::any_of(m.bodies.begin(), m.bodies.end(), [](const Body& b) { return b.material.plastic(); });
}
bool has_temperature(const Model& m) {
  return std::any_of(m.bodies.begin(), m.bodies.end(),
                     [](const Body& b) { return b.material.thermal() || b.material.conducts(); });
}
bool conducts_heat(const Model& m) { return m.conducts_heat(); }
}  // namespace

const std::vector<OutputField>& output_fields() {
  using L = FieldLocation;
  static const std::vector<OutputField> fields = {
      {"displacement", "displacement |u|", "|u|", "length", L::Node, 3, true, {}, displacement},
      {"stress", "stress (nodal average)", "stress", "stress", L::Node, 6, false, {}, nodal_stress},
      {"von_mises", "von Mises stress", "von Mises", "stress", L::Node, 1, true, {}, nodal_von_mises},
      {"contact_pressure", "contact pressure", "contact p", "stress", L::Node, 1, true, has_contact, contact_pressure},
      {"contact_slip", "contact slip (tangential sliding so far)", "slip", "length", L::Node, 1, true, has_contact,
       contact_slip},
      {"contact_shear", "contact shear traction |t|", "contact shear", "stress", L::Node, 3, true, has_contact,
       contact_shear},
      {"stress", "stress (element mean)", "stress", "stress", L::Cell, 6, false, {}, element_stress},
      {"von_mises", "von Mises stress (element mean)", "von Mises", "stress", L::Cell, 1, false, {}, element_von_mises},
      {"plastic_strain", "equivalent plastic strain (element mean)", "plastic strain", "-", L::Cell, 1, true,
       has_plasticity, plastic_strain},
      {"temperature", "temperature (nodal: heat conduction)", "temperature", "°C", L::Node, 1, true, conducts_heat,
       nodal_temperature},
      {"temperature",
       "temperature (element mean: the material's plus the rise from plastic work, or its nodes' where heat conducts)",
       "temperature", "°C", L::Cell, 1, true, has_temperature, temperature},
      {"jacobian_ratio", "element quality: smallest corner Jacobian, deformed / undeformed (≤ 0: folded)", "J ratio",
       "-", L::Cell, 1, true, has_finite_strain, jacobian_ratio},
  };
  return fields;
}

bool is_present(const OutputField& field, const Model& model) { return !field.present || field.present(model); }

std::vector<std::string> output_field_names() {
  std::vector<std::string> names;
  for (const OutputField& f : output_fields())
    if (std::find(names.begin(), names.end(), f.name) == names.end()) names.push_back(f.name);
  return names;
}

bool is_selected(const OutputField& field, const std::vector<std::string>& names) {
  return names.empty() || std::find(names.begin(), names.end(), kAllFields) != names.end() ||
         std::find(names.begin(), names.end(), field.name) != names.end();
}

const char* to_string(FieldLocation location) { return location == FieldLocation::Node ? "node" : "cell"; }

double vtu_bytes(const Model& model, const std::vector<std::string>& selected) {
  const double nodes = static_cast<double>(model.total_nodes()), cells = static_cast<double>(model.total_elements());
  const int corners = model.dim == 2 ? 4 : 8;
  double values = nodes * 3 + cells * (corners + 1);  // points; connectivity and offsets (types: a byte each)
  for (const OutputField& f : output_fields())
    if (is_present(f, model) && is_selected(f, selected))
      values += f.components * (f.location == FieldLocation::Node ? nodes : cells);
  return values * 8 + cells;
}

}  // namespace rollsim
