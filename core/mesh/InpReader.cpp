#include "mesh/InpReader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

namespace rollsim {

namespace {

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string trim(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line);
  for (std::string item; std::getline(in, item, ',');) out.push_back(trim(item));  // none after a trailing comma
  return out;
}

/// A keyword line: its name (upper case, after '*') and its parameters (upper-case keys; values as written).
struct Keyword {
  std::string name;
  std::map<std::string, std::string> params;
  std::string param(const std::string& key) const {
    const auto it = params.find(key);
    return it == params.end() ? "" : it->second;
  }
};

Keyword keyword(const std::string& line) {
  const std::vector<std::string> parts = split(line.substr(1));
  Keyword k;
  k.name = parts.empty() ? "" : upper(parts[0]);
  for (size_t i = 1; i < parts.size(); ++i) {
    const size_t eq = parts[i].find('=');
    k.params[upper(trim(parts[i].substr(0, eq)))] = eq == std::string::npos ? "" : trim(parts[i].substr(eq + 1));
  }
  return k;
}

class DeckParser {
 public:
  explicit DeckParser(InpDeck& deck) : deck_(deck) {}

  void parse(const std::string& text, const std::string& source) {
    std::istringstream in(text);
    std::string raw;
    int line_no = 0;
    Keyword current;  // the block the data lines belong to
    std::vector<std::string> pending;
    int pending_line = 0;
    while (std::getline(in, raw)) {
      ++line_no;
      const std::string line = trim(raw);
      if (line.empty() || line.rfind("**", 0) == 0) continue;
      where_ = source + ":" + std::to_string(line_no);
      if (line[0] == '*') {
        if (!pending.empty()) fail(source + ":" + std::to_string(pending_line), "the element's node list ends early");
        current = keyword(line);
        begin(current, source);
        continue;
      }
      std::vector<std::string> items = split(line);
      if (current.name == "ELEMENT") {  // an element's nodes may run on over lines that end with a comma
        if (pending.empty()) pending_line = line_no;
        pending.insert(pending.end(), items.begin(), items.end());
        if (line.back() == ',') continue;
        items.swap(pending);
        pending.clear();
      }
      data(current, items);
    }
    if (!pending.empty()) fail(source + ":" + std::to_string(pending_line), "the element's node list ends early");
  }

 private:
  [[noreturn]] void fail(const std::string& where, const std::string& what) const {
    throw MeshImportError(where + ": " + what);
  }
  [[noreturn]] void fail(const std::string& what) const { fail(where_, what); }

  int integer(const std::string& s) const {
    try {
      size_t used = 0;
      const long v = std::stol(s, &used);
      if (used == s.size() && v > 0 && v <= 2147483647L) return static_cast<int>(v);
    } catch (const std::exception&) {
    }
    fail("'" + s + "' is not a positive integer id");
  }

  double number(const std::string& s) const {
    try {
      size_t used = 0;
      const double v = std::stod(s, &used);
      if (used == s.size() && std::isfinite(v)) return v;
    } catch (const std::exception&) {
    }
    fail("'" + s + "' is not a finite number");
  }

  std::string set_name(const Keyword& k, const std::string& key) const {
    const std::string name = k.param(key);
    if (name.empty()) fail("*" + k.name + " without " + key + "=");
    return upper(name);
  }

  void begin(const Keyword& k, const std::string& source) {
    if (k.name == "NODE" || k.name == "NSET" || k.name == "ELSET" || k.name == "SURFACE") {
      if (k.name == "NSET") set_name(k, "NSET");
      if (k.name == "ELSET") set_name(k, "ELSET");
      if (k.name == "SURFACE") {
        set_name(k, "NAME");
        if (const std::string t = upper(k.param("TYPE")); !t.empty() && t != "ELEMENT")
          fail("*SURFACE, TYPE=" + t + ": only element-face surfaces (TYPE=ELEMENT) are read");
      }
      return;
    }
    if (k.name == "ELEMENT") {
      if (upper(k.param("TYPE")).empty()) fail("*ELEMENT without TYPE=");
      return;
    }
    if (k.name == "INCLUDE") {
      std::filesystem::path file = k.param("INPUT");
      if (file.empty()) fail("*INCLUDE without INPUT=");
      if (file.is_relative()) file = std::filesystem::path(source).parent_path() / file;
      if (++depth_ > 8) fail("*INCLUDE nested more than 8 deep");
      const std::string here = where_;
      std::ifstream in(file, std::ios::binary);
      if (!in) fail("*INCLUDE: cannot read " + file.string());
      std::ostringstream text;
      text << in.rdbuf();
      parse(text.str(), file.string());
      where_ = here;
      --depth_;
      return;
    }
    if (std::find(deck_.ignored.begin(), deck_.ignored.end(), "*" + k.name) == deck_.ignored.end())
      deck_.ignored.push_back("*" + k.name);
  }

  void data(const Keyword& k, const std::vector<std::string>& items) {
    if (items.empty()) return;
    if (k.name == "NODE") return node(k, items);
    if (k.name == "ELEMENT") return element(k, items);
    if (k.name == "NSET") return members(k, items, set_name(k, "NSET"), deck_.node_sets, deck_.node_sets);
    if (k.name == "ELSET") return members(k, items, set_name(k, "ELSET"), deck_.element_sets, deck_.element_sets);
    if (k.name == "SURFACE") return surface(set_name(k, "NAME"), items);
  }

  void node(const Keyword& k, const std::vector<std::string>& items) {
    if (items.size() < 2 || items.size() > 4) fail("a node line is: id, x, y[, z]");
    const int id = integer(items[0]);
    std::array<double, 3> x{0, 0, 0};
    for (size_t i = 1; i < items.size(); ++i) x[i - 1] = number(items[i]);
    if (!deck_.nodes.emplace(id, x).second) fail("node " + items[0] + " is defined twice");
    if (!k.param("NSET").empty()) deck_.node_sets[upper(k.param("NSET"))].push_back(id);
  }

  void element(const Keyword& k, const std::vector<std::string>& items) {
    InpDeck::Element e;
    e.type = upper(k.param("TYPE"));
    e.id = integer(items[0]);
    for (size_t i = 1; i < items.size(); ++i) e.nodes.push_back(integer(items[i]));
    if (!element_ids_.insert(e.id).second) fail("element " + items[0] + " is defined twice");
    if (!k.param("ELSET").empty()) deck_.element_sets[upper(k.param("ELSET"))].push_back(e.id);
    deck_.elements.push_back(std::move(e));
  }

  /// A set's data line: ids, names of sets of the same kind, or with GENERATE first, last[, step].
  void members(const Keyword& k, const std::vector<std::string>& items, const std::string& name,
               std::map<std::string, std::vector<int>>& sets, const std::map<std::string, std::vector<int>>& known) {
    std::vector<int>& set = sets[name];
    if (k.params.count("GENERATE")) {
      if (items.size() < 2 || items.size() > 3) fail("a GENERATE line is: first, last[, step]");
      const int first = integer(items[0]), last = integer(items[1]), step = items.size() == 3 ? integer(items[2]) : 1;
      if (last < first) fail("GENERATE: last " + items[1] + " is below first " + items[0]);
      for (long id = first; id <= last; id += step) set.push_back(static_cast<int>(id));
      return;
    }
    for (const std::string& item : items) {
      if (!item.empty() && std::isdigit(static_cast<unsigned char>(item[0]))) {
        set.push_back(integer(item));
        continue;
      }
      const auto it = known.find(upper(item));
      if (it == known.end() || upper(item) == name) fail("no set named '" + item + "' defined before this line");
      const std::vector<int> members = it->second;  // a copy: `set` may be the same map's new entry
      set.insert(set.end(), members.begin(), members.end());
    }
  }

  void surface(const std::string& name, const std::vector<std::string>& items) {
    if (items.size() != 2) fail("a surface line is: element or element set, face S1…S6");
    const std::string face = upper(items[1]);
    if (face.size() != 2 || face[0] != 'S' || face[1] < '1' || face[1] > '6')
      fail("'" + items[1] + "' is not an element face S1…S6");
    const int local = face[1] - '0';
    auto& facets = deck_.surfaces[name];
    if (std::isdigit(static_cast<unsigned char>(items[0][0]))) {
      facets.emplace_back(integer(items[0]), local);
      return;
    }
    const auto it = deck_.element_sets.find(upper(items[0]));
    if (it == deck_.element_sets.end()) fail("no element set named '" + items[0] + "' defined before this line");
    for (int e : it->second) facets.emplace_back(e, local);
  }

  InpDeck& deck_;
  std::string where_;
  std::set<int> element_ids_;
  int depth_ = 0;
};

/// Linear quadrilaterals (2D) and hexahedra (3D) by their CalculiX / Abaqus names.
int element_dimension(const std::string& type) {
  static const std::set<std::string> quads{"CPE4", "CPE4R", "CPE4H", "CPE4I", "CPS4",   "CPS4R", "CPS4I",
                                           "CAX4", "CAX4R", "CAX4H", "CAX4I", "CPE4RH", "CAX4RH"};
  static const std::set<std::string> hexes{"C3D8", "C3D8R", "C3D8I", "C3D8H", "C3D8RH"};
  if (quads.count(type)) return 2;
  if (hexes.count(type)) return 3;
  return 0;
}

std::string unsupported(const std::string& type) {
  if (type.rfind("C3D4", 0) == 0 || type.rfind("C3D10", 0) == 0) return "tetrahedra";
  if (type.rfind("C3D6", 0) == 0 || type.rfind("C3D15", 0) == 0) return "wedges";
  if (type.rfind("C3D20", 0) == 0 || type.find('8') != std::string::npos) return "quadratic elements";
  if (type.find('3') != std::string::npos || type.find('6') != std::string::npos) return "triangles";
  return "elements of this type";
}

}  // namespace

InpDeck parse_inp_deck(const std::string& text, const std::string& source) {
  InpDeck deck;
  DeckParser(deck).parse(text, source);
  return deck;
}

InpDeck read_inp_deck(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw MeshImportError(file.string() + ": cannot be read");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_inp_deck(text.str(), file.string());
}

namespace {

/// The elements of the body: every element, or those of `element_set`.
std::vector<const InpDeck::Element*> body_elements(const InpDeck& deck, const std::string& element_set,
                                                   const std::string& source) {
  std::vector<const InpDeck::Element*> out;
  if (element_set.empty()) {
    for (const auto& e : deck.elements) out.push_back(&e);
    return out;
  }
  const auto set = deck.element_sets.find(upper(element_set));
  if (set == deck.element_sets.end()) {
    std::string names;
    for (const auto& [name, ids] : deck.element_sets) names += (names.empty() ? "" : ", ") + name;
    throw MeshImportError(source + ": no element set named '" + element_set +
                              "' (the deck has: " + (names.empty() ? "none" : names) + ")",
                          "element_set");
  }
  std::map<int, const InpDeck::Element*> by_id;
  for (const auto& e : deck.elements) by_id[e.id] = &e;
  for (int id : std::set<int>(set->second.begin(), set->second.end())) {
    const auto it = by_id.find(id);
    if (it == by_id.end())
      throw MeshImportError(source + ": element set '" + element_set + "' names element " + std::to_string(id) +
                            ", which the deck does not define");
    out.push_back(it->second);
  }
  return out;
}

void check_types(const std::vector<const InpDeck::Element*>& elements, int dim, const std::string& source) {
  for (const InpDeck::Element* e : elements) {
    const int d = element_dimension(e->type);
    if (d == 0)
      throw MeshImportError(source + ": element " + std::to_string(e->id) + " is a " + e->type + ": " +
                            unsupported(e->type) +
                            " are not supported (rollsim reads linear quadrilaterals, CPE4/CPS4/CAX4, "
                            "and hexahedra, C3D8, with their R/H/I variants)");
    if (d != dim)
      throw MeshImportError(source + ": element " + std::to_string(e->id) + " is a " + e->type + ", a " +
                            std::to_string(d) + "D element in a " + std::to_string(dim) + "D model (dimension)");
    if (static_cast<int>(e->nodes.size()) != (dim == 2 ? 4 : 8))
      throw MeshImportError(source + ": element " + std::to_string(e->id) + " (" + e->type + ") has " +
                            std::to_string(e->nodes.size()) + " nodes, not " + (dim == 2 ? "4" : "8"));
  }
}

/// Which local element of `mesh` is inverted, by the deck's id (check_element_orientation names the local index).
void check_orientation(const Mesh& mesh, const std::vector<const InpDeck::Element*>& elements,
                       const std::string& source) {
  try {
    check_element_orientation(mesh);
  } catch (const std::runtime_error&) {
    for (int e = 0; e < mesh.num_elements(); ++e) {
      Mesh one;
      one.dim = mesh.dim;
      one.type = mesh.type;
      for (int a = 0; a < mesh.nodes_per_elem(); ++a) {
        one.nodes.push_back(mesh.nodes[static_cast<size_t>(mesh.element(e)[a])]);
        one.connectivity.push_back(a);
      }
      try {
        check_element_orientation(one);
      } catch (const std::runtime_error& why) {
        throw MeshImportError(source + ": element " + std::to_string(elements[static_cast<size_t>(e)]->id) +
                              " is inverted or degenerate (its nodes must run counter-clockwise" +
                              (mesh.dim == 3 ? " on the face S1 seen from the element's inside" : "") + ")");
      }
    }
    throw;
  }
}

}  // namespace

Mesh inp_body_mesh(const InpDeck& deck, int dim, const std::string& element_set, const std::string& source) {
  const std::vector<const InpDeck::Element*> elements = body_elements(deck, element_set, source);
  if (elements.empty())
    throw MeshImportError(source + ": no element" +
                          (element_set.empty() ? "" : " in element set '" + element_set + "'"));
  check_types(elements, dim, source);
  Mesh mesh;
  mesh.dim = dim;
  mesh.type = dim == 2 ? ElementType::Quad4 : ElementType::Hex8;
  std::map<int, int> local;  // deck node id -> body node
  for (const InpDeck::Element* e : elements)
    for (int n : e->nodes) {
      if (!deck.nodes.count(n))
        throw MeshImportError(source + ": element " + std::to_string(e->id) + " names node " + std::to_string(n) +
                              ", which the deck does not define");
      local.emplace(n, 0);
    }
  for (auto& [id, index] : local) {
    index = mesh.num_nodes();
    const std::array<double, 3>& x = deck.nodes.at(id);
    if (dim == 2 && x[2] != 0.0)
      throw MeshImportError(source + ": node " + std::to_string(id) + " has z = " + std::to_string(x[2]) +
                            " in a 2D model (the plane is z = 0)");
    mesh.nodes.push_back(x);
  }
  std::map<int, int> element_index;
  for (const InpDeck::Element* e : elements) {
    element_index[e->id] = mesh.num_elements();
    for (int n : e->nodes) mesh.connectivity.push_back(local.at(n));
  }
  check_orientation(mesh, elements, source);
  for (const auto& [name, ids] : deck.node_sets) {
    std::set<int> in;
    for (int id : ids)
      if (const auto it = local.find(id); it != local.end()) in.insert(it->second);
    if (!in.empty()) mesh.node_sets[lower(name)].assign(in.begin(), in.end());
  }
  for (const auto& [name, ids] : deck.element_sets) {
    std::set<int> in;
    for (int id : ids)
      if (const auto it = element_index.find(id); it != element_index.end()) in.insert(it->second);
    if (!in.empty()) mesh.element_sets[lower(name)].assign(in.begin(), in.end());
  }
  const int faces = dim == 2 ? 4 : 6;
  for (const auto& [name, facets] : deck.surfaces) {
    std::vector<Facet> in;
    for (const auto& [id, face] : facets) {
      const auto it = element_index.find(id);
      if (it == element_index.end()) continue;
      if (face > faces)
        throw MeshImportError(source + ": surface '" + name + "': element " + std::to_string(id) + " has no face S" +
                              std::to_string(face) + " (a quadrilateral has S1…S4)");
      in.push_back({it->second, face - 1});
    }
    if (!in.empty()) mesh.surfaces[lower(name)] = std::move(in);
  }
  add_derived_node_sets(mesh);
  return mesh;
}

}  // namespace rollsim
