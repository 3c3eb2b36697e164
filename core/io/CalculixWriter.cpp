#include "io/CalculixWriter.h"

#include <cstdio>
#include <set>
#include <sstream>
#include <stdexcept>

namespace rollsim {

namespace {

std::string set_name(const Model& m, int body, const std::string& set) { return "N_" + m.bodies[body].name + "_" + set; }

void write_ids(std::ostringstream& s, const std::vector<int>& ids, int offset) {
  for (size_t i = 0; i < ids.size(); ++i) s << ids[i] + offset + 1 << ((i % 16 == 15 || i + 1 == ids.size()) ? "\n" : ", ");
}

void write_mesh(std::ostringstream& s, const Model& m, std::vector<int>& node_offset) {
  char line[128];
  s << "*NODE\n";
  int offset = 0, eoffset = 0;
  for (const Body& b : m.bodies) {
    node_offset.push_back(offset);
    for (int n = 0; n < b.mesh.num_nodes(); ++n) {
      const auto& x = b.mesh.nodes[n];
      std::snprintf(line, sizeof line, "%d, %.17g, %.17g, %.17g\n", offset + n + 1, x[0], x[1], x[2]);
      s << line;
    }
    offset += b.mesh.num_nodes();
  }
  for (size_t bi = 0; bi < m.bodies.size(); ++bi) {
    const Mesh& mesh = m.bodies[bi].mesh;
    s << "*ELEMENT, TYPE=" << (m.dim == 2 ? "CPE4" : "C3D8") << ", ELSET=E_" << m.bodies[bi].name << "\n";
    for (int e = 0; e < mesh.num_elements(); ++e) {
      s << eoffset + e + 1;
      for (int a = 0; a < mesh.nodes_per_elem(); ++a) s << ", " << mesh.element(e)[a] + node_offset[bi] + 1;
      s << "\n";
    }
    eoffset += mesh.num_elements();
  }
}

}  // namespace

std::string calculix_input(const Model& m) {
  if (!m.pressures.empty()) throw std::invalid_argument("pressure loads are not exported to CalculiX yet");
  std::ostringstream s;
  s << "** CalculiX input written by rollsim export-ccx\n*HEADING\nrollsim model\n";
  std::vector<int> offset;
  write_mesh(s, m, offset);
  std::set<std::pair<int, std::string>> sets;
  for (const auto& bc : m.displacements) sets.insert({bc.body, bc.set});
  for (const auto& f : m.forces) sets.insert({f.body, f.set});
  for (const auto& [b, name] : sets) {
    s << "*NSET, NSET=" << set_name(m, b, name) << "\n";
    const auto& nodes = m.bodies[b].mesh.node_sets.at(name);
    write_ids(s, nodes, offset[b]);
  }
  for (const Body& b : m.bodies) {
    s << "*MATERIAL, NAME=M_" << b.name << "\n*ELASTIC\n" << b.material.E << ", " << b.material.nu << "\n";
    s << "*SOLID SECTION, ELSET=E_" << b.name << ", MATERIAL=M_" << b.name << "\n";
    if (m.dim == 2) s << "1.\n";  // unit thickness
  }
  s << "*STEP\n*STATIC\n*BOUNDARY\n";
  for (const auto& bc : m.displacements)
    for (int c = 0; c < m.dim; ++c)
      if (bc.value[c]) s << set_name(m, bc.body, bc.set) << ", " << c + 1 << ", " << c + 1 << ", " << *bc.value[c] << "\n";
  if (!m.forces.empty()) {
    s << "*CLOAD\n";
    for (const auto& f : m.forces)
      for (int c = 0; c < m.dim; ++c)
        if (f.value[c] != 0.0) s << set_name(m, f.body, f.set) << ", " << c + 1 << ", " << f.value[c] << "\n";
  }
  for (const auto& bc : m.displacements)
    s << "*NODE PRINT, NSET=" << set_name(m, bc.body, bc.set) << ", TOTALS=ONLY\nRF\n";
  s << "*END STEP\n";
  return s.str();
}

}  // namespace rollsim
