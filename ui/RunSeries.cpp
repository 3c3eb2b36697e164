#include "RunSeries.h"

namespace rollsim::ui {

namespace {
const QVector<ResidualSample> kNone;

QString number(double v) { return QString::number(v, 'g', 17); }
}  // namespace

void RunSeries::clear() {
  tracks_.clear();
  solves_.clear();
  factorizations_.clear();
  increment_ = 0;
  ++revision_;
}

QVector<ResidualSample>& RunSeries::track(const QString& kind) {
  for (Track& t : tracks_)
    if (t.kind == kind) return t.samples;
  tracks_.append({kind, {}});
  return tracks_.last().samples;
}

void RunSeries::add_cg_iteration(int solve, int iteration, double residual) {
  QVector<ResidualSample>& cg = track(QStringLiteral("cg"));
  cg.append({increment_, solve, iteration, residual, static_cast<int>(cg.size()) + 1});
  ++revision_;
}

void RunSeries::add_newton_iteration(int increment, int iteration, double residual) {
  const int solves = solves_.isEmpty() ? 0 : solves_.last().solve;
  const int cg = static_cast<int>(residuals(QStringLiteral("cg")).size());
  QVector<ResidualSample>& newton = track(QStringLiteral("newton"));
  newton.append({increment, solves, iteration, residual, cg > 0 ? cg : static_cast<int>(newton.size()) + 1});
  ++revision_;
}

void RunSeries::end_solve(int solve, int cg_iterations) {
  solves_.append({increment_, solve, cg_iterations});
  ++revision_;
}

void RunSeries::add_factorization(const QString& group) {
  ++revision_;
  for (GroupFactorizations& g : factorizations_)
    if (g.group == group) {
      ++g.count;
      return;
    }
  factorizations_.append({group, 1});
}

QStringList RunSeries::kinds() const {
  QStringList k;
  for (const Track& t : tracks_) k << t.kind;
  return k;
}

const QVector<ResidualSample>& RunSeries::residuals(const QString& kind) const {
  for (const Track& t : tracks_)
    if (t.kind == kind) return t.samples;
  return kNone;
}

QString RunSeries::csv() const {
  QString s = QStringLiteral("series,kind,increment,solve,iteration,group,value\n");
  for (const Track& t : tracks_)
    for (const ResidualSample& p : t.samples)
      s += QStringLiteral("residual,%1,%2,%3,%4,,%5\n")
               .arg(t.kind, QString::number(p.increment), QString::number(p.solve), QString::number(p.iteration),
                    number(p.residual));
  for (const SolveRecord& r : solves_)
    s += QStringLiteral("cg_iterations,cg,%1,%2,,,%3\n").arg(r.increment).arg(r.solve).arg(r.cg_iterations);
  for (const GroupFactorizations& g : factorizations_) {
    QString group = g.group;
    if (group.contains(',') || group.contains('"')) group = '"' + group.replace('"', QStringLiteral("\"\"")) + '"';
    s += QStringLiteral("factorizations,,,,,%1,%2\n").arg(group, QString::number(g.count));
  }
  return s;
}

}  // namespace rollsim::ui
