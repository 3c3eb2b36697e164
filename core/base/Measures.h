#pragma once
// What a process measures, in words every layer understands: a measure (name, label, unit), a table of
// them (per increment, or along a profile), the charts a process asks for, and the process's results. The Newton
// driver, Results, the observers and the writers speak of these only; what a measure means is its process's
// (core/process/). A unit is written once, in the measure's declaration.
#include <array>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace rollsim {

/// One measured quantity: its key (CSV column, summary.json key), what a reader calls it, and its unit.
struct Measure {
  std::string name;   // "roll_force"
  std::string label;  // "roll force"
  std::string unit;   // "N/mm (per unit width)"
};

/// The value of each of a table's measures at one point (an increment, a node of a profile).
using MeasureRow = std::vector<double>;

/// A table of measures: its columns once, then its rows. Written as `<name>.csv`.
struct MeasureTable {
  std::string name;  // file stem: "rolling" → rolling.csv
  std::vector<Measure> columns;
  std::vector<MeasureRow> rows;
  /// The column named `key`, or columns.size() when there is none.
  size_t column(const std::string& key) const {
    for (size_t c = 0; c < columns.size(); ++c)
      if (columns[c].name == key) return c;
    return columns.size();
  }
};

/// One line of a chart: a column of the table against the chart's x column, scaled for display (e.g. N/mm → MN/m).
struct ChartLine {
  std::string column;
  std::string label;
  double scale = 1;
  bool right_axis = false;
  int colour = 0;  // index into the chart sink's palette
};

/// A dashed horizontal reference (a closed form beside a measured line), in the line's displayed unit.
struct ChartReference {
  std::string label;
  double value = 0;
  bool right_axis = false;
  int colour = 0;
};

/// A chart a process asks for; a writer's chart sink draws it from the table it names.
struct ChartRequest {
  std::string file;         // "rolling.png"
  std::string title;        // "Roll force and torque against travel (…)"
  std::string short_title;  // for a small chart: the units in it, since a short axis title would be cut
  std::string table;        // MeasureTable::name
  std::string x;            // column along the x axis
  std::string x_title, left_title, right_title;  // axis titles with their displayed units
  std::vector<ChartLine> lines;
  std::vector<ChartReference> references;
};

/// What a process reports of a run: tables (the first per increment), the charts, its section of summary.json and
/// the lines a front end shows when the run ends.
/// The process's own time axis for the result files (ParaView's time): its value at load factor λ is
/// λ · per_load_factor — a rolling pass's roll travel [length]. Unknown (0): the load factor is the time.
struct ProcessClock {
  std::string name;  // "travel"
  std::string unit;  // "length"
  double per_load_factor = 0;
  bool known() const { return per_load_factor > 0; }
  double at(double load_factor) const { return known() ? load_factor * per_load_factor : load_factor; }
};

struct ProcessResults {
  std::string process;  // the registry name, the key of summary.json's results.<process>
  ProcessClock clock;   // the time of the increments' result files
  std::vector<MeasureTable> tables;
  std::vector<ChartRequest> charts;
  nlohmann::json summary;           // results.<process>: steady values, units, closed forms
  std::vector<std::string> report;  // "roll force 7.25e+03 N/mm, …": what a front end prints
  /// How a view first shows the results, in the process's terms: the box where it happens (x, y, z ranges in the
  /// model's coordinates, as [min x, max x, min y, max y, min z, max z]; a rolling pass: the roll gap), the field
  /// (an output field's name, e.g. plastic_strain) and whether deformed ×1; empty box: the whole model.
  struct View {
    std::optional<std::array<double, 6>> box;
    std::string field;
    bool deformed = false;
  } view;
  const MeasureTable* table(const std::string& key) const {
    for (const MeasureTable& t : tables)
      if (t.name == key) return &t;
    return nullptr;
  }
};

/// A measure's value at one completed increment, as the observers hear it.
struct MeasureValue {
  const Measure* measure = nullptr;
  double value = 0;
};

}  // namespace rollsim
