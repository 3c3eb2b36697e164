#include "bench/SuiteReport.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

namespace rollsim::bench {

namespace {

constexpr double kErrorTie = 1e-2;

std::string num(double v, const char* f = "%.6g") {
  if (!std::isfinite(v)) return "";
  char s[48];
  std::snprintf(s, sizeof s, f, v);
  return s;
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char ch : s) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return q + "\"";
}

std::string md_cell(std::string s) {
  for (char& ch : s)
    if (ch == '|' || ch == '\n') ch = ch == '|' ? '/' : ' ';
  return s;
}

bool plotted(const CaseResult& r) {
  return !r.c.reference_only && r.o.status == "converged" && std::isfinite(r.error) && std::isfinite(r.o.wall_s);
}

std::string iterations(const CaseResult& r) {
  if (r.o.newton_iterations > 0) return std::to_string(r.o.newton_iterations) + " Newton";
  if (r.o.cg_iterations > 0) return std::to_string(r.o.cg_iterations) + " CG";
  return "-";
}

std::string tolerance(const CaseResult& r) { return r.c.cg_tolerance > 0 ? num(r.c.cg_tolerance, "%.0e") : "-"; }

}  // namespace

std::vector<bool> pareto_front(const std::vector<CaseResult>& results) {
  std::vector<bool> front(results.size(), false);
  for (size_t i = 0; i < results.size(); ++i) {
    if (!plotted(results[i])) continue;
    bool dominated = false;
    for (size_t j = 0; j < results.size() && !dominated; ++j) {
      if (j == i || !plotted(results[j]) || results[j].c.family != results[i].c.family) continue;
      const double ti = results[i].o.wall_s, tj = results[j].o.wall_s, ei = results[i].error, ej = results[j].error;
      // errors within 1 % of each other are a tie (the same mesh solved to a different CG tolerance)
      const bool no_worse = ej <= ei * (1 + kErrorTie), better = ej < ei * (1 - kErrorTie);
      dominated = (tj < ti && no_worse) || (tj <= ti && better);
    }
    front[i] = !dominated;
  }
  return front;
}

std::string suite_csv(const std::vector<CaseResult>& results, const std::vector<bool>& pareto) {
  std::ostringstream s;
  s << "suite,family,variant,mode,level,cg_tolerance,status,verdict,wall_s,peak_rss_mb,dofs,multipliers,"
       "subdomains,rigid_modes,cg_iterations,factorizations,newton_iterations,active_set_iterations,quantity,value,"
       "reference,"
       "reference_kind,error,solver_error,condition,bound,pareto,words\n";
  for (size_t i = 0; i < results.size(); ++i) {
    const CaseResult& r = results[i];
    const CaseOutcome& o = r.o;
    s << r.c.suite << ',' << r.c.family << ',' << csv_field(r.c.variant) << ',' << r.c.mode << ',' << num(r.c.level)
      << ',' << num(r.c.cg_tolerance) << ',' << o.status << ',' << to_string(r.verdict) << ',' << num(o.wall_s) << ','
      << num(o.peak_rss_mb) << ',' << o.dofs << ',' << o.multipliers << ',' << o.subdomains << ',' << o.rigid_modes
      << ',' << o.cg_iterations << ',' << o.factorizations << ',' << o.newton_iterations << ','
      << o.active_set_iterations << ',' << csv_field(r.c.quantity) << ',' << num(o.value, "%.10g") << ','
      << num(r.reference, "%.10g") << ',' << csv_field(r.c.reference_kind) << ',' << num(r.error, "%.3e") << ','
      << num(o.solver_error, "%.3e") << ',' << num(o.condition, "%.3e") << ',' << num(r.c.bound, "%.1e") << ','
      << (pareto[i] ? 1 : 0) << ',' << csv_field(r.words) << '\n';
  }
  return s.str();
}

std::string accuracy_markdown(const std::vector<CaseResult>& results, const std::vector<bool>& pareto,
                              const std::string& image_prefix) {
  std::ostringstream s;
  std::vector<std::string> families;
  for (const CaseResult& r : results)
    if (families.empty() || families.back() != r.c.family) families.push_back(r.c.family);
  for (const std::string& f : families) {
    const CaseResult* first = nullptr;
    int runs = 0, not_ok = 0;
    for (const CaseResult& r : results)
      if (r.c.family == f && !r.c.reference_only) {
        if (!first) first = &r;
        ++runs;
        not_ok += r.o.status != "converged";
      }
    if (!first) continue;
    s << "### " << f << ": " << first->c.quantity << "\n\nReference: " << first->c.reference_kind << ". " << runs
      << " runs, " << not_ok << " not converged. The Pareto front (no other run both faster and more accurate):\n\n"
      << "![" << f << ": run time against error](" << image_prefix << f << ".png)\n\n"
      << "| mode | mesh | CG tolerance | time [s] | peak memory [MB] | dofs | iterations | error |\n"
      << "|---|---|---|---|---|---|---|---|\n";
    std::vector<const CaseResult*> front;
    for (size_t i = 0; i < results.size(); ++i)
      if (results[i].c.family == f && pareto[i]) front.push_back(&results[i]);
    std::sort(front.begin(), front.end(), [](auto* a, auto* b) { return a->o.wall_s < b->o.wall_s; });
    for (const CaseResult* p : front) {
      const CaseResult& r = *p;
      s << "| " << r.c.mode << " | " << r.c.variant << " | " << tolerance(r) << " | " << num(r.o.wall_s, "%.3f")
        << " | " << num(r.o.peak_rss_mb, "%.0f") << " | " << r.o.dofs << " | " << iterations(r) << " | "
        << num(r.error, "%.2e") << " |\n";
    }
    s << "\n";
  }
  return s.str();
}

std::string stability_markdown(const std::vector<CaseResult>& results) {
  std::ostringstream s;
  std::map<std::string, std::map<Verdict, int>> counts;
  std::vector<std::string> families;
  for (const CaseResult& r : results) {
    if (r.c.reference_only) continue;
    if (counts.find(r.c.family) == counts.end()) families.push_back(r.c.family);
    ++counts[r.c.family][r.verdict];
  }
  s << "| family | ok | wrong (said) | failed (with a reason) | broken (crash, NaN) |\n|---|---|---|---|---|\n";
  for (const std::string& f : families)
    s << "| " << f << " | " << counts[f][Verdict::ok] << " | " << counts[f][Verdict::wrong] << " | "
      << counts[f][Verdict::failed] << " | " << counts[f][Verdict::broken] << " |\n";
  s << "\nEvery case (references solved by `direct` on the same model are listed with the family's runs):\n\n"
    << "| family | variant | mode | CG tolerance | verdict | iterations | error | bound | solver error | words |\n"
    << "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const CaseResult& r : results)
    s << "| " << r.c.family << " | " << md_cell(r.c.variant) << " | " << r.c.mode << " | " << tolerance(r) << " | "
      << to_string(r.verdict) << " | " << iterations(r) << " | " << num(r.error, "%.1e") << " | "
      << num(r.c.bound, "%.0e") << " | " << num(r.o.solver_error, "%.1e") << " | " << md_cell(r.words) << " |\n";
  return s.str();
}

}  // namespace rollsim::bench
