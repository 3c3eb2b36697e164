#pragma once
// Where an ALE run (analysis/AleStep) puts the nodes of a body its material flows through, after each converged step,
// from a process (a rolling pass: its slab's window fixed around the roll gap) the analysis knows only through this
// interface.
#include <array>
#include <string>
#include <vector>

namespace rollsim {

class MeshMotion {
 public:
  using Positions = std::vector<std::array<double, 3>>;
  virtual ~MeshMotion() = default;
  /// The body whose mesh stays in place while its material flows through it.
  virtual int body() const = 0;
  /// Its nodes' new positions, from every body's current node positions after a converged step (`current[body()]`
  /// its own: its material's) and which of its nodes touch another body there (active contact points: a node put
  /// back on a touching surface stays on it). Throws AnalysisError when they cannot be placed.
  virtual Positions placed(const std::vector<Positions>& current, const std::vector<char>& touching) const = 0;
  /// Whether a point at `p` in the new mesh holds material that flowed in during the step, which the moving body's
  /// material at `current` (its nodes' positions after the step) does not cover: it starts virgin.
  virtual bool inflow(const std::array<double, 3>& p, const Positions& current) const = 0;
  /// The nodes of the face its material flows in through: the advected state is the virgin one there (an inflow
  /// boundary), so that what flows in washes the window's first elements (none: no such face).
  virtual std::vector<int> inflow_face() const { return {}; }
  /// What the motion is, for the run's progress line ("the slab's mesh held from x = -189 to 126 mm").
  virtual std::string describe() const = 0;
};

}  // namespace rollsim
