#include <algorithm>
#include <cmath>

#include "base/SchemaFields.h"
#include "material/FlowStressLaws.h"

namespace rollsim {

namespace {
using namespace schema;

const ObjectSchema& johnson_cook_schema() {
  static const ObjectSchema s{
      "Johnson–Cook flow stress",
      "Johnson and Cook's law (1983): σ_f = (A + B ε^n)(1 + C ln(ε̇/ε̇_0))(1 − T*^m), T* = (T − T_r)/(T_m − T_r) "
      "between 0 and 1. The rate enters as ε̇ + ε̇_0 (rate_offset defaults to the reference rate): 1 + C ln(1 + "
      "ε̇/ε̇_0), the smooth form that never lowers the stress below the quasi-static one. Rate-independent when C = 0; "
      "temperature-independent when m = 0.",
      {req(positive("A", "stress", "yield stress A at the reference rate and temperature")),
       def(non_negative("B", "stress", "hardening modulus B"), 0.0),
       def(positive("n", "-", "hardening exponent n"), 1.0),
       def(non_negative("C", "-", "strain-rate sensitivity C"), 0.0),
       def(positive("reference_rate", "1/s", "reference strain rate ε̇_0"), 1.0),
       def(non_negative("m", "-", "thermal softening exponent m (0: no temperature dependence)"), 0.0),
       def(num("reference_temperature", "°C", "reference (room) temperature T_r"), 20.0),
       def(num("melting_temperature", "°C", "melting temperature T_m"), 1500.0), strain_offset_field(1e-6),
       num("rate_offset", "1/s", "ε̇_0 added to the strain rate before the formula (default: reference_rate)")},
      "",
      {}};
  return s;
}

double get(const FlowStressData& d, const std::string& name) { return coefficient(d, johnson_cook_schema(), name); }

class JohnsonCook final : public FlowStress {
 public:
  explicit JohnsonCook(const FlowStressData& d)
      : FlowStress(get(d, "strain_offset"),
                   d.coefficients.count("rate_offset") ? d.coefficients.at("rate_offset") : get(d, "reference_rate")),
        A_(get(d, "A")),
        B_(get(d, "B")),
        n_(get(d, "n")),
        C_(get(d, "C")),
        rate0_(get(d, "reference_rate")),
        m_(get(d, "m")),
        Tr_(get(d, "reference_temperature")),
        Tm_(get(d, "melting_temperature")) {}
  bool rate_dependent() const override { return C_ != 0; }

 private:
  FlowStressPoint formula(double e, double rate, double T) const override {
    const double hardening = A_ + B_ * std::pow(e, n_), rate_factor = 1 + C_ * std::log(rate / rate0_);
    const double homologous = std::clamp((T - Tr_) / (Tm_ - Tr_), 0.0, 1.0);
    const double thermal = m_ > 0 ? 1 - std::pow(homologous, m_) : 1.0;
    return {hardening * rate_factor * thermal, B_ * n_ * std::pow(e, n_ - 1) * rate_factor * thermal,
            hardening * C_ / rate * thermal};
  }
  double A_, B_, n_, C_, rate0_, m_, Tr_, Tm_;
};

std::vector<Issue> check(const FlowStressData& d) {
  if (get(d, "melting_temperature") > get(d, "reference_temperature")) return {};
  return {{"melting_temperature", "must be above reference_temperature"}};
}

std::pair<double, double> temperatures(const FlowStressData& d) { return {-273.15, get(d, "melting_temperature")}; }
}  // namespace

const FlowStressLaw& johnson_cook_law() {
  static const FlowStressLaw law{
      "johnson_cook", &johnson_cook_schema(), check, temperatures,
      [](const FlowStressData& d) -> std::unique_ptr<FlowStress> { return std::make_unique<JohnsonCook>(d); }};
  return law;
}

}  // namespace rollsim
