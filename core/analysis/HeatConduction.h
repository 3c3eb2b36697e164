#pragma once
// Transient heat conduction in the bodies that conduct (materials with a conductivity and a heat capacity), staggered
// with the Newton analysis: after each converged mechanical step, one backward-Euler step of the heat equation over
// every conducting body at once,
//   (C + Δt (K + H_air + H_contact)) T = C T_n + Δt H_air T_air + Q,
// on the step's end configuration: K = ∫ k ∇N·∇N dv in the current positions, C the lumped capacity ∫ ρc N dV (in the
// reference volume: the mass is conserved), H_air the air's convection and radiation on the bodies' cooled surfaces
// (radiation linearised at T_n: ε σ (T_n² + T_air²)(T_n + T_air) in kelvin; row-sum lumped, so a thermal shock gives
// no undershoot), H_contact the conductance h_c between each touching slave node and its master point (one system:
// the bodies exchange heat implicitly), and Q the step's heat — plastic work (each point's adiabatic rise of the
// step, β ∫ τ_y dα / ρc, times ρc and its volume, spread onto its element's nodes) and friction work (a slipping
// point's friction force times its slip, shared between the bodies by the pair's friction_heat_to_slave). The new
// nodal temperatures then set every point's temperature (Σ N_a T_a), which the flow stress of the next step reads.
// A material's thermal_table gives k(T) and ρc(T), read at the step's start temperatures T_n (semi-implicit, no
// Picard iteration): k at each element's mean nodal temperature, ρc at each node's (C rebuilt each step); a
// temperature beyond the table holds its end value and is reported by warnings().
// One CHOLMOD factorization per step; its symbolic analysis is kept while the pattern (the contact links) stays.
#include <Eigen/Dense>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "base/SparseMatrix.h"
#include "contact/ContactConstraints.h"
#include "model/Model.h"
#include "solve/Factorization.h"

namespace rollsim {

/// Stefan–Boltzmann's constant with mm, N, s and K: 5.670374e-8 W/(m² K⁴) = 5.670374e-11 N/(mm s K⁴).
constexpr double kStefanBoltzmann = 5.670374419e-11;
constexpr double kKelvin = 273.15;  // 0 °C in kelvin

/// What one heat step takes from the mechanical step that converged before it.
struct HeatStepInput {
  double dt = 0;                                                  // the step's time [s]
  const std::vector<Eigen::VectorXd>* displacement = nullptr;     // every dof of every body at the step's end
  const std::vector<PairState>* pairs = nullptr;                  // the contact state at the step's end
  const std::vector<std::vector<double>>* slid_before = nullptr;  // per pair and point: PairState::slid at its start
};

class HeatConduction {
 public:
  explicit HeatConduction(const Model& model);
  /// One backward-Euler step. `states`: per body, its points' committed state (element-major, as
  /// GroupAssembler::committed_state gives it; empty for a body without state) — in, after the mechanical step (the
  /// points' temperature rises include the step's adiabatic heating: the step's plastic heat); out, every conducting
  /// point's rise set to its temperature from the nodes. Throws AnalysisError when a temperature is not finite.
  void step(const HeatStepInput& in, std::vector<std::vector<double>>& states);
  /// Nodal temperatures of body b [°C] (empty: it does not conduct).
  const Eigen::VectorXd& temperature(int b) const { return T_[static_cast<size_t>(b)]; }
  /// One line per body whose nodal temperatures left its material's thermal_table (its properties held there).
  std::vector<std::string> warnings() const;
  double seconds() const { return seconds_; }
  int factorizations() const { return factorizations_; }

 private:
  struct BodyHeat {
    int offset = -1;             // its first row in the system (-1: it does not conduct)
    Eigen::VectorXd share;       // ∫ N dV per node, in the reference volume
    Eigen::VectorXd capacity;    // lumped ρc ∫ N dV per node [energy / K] (a thermal_table's ρc: at T_n, each step)
    std::vector<double> volume;  // per element and Gauss point: its reference volume
    int stride = 0, rise = -1;   // the material's state size and where its temperature rise sits (-1: none)
    std::vector<double> written;  // per point: the rise this step wrote last (the next step's heat is the change)
    // with a thermal_table: the lowest and highest nodal temperature of any step's start or end [°C]
    double lowest = std::numeric_limits<double>::infinity(), highest = -std::numeric_limits<double>::infinity();
  };
  /// With a thermal_table: the capacity at the step's start temperatures, and the range they reached.
  void update_table(size_t b);
  void add_conduction(size_t b, const Eigen::VectorXd& u, double dt, std::vector<Eigen::Triplet<double>>& t) const;
  /// The contact links, the friction heat and which nodes touch (and so exchange no heat with the air).
  void add_contacts(const HeatStepInput& in, std::vector<Eigen::Triplet<double>>& t, Eigen::VectorXd& rhs,
                    std::vector<std::vector<char>>& touching);
  void add_air(const HeatStepInput& in, const std::vector<std::vector<char>>& touching, Eigen::VectorXd& diagonal,
               Eigen::VectorXd& rhs);
  void add_plastic_heat(size_t b, const std::vector<double>& state, Eigen::VectorXd& rhs);
  void write_points(size_t b, std::vector<double>& state);
  Eigen::VectorXd solve(const SparseMatrix& A, const Eigen::VectorXd& rhs);

  const Model& model_;
  std::vector<BodyHeat> bodies_;
  std::vector<Eigen::VectorXd> T_;
  long rows_ = 0;
  std::unique_ptr<Factorization> factor_;
  SparseMatrix pattern_;  // the last analysed pattern
  double seconds_ = 0;
  int factorizations_ = 0;
};

}  // namespace rollsim
