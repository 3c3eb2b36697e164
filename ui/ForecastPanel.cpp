#include "ForecastPanel.h"

#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

#include "ProjectDocument.h"

namespace rollsim::ui {

namespace {
QTableWidgetItem* cell(const std::string& text, bool warning) {
  auto* item = new QTableWidgetItem(QString::fromStdString(text));
  item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
  if (warning) item->setForeground(QColor(180, 30, 30));
  return item;
}
}  // namespace

ForecastPanel::ForecastPanel(ProjectDocument* document, QWidget* parent)
    : QWidget(parent), doc_(document), headline_(new QLabel), table_(new QTableWidget(0, 3)) {
  setObjectName(QStringLiteral("forecastPanel"));
  headline_->setObjectName(QStringLiteral("forecastHeadline"));
  headline_->setWordWrap(true);
  headline_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  table_->setObjectName(QStringLiteral("forecastFacts"));
  table_->setHorizontalHeaderLabels({tr("before the run"), tr("value"), tr("how it follows")});
  table_->verticalHeader()->hide();
  table_->verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 4);  // a fact a line: more in view
  table_->setShowGrid(false);
  table_->setAlternatingRowColors(true);
  table_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setStretchLastSection(true);
  table_->setWordWrap(false);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(headline_);
  layout->addWidget(table_, 1);
  connect(doc_, &ProjectDocument::modelChanged, this, &ForecastPanel::refresh);
  refresh();
}

QString ForecastPanel::headline() const { return headline_->text(); }

void ForecastPanel::refresh() {
  if (!doc_->model()) return;
  const RunForecast& f = doc_->forecast();
  headline_->setText(tr("forecast: %1").arg(QString::fromStdString(forecast_line(f))));
  headline_->setStyleSheet(f.refusal.ok() ? QString() : QStringLiteral("color: rgb(180, 30, 30);"));
  headline_->setToolTip(
      tr("the time is an estimate from the Cholesky factors' size and element counts, with rates "
         "measured on a 2-core machine (docs/BENCHMARKS.md, \"The run forecast\")"));
  table_->setRowCount(static_cast<int>(f.facts.size()));
  for (size_t i = 0; i < f.facts.size(); ++i) {
    const ProcessFact& fact = f.facts[i];
    const int r = static_cast<int>(i);
    table_->setItem(r, 0, cell(fact.name, fact.warning));
    table_->setItem(r, 1, cell(fact.value, fact.warning));
    table_->setItem(r, 2, cell(fact.note, fact.warning));
    table_->item(r, 2)->setToolTip(QString::fromStdString(fact.note));
  }
  table_->setVisible(!f.facts.empty());
}

}  // namespace rollsim::ui
