#pragma once
// The 3D view of the model (QVTKOpenGLNativeWidget): every body's mesh from vtkio's make_model_grid, coloured by
// body or subdomain (categorical colours) or, after a run, by displacement magnitude or von Mises stress
// (continuous map), with a colour legend, orientation axes and an optional deformed shape.
#include <QVTKOpenGLNativeWidget.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include <array>
#include <filesystem>
#include <memory>

#include "analysis/Results.h"
#include "model/Model.h"

class vtkActor;
class vtkAxesActor;
class vtkDataSetMapper;
class vtkGenericOpenGLRenderWindow;
class vtkLookupTable;
class vtkOrientationMarkerWidget;
class vtkRenderer;
class vtkScalarBarActor;
class vtkUnstructuredGrid;
class vtkWarpVector;

namespace rollsim::ui {

enum class ColorBy { Body, Subdomain, Displacement, VonMises };

class MeshView : public QVTKOpenGLNativeWidget {
  Q_OBJECT

 public:
  explicit MeshView(QWidget* parent = nullptr);
  ~MeshView() override;

  /// Shows a model without results (after an edit regenerated the mesh). The camera is kept unless the model's
  /// extent changed.
  void set_model(std::shared_ptr<const Model> model);
  /// Shows a model with its results (after a run).
  void set_results(std::shared_ptr<const Model> model, std::shared_ptr<const Results> results);
  bool has_results() const { return results_ != nullptr; }
  std::shared_ptr<const Model> model() const { return model_; }
  std::shared_ptr<const Results> results() const { return results_; }

  /// Displacement and von Mises need results; without them the view falls back to bodies.
  void set_color_by(ColorBy mode);
  ColorBy color_by() const { return color_by_; }
  /// Displacement magnification of the deformed shape (0: undeformed).
  void set_deformation_scale(double scale);
  double deformation_scale() const { return scale_; }
  /// A scale that makes the largest displacement 10 % of the model size (1 without results).
  double suggested_deformation_scale() const;
  void reset_camera();
  /// Writes what is shown (model and, after a run, results) as .vtu through vtkio. Throws on failure.
  void export_vtu(const std::filesystem::path& file) const;
  /// Renders the scene now (before a grab of the window).
  void render_now();
  /// Cells currently drawn (tests).
  long drawn_cells() const;

 signals:
  void colorByChanged(rollsim::ui::ColorBy mode);

 private:
  void resizeEvent(QResizeEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void rebuild_grid();
  void apply_coloring();
  void render();
  std::array<double, 6> bounds() const;

  vtkNew<vtkGenericOpenGLRenderWindow> window_;
  vtkNew<vtkRenderer> renderer_;
  vtkNew<vtkWarpVector> warp_;
  vtkNew<vtkDataSetMapper> mapper_;
  vtkNew<vtkActor> actor_;
  vtkNew<vtkLookupTable> categories_;
  vtkNew<vtkLookupTable> continuous_;
  vtkNew<vtkScalarBarActor> legend_;
  vtkNew<vtkAxesActor> axes_;
  vtkNew<vtkOrientationMarkerWidget> marker_;
  vtkSmartPointer<vtkUnstructuredGrid> grid_;
  std::shared_ptr<const Model> model_;
  std::shared_ptr<const Results> results_;
  ColorBy color_by_ = ColorBy::Body;
  double scale_ = 0;
  std::array<double, 6> shown_bounds_{0, 0, 0, 0, 0, 0};
  int shown_dim_ = 0;
  bool camera_fitted_ = true;  // until the user moves the camera, a resize fits the model again
};

}  // namespace rollsim::ui

Q_DECLARE_METATYPE(rollsim::ui::ColorBy)
