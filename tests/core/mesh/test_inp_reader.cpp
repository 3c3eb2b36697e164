// A CalculiX / Abaqus deck read into a body's mesh: ids in any order and with gaps, keywords in any case, element
// lines that run on, sets by list, by GENERATE and by other sets, surfaces by element and by element set, *INCLUDE;
// every unsupported or broken input refused with the file, the line and what is wrong.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "../../common/FreshDir.h"
#include "mesh/InpReader.h"
#include "mesh/MeshImport.h"

namespace test_inp_reader {

using namespace rollsim;

namespace {

// two Q4 elements side by side (ids 10 and 20), nodes numbered 101…106 with a gap, a third element (30) in its own
// set; comments, lower-case keywords and an element line that runs on
const char* kDeck2D = R"(** a 2 x 1 strip and one more square
*Heading
strip
*node, nset=every
101, 0, 0
102, 1, 0
104, 2, 0
105, 0, 1
106, 1, 1
107, 2, 1
201, 5, 0
202, 6, 0
203, 6, 1
204, 5, 1
*ELEMENT, TYPE=CPE4R, ELSET=strip
20, 102, 104, 107,
 106
10, 101, 102, 106, 105
*Element, type=CPS4, elset=other
30, 201, 202, 203, 204
*NSET, NSET=LEFT
101, 105
*NSET, NSET=BOTTOM, GENERATE
101, 104, 1
*NSET, NSET=BOTH
left, bottom
*ELSET, ELSET=FIRST
10
*SURFACE, NAME=Top, TYPE=ELEMENT
strip, S3
*SURFACE, NAME=right
20, S2
*MATERIAL, NAME=STEEL
*ELASTIC
210000, 0.3
*STEP
*STATIC
*END STEP
)";

InpDeck deck2d() { return parse_inp_deck(kDeck2D, "strip.inp"); }

std::string refusal(const std::string& text, int dim = 2, const std::string& set = "") {
  try {
    inp_body_mesh(parse_inp_deck(text, "deck.inp"), dim, set, "deck.inp");
  } catch (const MeshImportError& e) {
    return e.what();
  }
  return "";
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST(InpReader, ReadsTheDecksMeshKeywordsAndListsTheOthers) {
  const InpDeck d = deck2d();
  EXPECT_EQ(d.nodes.size(), 10u);
  ASSERT_EQ(d.elements.size(), 3u);
  EXPECT_EQ(d.elements[0].id, 20);
  EXPECT_EQ(d.elements[0].type, "CPE4R");
  EXPECT_EQ(d.elements[0].nodes, (std::vector<int>{102, 104, 107, 106}));       // the line that ran on
  EXPECT_EQ(d.node_sets.at("BOTTOM"), (std::vector<int>{101, 102, 103, 104}));  // GENERATE: 103 is not a node
  EXPECT_EQ(d.node_sets.at("BOTH"), (std::vector<int>{101, 105, 101, 102, 103, 104}));
  EXPECT_EQ(d.element_sets.at("STRIP"), (std::vector<int>{20, 10}));
  EXPECT_EQ(d.surfaces.at("TOP").size(), 2u);
  EXPECT_EQ(d.ignored,
            (std::vector<std::string>{"*HEADING", "*MATERIAL", "*ELASTIC", "*STEP", "*STATIC", "*END STEP"}));
}

TEST(InpReader, ABodyIsItsElementSetWithItsSetsRestrictedToIt) {
  const Mesh m = inp_body_mesh(deck2d(), 2, "Strip", "strip.inp");
  EXPECT_EQ(m.type, ElementType::Quad4);
  ASSERT_EQ(m.num_nodes(), 6);  // 101 102 104 105 106 107, numbered in the order of their ids
  ASSERT_EQ(m.num_elements(), 2);
  EXPECT_EQ(m.nodes[2][0], 2.0);  // node 104
  // the set's elements in the order of their ids: 10 then 20
  EXPECT_EQ(std::vector<int>(m.element(0), m.element(0) + 4), (std::vector<int>{0, 1, 4, 3}));
  EXPECT_EQ(std::vector<int>(m.element(1), m.element(1) + 4), (std::vector<int>{1, 2, 5, 4}));
  EXPECT_EQ(m.node_sets.at("left"), (std::vector<int>{0, 3}));
  EXPECT_EQ(m.node_sets.at("bottom"), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(m.node_sets.at("every").size(), 6u);  // the other body's nodes dropped
  EXPECT_EQ(m.element_sets.at("first"), (std::vector<int>{0}));
  EXPECT_FALSE(m.element_sets.count("other"));  // nothing of it in this body
  // S3 of a CPE4 runs from its third node to its fourth: rollsim's edge 2
  ASSERT_EQ(m.surfaces.at("top").size(), 2u);
  for (const Facet& f : m.surfaces.at("top")) EXPECT_EQ(f.local, 2);
  EXPECT_EQ(m.node_sets.at("top"), (std::vector<int>{3, 4, 5}));  // a surface is a node set too
  EXPECT_EQ(m.surfaces.at("right").front().element, 1);
  EXPECT_EQ(m.surfaces.at("right").front().local, 1);
  EXPECT_EQ(m.node_sets.at("all").size(), 6u);
  // every element when no set is named
  EXPECT_EQ(inp_body_mesh(deck2d(), 2, "", "strip.inp").num_elements(), 3);
}

TEST(InpReader, UnsupportedOrBrokenInputIsRefusedWithWhereAndWhy) {
  const std::string nodes = "*NODE\n1,0,0,0\n2,1,0,0\n3,0,1,0\n4,0,0,1\n5,1,1,0\n";
  EXPECT_TRUE(has(refusal(nodes + "*ELEMENT, TYPE=C3D4\n1, 1,2,3,4\n", 3), "element 1 is a C3D4: tetrahedra are not"));
  EXPECT_TRUE(has(refusal(nodes + "*ELEMENT, TYPE=CPE3\n1, 1,2,3\n"), "triangles are not supported"));
  EXPECT_TRUE(has(refusal(nodes + "*ELEMENT, TYPE=C3D8\n1, 1,2,5,3,1,2,5,3\n", 2), "a 3D element in a 2D model"));
  EXPECT_TRUE(has(refusal("*NODE\n1, 0, zero\n"), "deck.inp:2: 'zero' is not a finite number"));
  EXPECT_TRUE(has(refusal("*NODE\n1, 0, 0\n1, 1, 0\n"), "deck.inp:3: node 1 is defined twice"));
  EXPECT_TRUE(has(refusal(nodes + "*ELEMENT, TYPE=CPE4\n1, 1,2,5,9\n"), "names node 9, which the deck does not"));
  EXPECT_TRUE(has(refusal(nodes + "*ELEMENT, TYPE=CPE4\n1, 1,2,5,\n*NSET, NSET=A\n1\n"), "node list ends early"));
  EXPECT_TRUE(has(refusal(nodes + "*ELEMENT, TYPE=CPE4\n1, 1,2,5,3\n", 3), "a 2D element in a 3D model"));
  EXPECT_TRUE(has(refusal(nodes + "*ELEMENT, TYPE=CPE4, ELSET=A\n1, 1,2,5,3\n", 2, "B"),
                  "no element set named 'B' (the deck has: A)"));
  EXPECT_TRUE(has(refusal(nodes + "*ELEMENT, TYPE=CPE4\n7, 1,3,5,2\n"), "element 7 is inverted or degenerate"));
  EXPECT_TRUE(
      has(refusal("*NODE\n1,0,0,1\n2,1,0,1\n3,1,1,1\n4,0,1,1\n*ELEMENT, TYPE=CPE4\n1,1,2,3,4\n"), "node 1 has z = 1"));
  EXPECT_TRUE(has(refusal("*NSET, NSET=A\nB\n"), "deck.inp:2: no set named 'B' defined before this line"));
  EXPECT_TRUE(has(refusal("*SURFACE, NAME=S, TYPE=NODE\n1\n"), "only element-face surfaces"));
  EXPECT_TRUE(
      has(refusal(nodes + "*ELEMENT, TYPE=CPE4\n1, 1,2,5,3\n*SURFACE, NAME=S\n1, S5\n"), "element 1 has no face S5"));
}

TEST(InpReader, IncludedFilesAreReadRelativeToTheDeck) {
  const std::filesystem::path dir = fresh_dir("inp-include");
  std::ofstream(dir / "nodes.inp") << "*NODE\n1,0,0\n2,1,0\n3,1,1\n4,0,1\n";
  std::ofstream(dir / "main.inp") << "*INCLUDE, INPUT=nodes.inp\n*ELEMENT, TYPE=CPE4, ELSET=ONE\n1, 1,2,3,4\n";
  const std::shared_ptr<const Mesh> m = import_mesh(dir / "main.inp", 2, "one");
  EXPECT_EQ(m->num_nodes(), 4);
  EXPECT_EQ(m.get(), import_mesh(dir / "main.inp", 2, "one").get()) << "an unchanged file is read once";
  EXPECT_THROW(import_mesh(dir / "main.msh", 2, ""), MeshImportError);
  try {
    import_mesh(dir / "missing.inp", 2, "");
    FAIL();
  } catch (const MeshImportError& e) {
    EXPECT_TRUE(has(e.what(), "missing.inp: cannot be read")) << e.what();
  }
}

}  // namespace test_inp_reader
