#pragma once
// The model: bodies (mesh + material + element formulation), boundary conditions, loads, probes.
// Built from a validated Project; read by the analysis; never changed by a solver.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "mesh/Mesh.h"
#include "model/BodyPartition.h"
#include "model/MaterialData.h"

namespace rollsim {

struct Body {
  std::string name;
  Mesh mesh;
  MaterialData material;      // its parameters (material/ makes the behaviour from them)
  std::string material_name;  // the project's name of that material
  Formulation formulation = Formulation::Full;
  Kinematics kinematics = Kinematics::Small;
  Partition partition;  // subdomains for `feti` (one subdomain: undivided)
  // the state it starts from, when not virgin (a schedule's next pass: what the slab brings from the pass before) —
  // the equivalent plastic strain of each element's points [-] and each node's temperature [°C]; empty: none, and the
  // material's temperature
  std::vector<double> initial_plastic_strain;  // per element
  std::vector<double> initial_temperature;     // per node
  // every integration point's whole state (element-major, the material's state_size() each: a remeshed run's next
  // segment, analysis/Remeshing) — when given, it replaces initial_plastic_strain and the rises of
  // initial_temperature in the points' state
  std::vector<double> initial_state;
};

/// A rigid rotation by `angle` [radian, at load factor 1] about the axis through `center` along the unit vector
/// `axis` (right-hand rule; 2D: the z axis). Applied in increments: at load factor λ the angle is λ · angle.
struct RigidRotation {
  std::array<double, 3> center{0.0, 0.0, 0.0};
  std::array<double, 3> axis{0.0, 0.0, 1.0};
  double angle = 0.0;
};

/// Prescribed displacement per component (unset components stay free) on a node set; with a rotation, every
/// component of every node is prescribed: u(λ) = (R(λ θ) − I)(X − c) + λ value (unset components of value: 0).
struct DisplacementBC {
  int body = 0;
  std::string set;
  std::vector<int> nodes;
  std::array<std::optional<double>, 3> value;
  int source = -1;  // its index in the project's boundary_conditions (for messages)
  std::optional<RigidRotation> rotation;
};

/// Force applied at every node of a set [force].
struct NodalForce {
  int body = 0;
  std::string set;
  std::vector<int> nodes;
  std::array<double, 3> value{0.0, 0.0, 0.0};
};

/// Uniform pressure on a surface [force / length^2], positive pushing into the body: on the undeformed surface (a
/// dead load), or, `follower`, normal to the deformed surface and per unit of its current area.
struct Pressure {
  int body = 0;
  std::string surface;
  double value = 0.0;
  bool follower = false;
};

/// Uniform traction on a surface [force / length^2]: a vector per unit area of the undeformed surface (a dead load:
/// it neither turns nor grows with the surface), in 2D per unit length and unit thickness.
struct Traction {
  int body = 0;
  std::string surface;
  std::array<double, 3> value{0.0, 0.0, 0.0};
};

/// Uniform body force [force / length^3] per unit undeformed volume (weight: density × g), in 2D per unit thickness.
struct BodyForce {
  int body = 0;
  std::array<double, 3> value{0.0, 0.0, 0.0};
};

struct Probe {
  std::string name;
  std::array<double, 3> at{};
  int body = 0;
  int node = 0;
};

/// Contact between a slave surface (carries the multipliers, paper: the base) and a master surface.
/// tied: the slave nodes stick to the master surface in every component (the paper's "infinite friction");
/// frictionless: normal, unilateral, with an active set (the contact zone is an unknown). Small sliding:
/// each slave node keeps the master facet and the normal found in the undeformed configuration; large sliding
/// (the Newton analysis): the projection is searched again in the configuration where each step begins (Step), or
/// in the current configuration at every Newton iteration (Iteration).
/// sticking: unilateral, and an active point keeps its master point (no slip: the paper's condition on the roll);
/// coulomb: unilateral, an active point sticks while its tangential force is within μ times its normal force and
/// slips with exactly μ times it otherwise. Either may cap the friction stress at `shear_limit` (Tresca): a point then
/// slips once its tangential force passes shear_limit × its tributary measure.
enum class ContactKind { Tied, Frictionless, Sticking, Coulomb };

struct ContactPair {
  std::string name;
  ContactKind kind = ContactKind::Tied;
  int slave_body = 0, master_body = 0;
  std::string slave_surface, master_surface;
  double search_distance = 0;  // slave nodes farther than this from the master surface are ignored [length]
  enum class Sliding { Small, Step, Iteration } sliding = Sliding::Small;
  double friction = 0;     // Coulomb's μ [-]
  double shear_limit = 0;  // sticking and coulomb: cap on the friction stress (0: none) [force / length^(dim−1)]
  // a slipping point's elastic slip δ as a fraction of its facet size (contact/Friction.h: the direction of its
  // friction force is that of its trial force) [-]
  double slip_tolerance = 0.005;
  // the slave body has rigid modes its conditions leave free: this pair holds it, and friction keeps at least one of
  // its active points sticking (all slipping would leave the body free; see contact/Friction.h)
  bool holds_slave = false;
  // the search projects a slave node only on master facets whose bounding box is within search_distance
  // (analysis.contact_search: boxes); false: on every facet (all)
  bool box_search = true;
  // heat across the pair where its points touch, h_c (T_master − T_slave) per unit area [kW/(m² K) = N/(mm s K)]
  // (0: none); and the share of the friction work, μ N × slip, that heats the slave (the rest heats the master)
  double conductance = 0;
  double friction_heat_to_slave = 0.5;
  // the master surface's material turns by this rotation over the analysis while its mesh stays in place (an Eulerian
  // roll: its elastic field is steady in space, so its mesh need not turn): a point sticks to the turning material,
  // and slips against it (contact/ContactConstraints.h turn_master_surfaces)
  std::optional<RigidRotation> master_turns;
};

/// Heat a body's surface gives to the air around it: convection h (T − T_air) and radiation ε σ (T⁴ − T_air⁴) per
/// unit area [kW/(m² K) = N/(mm s K) with mm, N and s; ε: -]. Its points in contact exchange with the other body
/// instead.
struct AirCooling {
  int body = 0;
  std::string surface;
  double convection = 0;
  double emissivity = 0;
};

/// What heat leaves the bodies that conduct (materials with a conductivity): to the air at `ambient` [°C].
struct HeatExchange {
  double ambient = 20;
  std::vector<AirCooling> air;
};

struct Model {
  int dim = 2;
  std::vector<Body> bodies;
  std::vector<DisplacementBC> displacements;
  std::vector<NodalForce> forces;
  std::vector<Pressure> pressures;
  std::vector<Traction> tractions;
  std::vector<BodyForce> body_forces;
  std::vector<Probe> probes;
  std::vector<ContactPair> contacts;
  HeatExchange heat;
  std::vector<std::string> warnings;  // said to the user, e.g. a partition piece split automatically

  long total_nodes() const;
  /// True when a body conducts heat (its material has a conductivity and a heat capacity).
  bool conducts_heat() const;
  long total_elements() const;
};

}  // namespace rollsim
