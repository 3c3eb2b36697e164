#include <algorithm>
#include <cmath>

#include "base/SchemaFields.h"
#include "material/FlowStressLaws.h"

namespace rollsim {

namespace {
/// σ_0 + H ε + (σ_∞ − σ_0)(1 − exp(−δ ε)): linear hardening with a saturating exponential term (Voce) when σ_∞ > σ_0.
class SaturationHardening final : public FlowStress {
 public:
  explicit SaturationHardening(const MaterialData& d)
      : FlowStress(0, 0),
        s0_(d.yield_stress),
        H_(d.hardening_modulus),
        rise_(std::max(0.0, d.saturation_stress - d.yield_stress)),
        delta_(d.saturation_exponent) {}
  bool rate_dependent() const override { return false; }

 private:
  FlowStressPoint formula(double e, double, double) const override {
    const double decay = rise_ > 0 ? std::exp(-delta_ * e) : 1.0;
    return {s0_ + H_ * e + rise_ * (1.0 - decay), H_ + rise_ * delta_ * decay, 0.0};
  }
  double s0_, H_, rise_, delta_;
};
}  // namespace

std::unique_ptr<FlowStress> make_saturation_hardening(const MaterialData& data) {
  return std::make_unique<SaturationHardening>(data);
}

Field strain_offset_field(double d) {
  return schema::def(
      schema::non_negative("strain_offset", "-", "ε_0 added to the equivalent plastic strain before the formula"), d);
}

Field rate_offset_field(double d) {
  return schema::def(schema::non_negative("rate_offset", "1/s", "ε̇_0 added to the strain rate before the formula"), d);
}

}  // namespace rollsim
