#include <algorithm>
#include <cmath>

#include "base/SchemaFields.h"
#include "material/FlowStressLaws.h"

namespace rollsim {

namespace {
using namespace schema;

constexpr double kMPaPerKgfmm2 = 9.80665;
constexpr double kMinCarbon = 0.07, kMaxCarbon = 1.2;  // [wt %] the steels Shida fitted
constexpr double kMinT = 700, kMaxT = 1200;            // [°C]

const ObjectSchema& shida_schema() {
  static const ObjectSchema s{
      "Shida flow stress",
      "Shida's formula (1969) for carbon steels, from the carbon content alone, in the form rolling texts quote: with "
      "T = (t + 273)/1000 and T_d = 0.95 (C + 0.41)/(C + 0.32), σ_f = σ_T f(ε) (ε̇/10)^m [kgf/mm², given here in "
      "MPa], f(ε) = 1.3 (ε/0.2)^n − 0.3 (ε/0.2), n = 0.41 − 0.07 C; above T_d (austenite) σ_T = 0.28 "
      "exp(5/T − 0.01/(C + 0.05)), m = (−0.019 C + 0.126) T + 0.075 C − 0.05; below it σ_T = 0.28 g exp(5/T_d − "
      "0.01/(C + 0.05)), g = 30 (C + 0.9)(T − 0.95 (C + 0.49)/(C + 0.42))² + (C + 0.06)/(C + 0.09), m = (0.081 C − "
      "0.154) T − 0.019 C + 0.207 + 0.027/(C + 0.32). Fitted for 0.07–1.2 % C, 700–1200 °C, ε ≤ 0.7, ε̇ 0.1–100 "
      "/s: a temperature outside is warned of. f(ε) is held at its peak beyond it, ε = 0.2 (1.3 n / 0.3)^(1/(1 − n)) "
      "(0.489 for 0.2 % C): the formula would fall to zero at ε ≈ 2.3, where a rolled surface's shear takes it. The "
      "project's stresses must be in MPa.",
      {req(bounded(num("carbon", "wt %", "carbon content C (0.07–1.2)"), kMinCarbon, kMaxCarbon)),
       strain_offset_field(0.01), rate_offset_field(0.01)},
      "",
      {}};
  return s;
}

class Shida final : public FlowStress {
 public:
  explicit Shida(const FlowStressData& d)
      : FlowStress(coefficient(d, shida_schema(), "strain_offset"), coefficient(d, shida_schema(), "rate_offset")),
        C_(coefficient(d, shida_schema(), "carbon")) {}
  bool rate_dependent() const override { return true; }

 private:
  FlowStressPoint formula(double e, double rate, double t) const override {
    const double C = C_, T = (t + 273) / 1000, Td = 0.95 * (C + 0.41) / (C + 0.32);
    double sT, m;
    if (T >= Td) {
      sT = 0.28 * std::exp(5 / T - 0.01 / (C + 0.05));
      m = (-0.019 * C + 0.126) * T + (0.075 * C - 0.05);
    } else {
      const double d = T - 0.95 * (C + 0.49) / (C + 0.42);
      const double g = 30 * (C + 0.9) * d * d + (C + 0.06) / (C + 0.09);
      sT = 0.28 * g * std::exp(5 / Td - 0.01 / (C + 0.05));
      m = (0.081 * C - 0.154) * T + (-0.019 * C + 0.207) + 0.027 / (C + 0.32);
    }
    // f(ε) peaks at x* = (1.3 n / 0.3)^(1/(1−n)) (ε ≈ 0.49 for 0.2 % C) and would fall to 0 at ε ≈ 2.3: beyond its
    // peak it is held there (steady-state flow, as dynamic recrystallisation keeps hot steel), never negative
    const double n = 0.41 - 0.07 * C, peak = std::pow(1.3 * n / 0.3, 1 / (1 - n));
    const double x = std::min(e / 0.2, peak), xn = std::pow(x, n);
    const double scale = kMPaPerKgfmm2 * sT * std::pow(rate / 10, m);
    const double s = scale * (1.3 * xn - 0.3 * x);
    return {s, e / 0.2 < peak ? scale * (1.3 * n * xn / x - 0.3) / 0.2 : 0.0, s * m / rate};
  }
  double C_;
};

std::vector<Issue> check(const FlowStressData&) { return {}; }
std::pair<double, double> temperatures(const FlowStressData&) { return {kMinT, kMaxT}; }
}  // namespace

const FlowStressLaw& shida_law() {
  static const FlowStressLaw law{
      "shida", &shida_schema(), check, temperatures,
      [](const FlowStressData& d) -> std::unique_ptr<FlowStress> { return std::make_unique<Shida>(d); }};
  return law;
}

}  // namespace rollsim
