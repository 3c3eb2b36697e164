#pragma once
// A distorted 2D mesh's nodes moved back to a spread like its original mesh's, the elements and their connectivity
// unchanged (an r-adaptive remesh: every node set, surface and element keeps its numbers). On each stretch of the
// boundary between two features — corners the node sets or surfaces make (where the sets an edge belongs to change,
// or a node belongs to a set its boundary neighbours do not) or where the original boundary turns by more than 45° —
// the nodes are placed along the deformed boundary at the original arc-length fractions, so a graded spread stays
// graded and the boundary's shape stays; the features stay where they are. The inner nodes follow the boundary's
// motion since the original mesh by its harmonic extension (a discrete Laplace equation on the mesh's edges, each
// weighted by its inverse length so that an affine motion of a structured, graded mesh is reproduced: the "Laplacian
// mesh motion" of ALE codes), so they keep the original's spread where the motion is smooth — or, where that would
// shape an element worse (a corner the boundary has turned around, a sheared layer), by the harmonic extension of the
// boundary nodes' correction from where they are, or as a harmonic map of the boundary (each inner node the mean of
// its neighbours): the first of the three, in that order, whose worst element's sharpest corner is within 10 % of the
// widest (the harmonic map evens out a grading too).
#include <array>
#include <vector>

#include "mesh/Mesh.h"

namespace rollsim {

/// The new node positions of `original` (its node positions: where it started) whose nodes are now at `current`;
/// the boundary nodes `staying` are features too (a contact's touching nodes: moved along a chord of the surface they
/// could end up inside the other body). Quad meshes (2D) only; throws std::invalid_argument for another.
/// `faces`: node sets stuck to a tool (each on one line): free boundary nodes that have crossed a face's line fold
/// onto it — the face's corner node moves to where the free boundary crosses back over the line, so that the folded
/// material is face (the tool's from then on) and the grid's corner stays at the boundary's corner.
std::vector<std::array<double, 3>> even_nodes(const Mesh& original, const std::vector<std::array<double, 3>>& current,
                                              const std::vector<int>& staying = {},
                                              const std::vector<std::vector<int>>& faces = {});

}  // namespace rollsim
