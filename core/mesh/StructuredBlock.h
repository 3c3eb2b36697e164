#pragma once
// Structured rectangle (Q4) / box (H8) generator.
#include <array>
#include <string>
#include <vector>

#include "mesh/Mesh.h"

namespace rollsim {

struct BlockSpec {
  int dim = 2;
  std::array<int, 3> n{1, 1, 1};              // elements along x, y, z
  std::array<double, 3> size{1.0, 1.0, 1.0};  // edge lengths
  std::array<double, 3> origin{0.0, 0.0, 0.0};
  // per axis, the size ratio of each element to its neighbour on the + side (> 1: elements shrink geometrically
  // toward the max face, < 1: toward the min face; 1: uniform)
  std::array<double, 3> grading{1.0, 1.0, 1.0};
  // the nodes' x coordinates, n[0] + 1 of them increasing (empty: from origin, size and grading). An ALE rolling
  // window's columns, fine over the arc and growing away from it (process/rolling's ale_grading).
  std::vector<double> x_planes;
};

/// Nodes are numbered along the shortest direction first (the paper's cantilever numbering),
/// elements likewise. Surfaces and node sets: xmin, xmax, ymin, ymax (, zmin, zmax); element set "all".
/// Grading moves the nodes along its axis only (the numbering and connectivity do not change); a grading of 1 gives
/// origin + size · i / n exactly. Throws std::invalid_argument naming the axis whose grading is not a positive
/// number, or when x_planes is given and does not hold n[0] + 1 increasing coordinates.
Mesh make_block(const BlockSpec& spec);

/// Largest / smallest element size a grading may produce: beyond it the smallest elements approach round-off.
constexpr double kMaxGradingSpread = 1e6;
/// Why a geometric grading (size ratio of neighbours) over n elements is refused, or "" when it is accepted.
std::string grading_problem(double grading, int n);

/// Fraction of the length from the min face of node i (0..n) of n elements whose sizes fall by `grading` from each
/// element to the next: size_i ∝ grading^−i, so (1 − q^i) / (1 − q^n) with q = 1 / grading; i / n for grading 1.
double graded_fraction(int i, int n, double grading);

}  // namespace rollsim
