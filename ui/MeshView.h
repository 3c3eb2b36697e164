#pragma once
// The 3D view of the model (QVTKOpenGLNativeWidget): every body's mesh from vtkio's make_model_grid, coloured by
// body or subdomain (categorical colours) or, after a run, by displacement magnitude or von Mises stress
// (continuous map), with a colour legend, orientation axes and an optional deformed shape.
#include <QVTKOpenGLNativeWidget.h>
#include <vtkNew.h>

class vtkIntArray;
#include <vtkSmartPointer.h>

#include <QColor>
#include <QRect>
#include <array>
#include <filesystem>
#include <memory>
#include <optional>

#include "analysis/Results.h"
#include "model/Model.h"

class vtkActor;
class vtkAxesActor;
class vtkGeometryFilter;
class vtkPolyDataMapper;
class vtkGenericOpenGLRenderWindow;
class vtkLookupTable;
class vtkOrientationMarkerWidget;
class vtkRenderer;
class vtkScalarBarActor;
class vtkUnstructuredGrid;
class vtkWarpVector;
class QRubberBand;

namespace rollsim::ui {

/// What the view is coloured by: "body", "subdomain" (categorical) or the name of a colourable node field of the
/// output registry (io/OutputFields) — the toolbar lists them from there, so a new field needs no code here.
using ColorBy = QString;
namespace color_by {
inline const ColorBy Body = QStringLiteral("body");
inline const ColorBy Subdomain = QStringLiteral("subdomain");
inline const ColorBy Displacement = QStringLiteral("displacement");
inline const ColorBy VonMises = QStringLiteral("von_mises");
inline const ColorBy ContactPressure = QStringLiteral("contact_pressure");
}  // namespace color_by

/// The categorical colour of body / subdomain `i` in the view (Tableau 10, repeating).
QColor category_color(int i);

/// What a left drag in the view does: turn the camera, paint with a round brush, or select a rubber-band box.
enum class PaintTool { Camera, Brush, Box };

class MeshView : public QVTKOpenGLNativeWidget {
  Q_OBJECT

 public:
  explicit MeshView(QWidget* parent = nullptr);
  ~MeshView() override;

  /// Shows a model without results (after an edit regenerated the mesh). The camera is kept unless the model's
  /// extent changed.
  void set_model(std::shared_ptr<const Model> model);
  /// Shows a model with its results (after a run): the final fields (Results::bodies).
  void set_results(std::shared_ptr<const Model> model, std::shared_ptr<const Results> results);
  /// Shows the fields of load increment `index` (0-based in Results::increments; -1: the final fields); the
  /// colouring's range and the deformed shape follow.
  void set_increment(int index);
  /// The increment shown (-1: the final fields) and how many the results hold.
  int increment() const { return increment_; }
  int increment_count() const { return results_ ? static_cast<int>(results_->increments.size()) : 0; }
  /// The range the continuous colouring maps (the legend's), e.g. of |u| on the shown increment.
  std::array<double, 2> color_range() const;
  bool has_results() const { return results_ != nullptr; }
  std::shared_ptr<const Model> model() const { return model_; }
  std::shared_ptr<const Results> results() const { return results_; }

  /// Displacement, von Mises and contact pressure need results (contact pressure a model with contacts);
  /// without them the view falls back to bodies.
  void set_color_by(const ColorBy& mode);
  bool can_color_by(const ColorBy& mode) const;
  ColorBy color_by() const { return color_by_; }
  /// Displacement magnification of the deformed shape (0: undeformed).
  void set_deformation_scale(double scale);
  double deformation_scale() const { return scale_; }
  /// A scale that makes the largest displacement 10 % of the model size (1 without results).
  double suggested_deformation_scale() const;
  void reset_camera();
  /// Fits the camera to `box` ([min x, max x, min y, max y, min z, max z]: a process's region, e.g. the roll gap)
  /// instead of the whole model, until reset_camera.
  void frame(const std::array<double, 6>& box);
  /// frame()'s box while the camera holds it (empty after reset_camera or once the user turns the camera).
  std::optional<std::array<double, 6>> framed() const {
    return camera_fitted_ ? framed_ : std::optional<std::array<double, 6>>{};
  }
  /// Writes what is shown (model and, after a run, results) as .vtu through vtkio. Throws on failure.
  void export_vtu(const std::filesystem::path& file) const;
  /// Writes the run's increments as a ParaView collection (`file`.pvd and one .vtu per increment beside it) through
  /// vtkio. Throws without results or on failure.
  void export_pvd(const std::filesystem::path& file) const;
  /// Renders the scene now (before a grab of the window).
  void render_now();
  /// Cells currently drawn (tests).
  long drawn_cells() const;

  /// Partition painting on one body (-1: none). `through`: every cell whose centre falls under the brush or box,
  /// across the depth (columns of a slab); otherwise only the cells visible on screen (VTK hardware selection).
  void set_paint_tool(PaintTool tool);
  PaintTool paint_tool() const { return tool_; }
  void set_paint_body(int body) { paint_body_ = body; }
  void set_brush_radius(int pixels) { brush_radius_ = std::max(1, pixels); }
  int brush_radius() const { return brush_radius_; }
  void set_paint_through(bool through) { through_ = through; }
  /// Elements of `body` under a brush at `centre` (widget pixels) / inside `box`.
  std::vector<int> cells_in_circle(int body, QPoint centre, int radius);
  std::vector<int> cells_in_box(int body, QRect box);
  /// Widget positions of the cell centres of `body` (the undeformed mesh), for the current camera.
  std::vector<QPointF> projected_centres(int body) const;
  /// Shows a body's element -> subdomain map (colours by subdomain).
  void set_partition(int body, const std::vector<int>& map);

 signals:
  void colorByChanged(const QString& mode);
  /// Another increment is shown (set_increment, or new results).
  void incrementChanged(int index);
  /// A paint step on the paint body: `elements` under the brush or in the box; `stroke` groups the steps of one
  /// drag (a new id per press).
  void painted(const std::vector<int>& elements, int stroke);

 private:
  void resizeEvent(QResizeEvent* event) override;
  bool event(QEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void paint_press(QPoint at);
  void paint_move(QPoint at);
  void paint_release(QPoint at);
  void wheelEvent(QWheelEvent* event) override;
  std::vector<int> visible_cells(int body, QRect box);
  long cell_offset(int body) const;
  void rebuild_grid();
  void apply_coloring();
  /// Writes a changed subdomain_id of the grid into the drawn faces; false if they are not there (then the
  /// caller marks the grid modified and the filters run again).
  bool recolour_faces(vtkIntArray& cell_ids);
  void render();
  std::array<double, 6> bounds() const;
  void fit(const std::array<double, 6>& box);    // the camera on `box`, the view's legend kept clear of it
  std::optional<std::array<double, 6>> framed_;  // frame()'s box, kept over resizes

  vtkNew<vtkGenericOpenGLRenderWindow> window_;
  vtkNew<vtkRenderer> renderer_;
  vtkNew<vtkWarpVector> warp_;
  vtkNew<vtkGeometryFilter> surface_;  // outer faces, with the grid cell of each (vtkOriginalCellIds)
  vtkNew<vtkPolyDataMapper> mapper_;
  vtkNew<vtkActor> actor_;
  vtkNew<vtkLookupTable> categories_;  // indexed, annotated: the legend's
  vtkNew<vtkLookupTable> colours_;     // the same colours by range: the mapper's (an indexed lookup per cell is
                                       // slow: half a second per repaint of 1e5 hexahedra)
  vtkNew<vtkLookupTable> continuous_;
  vtkNew<vtkScalarBarActor> legend_;
  vtkNew<vtkAxesActor> axes_;
  vtkNew<vtkOrientationMarkerWidget> marker_;
  vtkSmartPointer<vtkUnstructuredGrid> grid_;
  std::shared_ptr<const Model> model_;
  std::shared_ptr<const Results> results_;
  ColorBy color_by_ = color_by::Body;
  int increment_ = -1;
  double scale_ = 0;
  std::array<double, 6> shown_bounds_{0, 0, 0, 0, 0, 0};
  int shown_dim_ = 0;
  bool camera_fitted_ = true;  // until the user moves the camera, a resize fits the model again
  PaintTool tool_ = PaintTool::Camera;
  int paint_body_ = -1, brush_radius_ = 12, stroke_ = 0;
  bool through_ = true, painting_ = false;
  QPoint press_;
  QRubberBand* band_ = nullptr;
  std::vector<std::array<double, 3>> centres_;  // cell centres of the grid
};

}  // namespace rollsim::ui

Q_DECLARE_METATYPE(std::vector<int>)
