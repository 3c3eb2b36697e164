#include <cmath>

#include "base/SchemaFields.h"
#include "material/FlowStressLaws.h"

namespace rollsim {

namespace {
using namespace schema;

const ObjectSchema& hensel_spittel_schema() {
  static const ObjectSchema s{
      "Hensel–Spittel flow stress",
      "Hensel and Spittel's law in the Freiberg form QForm and FORGE take coefficients in: σ_f = A e^(m1 T) T^m9 "
      "ε^m2 e^(m4/ε) (1 + ε)^(m5 T + m6) e^(m7 ε) ε̇^(m3 + m8 T), T in °C (the coefficients of a steel come from "
      "compression or torsion tests at its temperatures and rates; Spittel & Spittel 2009 tabulate many). m6 = 0 "
      "gives the form without it.",
      [] {
        std::vector<Field> f{
            req(positive("A", "stress", "the law's scale A")),
            def(num("m1", "1/°C", "temperature exponent m1 (e^(m1 T))"), 0.0),
            def(num("m2", "-", "strain exponent m2 (ε^m2)"), 0.0),
            def(num("m3", "-", "strain-rate exponent m3 (ε̇^m3)"), 0.0),
            def(num("m4", "-", "softening term m4 (e^(m4/ε))"), 0.0),
            def(num("m5", "1/°C", "m5 of (1 + ε)^(m5 T + m6)"), 0.0),
            def(num("m6", "-", "m6 of (1 + ε)^(m5 T + m6)"), 0.0),
            def(num("m7", "-", "m7 of e^(m7 ε)"), 0.0),
            def(num("m8", "1/°C", "temperature term of the rate exponent (ε̇^(m8 T))"), 0.0),
            def(num("m9", "-", "T^m9 (T in °C: above 0 where m9 ≠ 0)"), 0.0),
            strain_offset_field(0.01),
            rate_offset_field(0.01),
            num("min_temperature", "°C", "lowest temperature of the coefficients' fit (a warning below)"),
            num("max_temperature", "°C", "highest temperature of the fit (a warning above)")};
        return f;
      }(),
      "",
      {}};
  return s;
}

class HenselSpittel final : public FlowStress {
 public:
  explicit HenselSpittel(const FlowStressData& d)
      : FlowStress(get(d, "strain_offset"), get(d, "rate_offset")), A_(get(d, "A")) {
    for (int i = 0; i < 9; ++i) m_[i] = get(d, "m" + std::to_string(i + 1));
  }
  bool rate_dependent() const override { return m_[2] != 0 || m_[7] != 0; }

 private:
  static double get(const FlowStressData& d, const std::string& name) {
    return coefficient(d, hensel_spittel_schema(), name);
  }
  FlowStressPoint formula(double e, double rate, double T) const override {
    const double m1 = m_[0], m2 = m_[1], m3 = m_[2], m4 = m_[3], m5 = m_[4], m6 = m_[5], m7 = m_[6], m8 = m_[7],
                 m9 = m_[8];
    const double rate_exponent = m3 + m8 * T, strain_power = m5 * T + m6;
    const double s = A_ * std::exp(m1 * T) * (m9 != 0 ? std::pow(T, m9) : 1.0) * std::pow(e, m2) * std::exp(m4 / e) *
                     std::pow(1 + e, strain_power) * std::exp(m7 * e) * std::pow(rate, rate_exponent);
    return {s, s * (m2 / e - m4 / (e * e) + strain_power / (1 + e) + m7), s * rate_exponent / rate};
  }
  double A_, m_[9];
};

std::vector<Issue> check(const FlowStressData& d) {
  std::vector<Issue> issues;
  const auto min = d.coefficients.find("min_temperature"), max = d.coefficients.find("max_temperature");
  if (min != d.coefficients.end() && max != d.coefficients.end() && !(min->second < max->second))
    issues.push_back({"max_temperature", "must be above min_temperature"});
  return issues;
}

std::pair<double, double> temperatures(const FlowStressData& d) {
  const auto min = d.coefficients.find("min_temperature"), max = d.coefficients.find("max_temperature");
  return {min != d.coefficients.end() ? min->second : -HUGE_VAL, max != d.coefficients.end() ? max->second : HUGE_VAL};
}
}  // namespace

const FlowStressLaw& hensel_spittel_law() {
  static const FlowStressLaw law{
      "hensel_spittel", &hensel_spittel_schema(), check, temperatures,
      [](const FlowStressData& d) -> std::unique_ptr<FlowStress> { return std::make_unique<HenselSpittel>(d); }};
  return law;
}

}  // namespace rollsim
