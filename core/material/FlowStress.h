#pragma once
// A flow stress law σ_f(ε, ε̇, T): the yield stress of a J2 material as a function of its equivalent plastic strain
// ε, that strain's rate ε̇ and the temperature T — the hardening of cold forming, the rate and temperature
// dependence of hot forming. One small interface; the laws (material/FlowStressLaws) are chosen by name from a
// registry that also declares each one's coefficients to the project schema.
#include <memory>
#include <string>
#include <vector>

#include "base/Schema.h"
#include "model/MaterialData.h"

namespace rollsim {

/// σ_f [stress] and its partial derivatives ∂σ_f/∂ε [stress] and ∂σ_f/∂ε̇ [stress · s] at one (ε, ε̇, T).
struct FlowStressPoint {
  double stress = 0, d_strain = 0, d_rate = 0;
};

class FlowStress {
 public:
  virtual ~FlowStress() = default;
  /// σ_f at equivalent plastic strain ε [-], rate ε̇ [1/s] and temperature T [°C]: the law's formula at ε + ε_0,
  /// ε̇ + ε̇_0, its strain_offset and rate_offset (most hot-forming formulas vanish at ε = 0 or ε̇ = 0; a floor
  /// max(ε̇, ε̇_0) would put a kink in the tangent where the rate leaves it, and Newton stalls there).
  FlowStressPoint at(double strain, double rate, double temperature) const;
  /// Whether σ_f depends on ε̇ (a J2 return then needs the increment's time).
  virtual bool rate_dependent() const = 0;

 protected:
  FlowStress(double strain_offset, double rate_offset) : strain_offset_(strain_offset), rate_offset_(rate_offset) {}
  /// The law's formula and its derivatives at (ε, ε̇, T), the offsets already added.
  virtual FlowStressPoint formula(double strain, double rate, double temperature) const = 0;

 private:
  double strain_offset_, rate_offset_;
};

/// One law of the registry: its name (materials[].flow_stress.law), its coefficients' schema (the fields beside
/// `law`), what a project's values must also satisfy beyond their ranges, and how it is made.
struct FlowStressLaw {
  std::string name;
  const ObjectSchema* schema;
  /// Problems of a set of coefficients (paths below the flow_stress object, e.g. "carbon"), beyond the schema's.
  std::vector<Issue> (*check)(const FlowStressData&);
  /// The temperatures [°C] the law holds over, for these coefficients: a body outside them is warned of.
  std::pair<double, double> (*temperatures)(const FlowStressData&);
  std::unique_ptr<FlowStress> (*make)(const FlowStressData&);
};

/// Every registered law, by name.
const std::vector<FlowStressLaw>& flow_stress_laws();
/// The law named `name`, or null.
const FlowStressLaw* find_flow_stress_law(const std::string& name);
/// The flow stress of a plastic material: its law, or its own hardening (σ_0 + H ε + saturation, rate- and
/// temperature-independent) when it names none.
std::unique_ptr<FlowStress> make_flow_stress(const MaterialData& data);
/// Coefficient `name` of `data`: its value, or the default `schema` declares for it (a law made from code with some
/// coefficients left out); throws std::invalid_argument when it has neither.
double coefficient(const FlowStressData& data, const ObjectSchema& schema, const std::string& name);
/// The FlowStressData of a validated flow_stress object (its `law` and every number beside it).
FlowStressData flow_stress_data(const json& object);
/// Problems of a plastic material's flow stress law, at paths below the material ("flow_stress.carbon",
/// "temperature"): its coefficients, a positive flow stress at its temperature, and the time a rate-dependent law
/// needs (`duration` of the analysis, 0: none).
std::vector<Issue> check_flow_stress(const MaterialData& data, double duration);
/// "" or why the material's temperature lies outside the range its law holds over.
std::string temperature_warning(const MaterialData& data);
/// The schema of materials[].flow_stress: `law` selecting one registered law's coefficients.
const ObjectSchema& flow_stress_schema();

}  // namespace rollsim
