// CalculiX .inp writer: *NODE, *ELEMENT, *NSET, *MATERIAL, *BOUNDARY, *CLOAD, *DLOAD, one static step.
#include "io/CalculixWriter.h"

#include <cctype>
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
  for (const auto& bc : m.displacements)
    for (int c = 0; c < m.dim; ++c)
      if (bc.value[c]) {
        const std::string name = calculix_set_name(m, bc.body, bc.set);
        lines << name << ", " << c + 1 << ", " << c + 1 << ", " << num(*bc.value[c]) << "\n";
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

void write_step(std::ostringstream& s, const Model& m, const Offsets& o) {
  s << "*STEP\n*STATIC\n";
  write_boundary(s, m);
  write_forces(s, m);
  write_pressures(s, m, o);
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
  std::ostringstream s;
  s << "** CalculiX input written by rollsim export-ccx\n*HEADING\nrollsim model\n";
  const Offsets o = offsets_of(m);
  write_nodes(s, m, o);
  write_elements(s, m, o);
  write_node_sets(s, m, o);
  write_materials(s, m);
  write_step(s, m, o);
  return s.str();
}

}  // namespace rollsim
