#pragma once
// Everything a run reports for the live plots, recorded as it arrives (the data; ResidualPlot, SolvePlot and
// FactorizationPlot draw it): the residual of every iteration per kind ("cg" of the interface solves, "newton" of
// the nonlinear driver), the CG iterations of every linear solve and the numeric factorizations per group.
#include <QString>
#include <QStringList>
#include <QVector>

namespace rollsim::ui {

struct ResidualSample {
  int increment = 0;    // load increment (1-based; 0 before the first one started)
  int solve = 0;        // linear solve (cg: the solve it belongs to; newton: the solves done so far)
  int iteration = 0;    // 1-based within its solve (cg) or increment (newton)
  double residual = 0;  // relative, dimensionless
  int x = 0;            // where it is drawn: cg, its place among all CG iterations; newton, the CG iterations done
                        // when it arrived (the end of its solve), or its own count when no solve used CG
};

struct SolveRecord {
  int increment = 0, solve = 0, cg_iterations = 0;
};

struct GroupFactorizations {
  QString group;
  int count = 0;
};

class RunSeries {
 public:
  /// Forgets everything (a new run starts).
  void clear();

  void begin_increment(int increment) { increment_ = increment; }
  void add_cg_iteration(int solve, int iteration, double residual);
  void add_newton_iteration(int increment, int iteration, double residual);
  void end_solve(int solve, int cg_iterations);
  void add_factorization(const QString& group);

  /// The kinds recorded so far, in the order they first arrived ("cg", "newton").
  QStringList kinds() const;
  /// The samples of one kind, in arrival order (empty for an unknown kind).
  const QVector<ResidualSample>& residuals(const QString& kind) const;
  const QVector<SolveRecord>& solves() const { return solves_; }
  /// Per group, in the order of the first factorization.
  const QVector<GroupFactorizations>& factorizations() const { return factorizations_; }
  /// Changes with every recorded event: a plot redraws only when it moved.
  long revision() const { return revision_; }

  /// Every series as one CSV table, a row per point:
  ///   series,kind,increment,solve,iteration,group,value
  /// series `residual` (kind cg/newton, value = relative residual), `cg_iterations` (one row per linear solve,
  /// value = its CG iterations), `factorizations` (one row per group, value = numeric factorizations); fields that do
  /// not apply are empty.
  QString csv() const;

 private:
  struct Track {
    QString kind;
    QVector<ResidualSample> samples;
  };
  QVector<ResidualSample>& track(const QString& kind);

  QVector<Track> tracks_;
  QVector<SolveRecord> solves_;
  QVector<GroupFactorizations> factorizations_;
  int increment_ = 0;
  long revision_ = 0;
};

}  // namespace rollsim::ui
