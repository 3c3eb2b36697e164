#pragma once
// The live partition table: one row per subdomain (elements, dofs, interface multipliers, rigid modes, pieces,
// estimated factorization cost) and a total row against one domain — core's PartitionReporter, which recomputes
// only the subdomains a stroke changed — with the problems of the map (empty, disconnected subdomains) below.
#include <QTableWidget>
#include <memory>
#include <vector>

#include "model/DofMap.h"
#include "model/Model.h"
#include "partition/PartitionReport.h"

class QLabel;

namespace rollsim::ui {

class PartitionTable : public QTableWidget {
  Q_OBJECT

 public:
  explicit PartitionTable(QWidget* parent = nullptr);
  ~PartitionTable() override;
  /// Shows the partition `map` of body `body` of `model` (null or -1: empty table).
  void show_map(std::shared_ptr<const Model> model, int body, const std::vector<int>& map);
  /// The report behind the rows (null before the first map).
  const PartitionReport* report() const { return report_; }
  /// "predicted cost 0.42 × one domain (pays)" or the map's problems.
  QString verdict() const { return verdict_; }

 signals:
  void verdictChanged(const QString& text);

 private:
  void fill_rows(const PartitionReport& r);

  std::shared_ptr<const Model> model_;  // keeps the body the reporter refers to alive
  int body_ = -1;
  std::unique_ptr<DofMap> dofs_;
  std::unique_ptr<PartitionReporter> reporter_;
  const PartitionReport* report_ = nullptr;
  QString verdict_;
};

}  // namespace rollsim::ui
