#include "bench/Suites.h"

#include <stdexcept>

#include "bench/AccuracySuite.h"
#include "bench/IsolatedRun.h"
#include "bench/StabilitySuite.h"

namespace rollsim::bench {

const std::vector<std::string>& suite_names() {
  static const std::vector<std::string> names = {"accuracy", "stability"};
  return names;
}

SuiteSize suite_size(const std::string& name) {
  if (name == "tiny") return SuiteSize::tiny;
  if (name == "quick") return SuiteSize::quick;
  if (name == "full") return SuiteSize::full;
  throw std::invalid_argument("suite size must be one of tiny, quick, full, got \"" + name + "\"");
}

std::vector<SuiteCase> suite_cases(const std::string& name, SuiteSize size, const std::string& family) {
  std::vector<SuiteCase> all;
  if (name == "accuracy")
    all = accuracy_cases(size);
  else if (name == "stability")
    all = stability_cases(size);
  else
    throw std::invalid_argument("unknown suite \"" + name + "\" (accuracy, stability)");
  if (family.empty()) return all;
  std::vector<SuiteCase> some;
  std::string known;
  for (const SuiteCase& c : all) {
    if (c.family == family) some.push_back(c);
    if (known.find(" " + c.family + ",") == std::string::npos) known += " " + c.family + ",";
  }
  if (some.empty()) throw std::invalid_argument("suite " + name + " has no family \"" + family + "\" (" + known + ")");
  return some;
}

std::vector<CaseResult> run_suite(const std::vector<SuiteCase>& cases, double timeout_s,
                                  const std::function<void(size_t, const SuiteCase&, const CaseOutcome&)>& progress) {
  std::vector<CaseOutcome> outcomes;
  for (const SuiteCase& c : cases) {
    outcomes.push_back(run_case_isolated(c, timeout_s));
    if (progress) progress(outcomes.size(), c, outcomes.back());
  }
  return judge(cases, outcomes);
}

}  // namespace rollsim::bench
