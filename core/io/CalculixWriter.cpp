// CalculiX .inp writer: *NODE, *ELEMENT, *NSET, *MATERIAL, *BOUNDARY, *CLOAD, *DLOAD, one static step.
#include "io/CalculixWriter.h"

#include "fem/Loads.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>
#include <stdexcept>

namespace rollsim {

namespace {

/// Shortest text that reads back as the same double.
std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

/// CalculiX names: letters, digits and '_' only (it upper-cases them itself); at most 80 characters.
std::string sanitize(const std::string& name) {
  std::string out;
  for (char c : name) out += std::isalnum(static_cast<unsigned char>(c)) ? static_cast<char>(std::toupper(c)) : '_';
  return out.substr(0, 80);
}

void write_ids(std::ostringstream& s, const std::vector<int>& ids, int offset) {
  for (size_t i = 0; i < ids.size(); ++i)
    s << ids[i] + offset + 1 << ((i % 16 == 15 || i + 1 == ids.size()) ? "\n" : ", ");
}

/// First node / element id - 1 of each body.
struct Offsets {
  std::vector<int> node, element;
};

Offsets offsets_of(const Model& m) {
  Offsets o;
  int n = 0, e = 0;
  for (const Body& b : m.bodies) {
    o.node.push_back(n);
    o.element.push_back(e);
    n += b.mesh.num_nodes();
    e += b.mesh.num_elements();
  }
  return o;
}

void write_nodes(std::ostringstream& s, const Model& m, const Offsets& o) {
  s << "*NODE, NSET=NALL\n";
  for (size_t bi = 0; bi < m.bodies.size(); ++bi) {
    const Mesh& mesh = m.bodies[bi].mesh;
    for (int n = 0; n < mesh.num_nodes(); ++n) {
      const auto& x = mesh.nodes[n];
      s << o.node[bi] + n + 1 << ", " << num(x[0]) << ", " << num(x[1]) << ", " << num(x[2]) << "\n";
    }
  }
}

// Our Q4 (counter-clockwise) and H8 (bottom 0-1-2-3 counter-clockwise seen from +z, top 4-7 above them) orderings
// are CalculiX's CPE4 and C3D8 orderings, so the connectivity is copied as is.
void write_elements(std::ostringstream& s, const Model& m, const Offsets& o) {
  for (size_t bi = 0; bi < m.bodies.size(); ++bi) {
    const Mesh& mesh = m.bodies[bi].mesh;
    s << "*ELEMENT, TYPE=" << (m.dim == 2 ? "CPE4" : "C3D8") << ", ELSET=E_" << sanitize(m.bodies[bi].name) << "\n";
    for (int e = 0; e < mesh.num_elements(); ++e) {
      s << o.element[bi] + e + 1;
      for (int a = 0; a < mesh.nodes_per_elem(); ++a) s << ", " << mesh.element(e)[a] + o.node[bi] + 1;
      s << "\n";
    }
  }
}

void write_node_sets(std::ostringstream& s, const Model& m, const Offsets& o) {
  std::set<std::pair<int, std::string>> sets;
  for (const auto& bc : m.displacements) sets.insert({bc.body, bc.set});
  for (const auto& f : m.forces) sets.insert({f.body, f.set});
  for (const auto& [b, name] : sets) {
    s << "*NSET, NSET=" << calculix_set_name(m, b, name) << "\n";
    write_ids(s, m.bodies[b].mesh.node_sets.at(name), o.node[b]);
  }
}

void write_materials(std::ostringstream& s, const Model& m) {
  for (const Body& b : m.bodies) {
    if (b.formulation != Formulation::Full)
      throw std::invalid_argument("body '" + b.name + "': the B-bar formulation has no CalculiX CPE4/C3D8 equivalent");
    const std::string name = sanitize(b.name);
    s << "*MATERIAL, NAME=M_" << name << "\n*ELASTIC\n" << num(b.material.E) << ", " << num(b.material.nu) << "\n";
    s << "*SOLID SECTION, ELSET=E_" << name << ", MATERIAL=M_" << name << "\n";
    if (m.dim == 2) s << "1.\n";  // plane strain, unit thickness
  }
}

void write_boundary(std::ostringstream& s, const Model& m) {
  std::ostringstream lines;
  for (const auto& bc : m.displacements) {
    if (bc.rotation)
      throw std::invalid_argument("boundary_conditions[" + std::to_string(bc.source) +
                                  "]: a prescribed rotation is not exported (CalculiX's *BOUNDARY takes one value "
                                  "per set and component)");
    for (int c = 0; c < m.dim; ++c)
      if (bc.value[c]) {
        const std::string name = calculix_set_name(m, bc.body, bc.set);
        lines << name << ", " << c + 1 << ", " << c + 1 << ", " << num(*bc.value[c]) << "\n";
      }
  }
  if (!lines.str().empty()) s << "*BOUNDARY\n" << lines.str();
}

void write_forces(std::ostringstream& s, const Model& m) {
  if (m.forces.empty()) return;
  s << "*CLOAD\n";  // on a node set: the value at every node, as ours
  for (const auto& f : m.forces)
    for (int c = 0; c < m.dim; ++c)
      if (f.value[c] != 0.0)
        s << calculix_set_name(m, f.body, f.set) << ", " << c + 1 << ", " << num(f.value[c]) << "\n";
}

// Our facet `local` (Q4 edge k from node k to k+1; H8 faces bottom, top, y-, x+, y+, x- in the block) is
// CalculiX's face S(local+1) of CPE4 / C3D8; positive pressure pushes into the body in both codes.
void write_pressures(std::ostringstream& s, const Model& m, const Offsets& o) {
  if (m.pressures.empty()) return;
  s << "*DLOAD\n";
  for (const auto& p : m.pressures)
    for (const Facet& f : m.bodies[p.body].mesh.surfaces.at(p.surface))
      s << o.element[p.body] + f.element + 1 << ", P" << f.local + 1 << ", " << num(p.value) << "\n";
}

/// A typical element size: the largest extent over the element count's dim-th root.
double element_size(const Mesh& mesh) {
  double extent = 0;
  for (int k = 0; k < mesh.dim; ++k) {
    double lo = mesh.nodes.front()[k], hi = lo;
    for (const auto& x : mesh.nodes) lo = std::min(lo, x[k]), hi = std::max(hi, x[k]);
    extent = std::max(extent, hi - lo);
  }
  return extent / std::pow(std::max(1, mesh.num_elements()), 1.0 / mesh.dim);
}

std::string surface_name(const Model& m, int body, const std::string& surface) {
  return sanitize("S_" + m.bodies[body].name + "_" + surface);
}

/// An element-face surface (our facet `local` is CalculiX's face S(local+1), as for *DLOAD).
void write_surface(std::ostringstream& s, const Model& m, const Offsets& o, int body, const std::string& surface) {
  s << "*SURFACE, NAME=" << surface_name(m, body, surface) << ", TYPE=ELEMENT\n";
  for (const Facet& f : m.bodies[body].mesh.surfaces.at(surface))
    s << o.element[body] + f.element + 1 << ", S" << f.local + 1 << "\n";
}

/// The contact pairs: tied -> *TIE (slave nodes tied to the master faces, as our u_s = Σ N_k u_k rows);
/// frictionless -> node-to-surface *CONTACT PAIR, small sliding, with a linear pressure-overclosure law stiff enough
/// (1e3 × the stiffer body's E / its element size) to stand for our exact non-penetration.
void write_contacts(std::ostringstream& s, const Model& m, const Offsets& o) {
  std::set<std::pair<int, std::string>> written;
  for (const ContactPair& p : m.contacts)
    for (const auto& side : {std::make_pair(p.slave_body, p.slave_surface), {p.master_body, p.master_surface}})
      if (written.insert(side).second) write_surface(s, m, o, side.first, side.second);
  for (const ContactPair& p : m.contacts) {
    const std::string slave = surface_name(m, p.slave_body, p.slave_surface);
    const std::string master = surface_name(m, p.master_body, p.master_surface);
    const std::string name = sanitize(p.name);
    if (p.kind == ContactKind::Sticking || p.kind == ContactKind::Coulomb)
      throw std::invalid_argument("contact pair '" + p.name + "': sticking and coulomb contact are not exported");
    if (p.kind == ContactKind::Tied) {
      char tolerance[24];  // CalculiX reads a short number field
      std::snprintf(tolerance, sizeof tolerance, "%.6g", p.search_distance);
      s << "*TIE, NAME=T_" << name << ", POSITION TOLERANCE=" << tolerance << ", ADJUST=NO\n"
        << slave << ", " << master << "\n";
      continue;
    }
    const double E = std::max(m.bodies[p.slave_body].material.E, m.bodies[p.master_body].material.E);
    const double h = std::min(element_size(m.bodies[p.slave_body].mesh), element_size(m.bodies[p.master_body].mesh));
    s << "*SURFACE INTERACTION, NAME=I_" << name << "\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n"
      << num(1e3 * E / h) << "\n*CONTACT PAIR, INTERACTION=I_" << name << ", TYPE=NODE TO SURFACE, SMALL SLIDING\n"
      << slave << ", " << master << "\n";
  }
}

/// Body forces as CalculiX's own element loads BX, BY, BZ (force per volume) on the body's element set; tractions,
/// which CalculiX's *DLOAD does not take, as their consistent nodal forces (fem/Loads), node by node.
void write_body_loads(std::ostringstream& s, const Model& m, const Offsets& o) {
  if (!m.body_forces.empty()) {
    s << "*DLOAD\n";
    for (const BodyForce& f : m.body_forces)
      for (int c = 0; c < m.dim; ++c)
        if (f.value[c] != 0.0)
          s << "E_" << sanitize(m.bodies[f.body].name) << ", B"
            << "XYZ"[c] << ", " << num(f.value[c]) << "\n";
  }
  if (m.tractions.empty()) return;
  s << "*CLOAD\n";
  for (const Traction& t : m.tractions) {
    const Eigen::VectorXd F = traction_nodal_load(m.bodies[t.body].mesh, t);
    for (Eigen::Index i = 0; i < F.size(); ++i)
      if (F[i] != 0.0) s << o.node[t.body] + i / m.dim + 1 << ", " << i % m.dim + 1 << ", " << num(F[i]) << "\n";
  }
}

void write_step(std::ostringstream& s, const Model& m, const Offsets& o) {
  s << "*STEP\n*STATIC\n";
  write_boundary(s, m);
  write_forces(s, m);
  write_pressures(s, m, o);
  write_body_loads(s, m, o);
  std::set<std::string> printed;
  for (const auto& bc : m.displacements) {
    const std::string name = calculix_set_name(m, bc.body, bc.set);
    if (printed.insert(name).second) s << "*NODE PRINT, NSET=" << name << ", TOTALS=ONLY\nRF\n";
  }
  s << "*NODE FILE\nU\n*EL FILE\nS\n";  // the fields rollsim writes into result.vtu
  s << "*END STEP\n";
}

}  // namespace

std::string calculix_set_name(const Model& m, int body, const std::string& set) {
  return sanitize("N_" + m.bodies[body].name + "_" + set);
}

std::string calculix_input(const Model& m) {
  if (m.dim == 2 && !m.contacts.empty())
    throw std::invalid_argument(
        "contacts[0] ('" + m.contacts[0].name +
        "'): CalculiX expands plane-strain elements into 3D ones, and its *TIE and contact pairs do not act on them as "
        "rollsim's 2D contact does (measured on block-indent-2d-50x30: a tied pair carried no force), so a 2D model "
        "with contact cannot be exported as the same model; export the 3D model, or remove the contact");
  std::ostringstream s;
  s << "** CalculiX input written by rollsim export-ccx\n*HEADING\nrollsim model\n";
  const Offsets o = offsets_of(m);
  write_nodes(s, m, o);
  write_elements(s, m, o);
  write_node_sets(s, m, o);
  write_materials(s, m);
  write_contacts(s, m, o);
  write_step(s, m, o);
  return s.str();
}

}  // namespace rollsim
