#include "bench/Verdict.h"

#include <cmath>
#include <cstdio>
#include <map>

namespace rollsim::bench {

namespace {

std::string sci(double v) {
  char s[32];
  std::snprintf(s, sizeof s, "%.1e", v);
  return s;
}

void judge_one(CaseResult& r) {
  const std::string& st = r.o.status;
  if (st == "timeout") {  // slower than the suite allows: a limit of the suite, said as such
    r.verdict = Verdict::failed, r.words = "timeout: " + r.o.message + " — slower than the suite's limit";
    return;
  }
  if (st == "crashed" || st == "non_finite") {
    r.verdict = Verdict::broken, r.words = st + ": " + r.o.message;
    return;
  }
  if (st != "converged") {
    r.verdict = r.o.message.empty() ? Verdict::broken : Verdict::failed;
    r.words = st + ": " + (r.o.message.empty() ? "no reason given" : r.o.message);
    return;
  }
  if (r.c.reference_only) {
    r.verdict = Verdict::ok, r.words = "reference";
    return;
  }
  if (!std::isfinite(r.error)) {
    r.verdict = Verdict::failed, r.words = "no reference to compare with (" + r.c.reference_case + " did not converge)";
    return;
  }
  if (r.error <= r.c.bound) {
    r.verdict = Verdict::ok, r.words = std::isfinite(r.c.bound) ? "within " + sci(r.c.bound) : "measured";
    return;
  }
  r.verdict = Verdict::wrong;
  r.words = "error " + sci(r.error) + " above the bound " + sci(r.c.bound) +
            (r.c.if_wrong.empty() ? std::string() : ": " + r.c.if_wrong);
}

}  // namespace

const char* to_string(Verdict v) {
  switch (v) {
    case Verdict::ok:
      return "ok";
    case Verdict::wrong:
      return "wrong";
    case Verdict::failed:
      return "failed";
    default:
      return "broken";
  }
}

std::vector<CaseResult> judge(const std::vector<SuiteCase>& cases, const std::vector<CaseOutcome>& outcomes) {
  std::map<std::string, const CaseOutcome*> by_name;
  for (size_t i = 0; i < cases.size(); ++i) by_name[cases[i].name()] = &outcomes[i];
  std::vector<CaseResult> out;
  for (size_t i = 0; i < cases.size(); ++i) {
    CaseResult r;
    r.c = cases[i], r.o = outcomes[i];
    if (std::isfinite(r.o.exact)) {
      r.reference = r.o.exact;
    } else if (auto it = by_name.find(r.c.reference_case); it != by_name.end() && it->second->status == "converged") {
      r.reference = it->second->value;
    }
    if (std::isfinite(r.reference) && std::isfinite(r.o.value) && r.reference != 0)
      r.error = std::abs(r.o.value - r.reference) / std::abs(r.reference);
    judge_one(r);
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace rollsim::bench
