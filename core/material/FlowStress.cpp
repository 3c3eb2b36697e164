#include "material/FlowStress.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "material/FlowStressLaws.h"

namespace rollsim {

FlowStressPoint FlowStress::at(double strain, double rate, double temperature) const {
  return formula(strain + strain_offset_, rate + rate_offset_, temperature);
}

const std::vector<FlowStressLaw>& flow_stress_laws() {
  static const std::vector<FlowStressLaw> laws{hensel_spittel_law(), shida_law(), johnson_cook_law()};
  return laws;
}

const FlowStressLaw* find_flow_stress_law(const std::string& name) {
  for (const FlowStressLaw& law : flow_stress_laws())
    if (law.name == name) return &law;
  return nullptr;
}

std::unique_ptr<FlowStress> make_flow_stress(const MaterialData& data) {
  if (data.flow_stress.law.empty()) return make_saturation_hardening(data);
  const FlowStressLaw* law = find_flow_stress_law(data.flow_stress.law);
  if (!law) throw std::invalid_argument("no flow stress law '" + data.flow_stress.law + "'");
  return law->make(data.flow_stress);
}

double coefficient(const FlowStressData& data, const ObjectSchema& schema, const std::string& name) {
  if (const auto it = data.coefficients.find(name); it != data.coefficients.end()) return it->second;
  for (const Field& f : schema.fields)
    if (f.name == name && f.default_value.is_number()) return f.default_value.get<double>();
  throw std::invalid_argument("flow stress law '" + data.law + "' needs its coefficient '" + name + "'");
}

FlowStressData flow_stress_data(const json& object) {
  FlowStressData d;
  d.law = object.at("law").get<std::string>();
  for (const auto& [key, value] : object.items())
    if (value.is_number()) d.coefficients[key] = value.get<double>();
  return d;
}

namespace {
std::string celsius(double t) {
  char s[32];
  std::snprintf(s, sizeof s, "%g °C", t);
  return s;
}
}  // namespace

std::vector<Issue> check_flow_stress(const MaterialData& data, double duration) {
  const FlowStressLaw* law = find_flow_stress_law(data.flow_stress.law);
  if (!law) return {{"flow_stress.law", "no flow stress law '" + data.flow_stress.law + "'"}};
  std::vector<Issue> issues;
  for (const Issue& i : law->check(data.flow_stress)) issues.push_back({"flow_stress." + i.path, i.message});
  if (!issues.empty()) return issues;
  const auto flow = law->make(data.flow_stress);
  const double s = flow->at(0, 0, data.temperature).stress;
  if (!(s > 0) || !std::isfinite(s))
    issues.push_back({"temperature", "the " + law->name + " law gives no positive flow stress at " +
                                         celsius(data.temperature) + " (" + std::to_string(s) + ")"});
  if (flow->rate_dependent() && !(duration > 0))
    issues.push_back({"flow_stress", "the " + law->name +
                                         " law depends on the strain rate, which needs time: give analysis.duration "
                                         "(a rolling pass: process.roll_speed)"});
  return issues;
}

std::string temperature_warning(const MaterialData& data) {
  const FlowStressLaw* law = find_flow_stress_law(data.flow_stress.law);
  if (!law) return "";
  const auto [lo, hi] = law->temperatures(data.flow_stress);
  if (data.temperature >= lo && data.temperature <= hi) return "";
  return celsius(data.temperature) + " is outside the range the " + law->name + " law holds over (" + celsius(lo) +
         " to " + celsius(hi) + "): its flow stress there is an extrapolation";
}

const ObjectSchema& flow_stress_schema() {
  static const ObjectSchema s = [] {
    ObjectSchema o{"flow stress",
                   "A flow stress law σ_f(ε, ε̇, T) of the equivalent plastic strain ε [-], its rate ε̇ [1/s] and the "
                   "temperature T [°C], selected by `law`: the yield stress of a J2-plastic material instead of "
                   "yield_stress and its hardening. The rate is the plastic strain increment over the increment's "
                   "time (analysis.duration, or a rolling pass's roll_speed); the temperature is the material's "
                   "`temperature`. A law's strain_offset and rate_offset are added to ε and ε̇ before its formula "
                   "(most hot-forming formulas vanish at zero strain or rate; an offset, unlike a floor, keeps the "
                   "tangent continuous for Newton): give the values the coefficients were fitted with. Stresses in the "
                   "project's unit (MPa for Shida's formula).",
                   {},
                   "law",
                   {}};
    for (const FlowStressLaw& law : flow_stress_laws()) o.variants[law.name] = law.schema;
    return o;
  }();
  return s;
}

}  // namespace rollsim
