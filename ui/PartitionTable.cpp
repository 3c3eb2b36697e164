#include "PartitionTable.h"

#include <QHeaderView>
#include <cmath>

namespace rollsim::ui {

namespace {
enum Column { Id, Elements, Dofs, Multipliers, RigidModes, Pieces, FactorMflop, CostShare, kColumns };

QTableWidgetItem* cell(const QString& text, bool warn = false) {
  auto* item = new QTableWidgetItem(text);
  item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
  if (warn) item->setForeground(QColor(176, 0, 32));
  return item;
}

QString mflop(double flops) { return QString::number(flops / 1e6, 'f', flops < 1e7 ? 2 : 0); }
}  // namespace

PartitionTable::PartitionTable(QWidget* parent) : QTableWidget(parent) {
  setColumnCount(kColumns);
  setHorizontalHeaderLabels({tr("sub"), tr("elements"), tr("dofs"), tr("multipliers"), tr("rigid modes"), tr("pieces"),
                             tr("factor Mflop"), tr("cost %")});
  horizontalHeaderItem(Multipliers)
      ->setToolTip(tr("interface multipliers on the subdomain's boundary "
                      "(non-redundant, as the feti solver builds them)"));
  horizontalHeaderItem(RigidModes)->setToolTip(tr("rigid modes of the subdomain: > 0 means floating"));
  horizontalHeaderItem(FactorMflop)
      ->setToolTip(tr("estimated Cholesky factorization flops of the subdomain "
                      "(AMD ordering of its node graph)"));
  horizontalHeaderItem(CostShare)->setToolTip(
      tr("the subdomain's share of the predicted solve cost against one "
         "domain (factorizations and CG substitutions)"));
  verticalHeader()->hide();
  horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  setEditTriggers(QAbstractItemView::NoEditTriggers);
  setSelectionMode(QAbstractItemView::NoSelection);
}

PartitionTable::~PartitionTable() = default;

void PartitionTable::show_map(std::shared_ptr<const Model> model, int body, const std::vector<int>& map) {
  if (!model || body < 0 || body >= static_cast<int>(model->bodies.size())) {
    reporter_.reset();
    report_ = nullptr;
    setRowCount(0);
    return;
  }
  if (model != model_ || body != body_) {  // a new mesh: a new reporter (the old one refers to the old body)
    reporter_.reset();
    model_ = std::move(model);
    body_ = body;
    const Body& b = model_->bodies[static_cast<size_t>(body)];
    dofs_ = std::make_unique<DofMap>(b, body, model_->displacements);
    reporter_ = std::make_unique<PartitionReporter>(b, *dofs_);
  }
  Partition p;
  p.element_subdomain = map;
  for (const int id : map) p.num_subdomains = std::max(p.num_subdomains, id + 1);
  report_ = &reporter_->update(p);
  fill_rows(*report_);
}

void PartitionTable::fill_rows(const PartitionReport& r) {
  const int n = static_cast<int>(r.subdomains.size());
  setRowCount(n + 1);
  for (int i = 0; i < n; ++i) {
    const SubdomainReport& s = r.subdomains[static_cast<size_t>(i)];
    setItem(i, Id, cell(QString::number(s.id)));
    setItem(i, Elements, cell(QString::number(s.elements), s.elements == 0));
    setItem(i, Dofs, cell(QString::number(s.dofs)));
    setItem(i, Multipliers, cell(QString::number(s.multipliers)));
    setItem(i, RigidModes, cell(QString::number(s.rigid_modes_after_split)));
    setItem(i, Pieces, cell(QString::number(s.pieces), s.pieces != 1));
    setItem(i, FactorMflop, cell(mflop(s.factor.flops)));
    setItem(i, CostShare, cell(QString::number(100 * s.cost / r.one_domain_cost, 'f', 1)));
  }
  setItem(n, Id, cell(tr("all")));
  setItem(n, Elements, cell(QString::number(r.body_elements)));
  setItem(n, Dofs, cell(QString::number(r.dofs)));
  setItem(n, Multipliers, cell(QString::number(r.multipliers)));
  setItem(n, RigidModes, cell(QString::number(r.rigid_modes_after_split)));
  setItem(n, Pieces, cell(QString()));
  setItem(n, FactorMflop, cell(tr("%1 (one: %2)").arg(mflop(r.subdomain_factors.flops), mflop(r.one_domain.flops))));
  setItem(n, CostShare, cell(QString::number(100 * r.predicted_ratio, 'f', 1), r.predicted_ratio >= 1));
  for (int c = 0; c < kColumns; ++c) {
    QFont f = item(n, c)->font();
    f.setBold(true);
    item(n, c)->setFont(f);
  }
  if (!r.problems.empty()) {
    QStringList lines;
    for (const PartitionProblem& p : r.problems) lines << QString::fromStdString(p.path + ": " + p.message);
    verdict_ = lines.join(QLatin1Char('\n'));
  } else if (n <= 1) {
    verdict_ = tr("one domain: paint or fill to split the body");
  } else {
    verdict_ = tr("predicted cost %1 × one domain (%2)")
                   .arg(r.predicted_ratio, 0, 'f', 2)
                   .arg(r.predicted_ratio < 1 ? tr("the partition pays") : tr("one domain is cheaper"));
  }
  emit verdictChanged(verdict_);
}

}  // namespace rollsim::ui
