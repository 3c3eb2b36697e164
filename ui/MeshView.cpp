#include "MeshView.h"

#include <vtkActor.h>
#include <vtkAxesActor.h>
#include <vtkCamera.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataSetMapper.h>
#include <vtkDoubleArray.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkLookupTable.h>
#include <vtkOrientationMarkerWidget.h>
#include <vtkPointData.h>
#include <vtkProperty.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextProperty.h>
#include <vtkUnstructuredGrid.h>
#include <vtkVariant.h>
#include <vtkWarpVector.h>

#include <QMouseEvent>
#include <QResizeEvent>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>

#include "ModelGrid.h"
#include "VtuWriter.h"

namespace rollsim::ui {

namespace {

// Categorical colours (Tableau 10): bodies and subdomains side by side stay distinguishable.
constexpr std::array<std::array<double, 3>, 10> kCategories{{{0.306, 0.475, 0.655},
                                                             {0.949, 0.557, 0.169},
                                                             {0.349, 0.631, 0.310},
                                                             {0.882, 0.341, 0.349},
                                                             {0.463, 0.718, 0.698},
                                                             {0.929, 0.788, 0.282},
                                                             {0.690, 0.478, 0.631},
                                                             {1.000, 0.616, 0.655},
                                                             {0.612, 0.459, 0.373},
                                                             {0.729, 0.690, 0.675}}};
constexpr long kEdgesUpTo = 40000;  // cell edges are drawn on meshes up to this many cells

}  // namespace

MeshView::MeshView(QWidget* parent) : QVTKOpenGLNativeWidget(parent) {
  setRenderWindow(window_);
  window_->AddRenderer(renderer_);
  renderer_->GradientBackgroundOn();
  renderer_->SetBackground(0.93, 0.94, 0.96);
  renderer_->SetBackground2(0.62, 0.67, 0.76);
  vtkNew<vtkInteractorStyleTrackballCamera> style;
  interactor()->SetInteractorStyle(style);

  mapper_->SetInputConnection(warp_->GetOutputPort());
  mapper_->SetColorModeToMapScalars();
  actor_->SetMapper(mapper_);
  actor_->GetProperty()->SetEdgeColor(0.15, 0.15, 0.15);
  actor_->VisibilityOff();
  renderer_->AddActor(actor_);

  continuous_->SetHueRange(0.667, 0.0);  // blue (low) to red (high)
  continuous_->SetNumberOfTableValues(256);
  continuous_->Build();
  categories_->IndexedLookupOn();

  legend_->SetOrientationToVertical();
  legend_->SetPosition(0.88, 0.12);
  legend_->SetWidth(0.1);
  legend_->SetHeight(0.76);
  legend_->SetNumberOfLabels(5);
  legend_->SetLabelFormat("%-#8.3g");
  legend_->GetTitleTextProperty()->SetColor(0.1, 0.1, 0.1);
  legend_->GetLabelTextProperty()->SetColor(0.1, 0.1, 0.1);
  legend_->GetAnnotationTextProperty()->SetColor(0.1, 0.1, 0.1);
  legend_->GetTitleTextProperty()->ShadowOff();
  legend_->GetLabelTextProperty()->ShadowOff();
  legend_->GetAnnotationTextProperty()->ShadowOff();
  legend_->VisibilityOff();
  renderer_->AddActor2D(legend_);

  marker_->SetOrientationMarker(axes_);
  marker_->SetInteractor(interactor());
  marker_->SetViewport(0.0, 0.0, 0.18, 0.18);
  marker_->SetEnabled(1);
  marker_->InteractiveOff();
}

MeshView::~MeshView() { marker_->SetEnabled(0); }

void MeshView::set_model(std::shared_ptr<const Model> model) {
  model_ = std::move(model);
  results_.reset();
  rebuild_grid();
}

void MeshView::set_results(std::shared_ptr<const Model> model, std::shared_ptr<const Results> results) {
  model_ = std::move(model);
  results_ = std::move(results);
  rebuild_grid();
}

std::array<double, 6> MeshView::bounds() const {
  std::array<double, 6> b{0, 0, 0, 0, 0, 0};
  if (grid_ && grid_->GetNumberOfPoints() > 0) grid_->GetBounds(b.data());
  return b;
}

void MeshView::rebuild_grid() {
  if (!model_) {
    actor_->VisibilityOff();
    legend_->VisibilityOff();
    render();
    return;
  }
  grid_ = make_model_grid(*model_, results_.get());
  warp_->SetInputData(grid_);
  warp_->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "displacement");
  warp_->SetScaleFactor(results_ ? scale_ : 0.0);
  if (!results_) {  // vtkWarpVector needs vectors: undeformed meshes pass through with a zero field
    vtkNew<vtkDoubleArray> zero;
    zero->SetName("displacement");
    zero->SetNumberOfComponents(3);
    zero->SetNumberOfTuples(grid_->GetNumberOfPoints());
    zero->Fill(0.0);
    grid_->GetPointData()->AddArray(zero);
  }
  actor_->GetProperty()->SetEdgeVisibility(grid_->GetNumberOfCells() <= kEdgesUpTo);
  actor_->VisibilityOn();
  apply_coloring();
  const auto b = bounds();
  double change = 0, size = 0;
  for (int i = 0; i < 6; ++i) change = std::max(change, std::fabs(b[i] - shown_bounds_[i]));
  for (int i = 0; i < 3; ++i) size = std::max(size, b[2 * i + 1] - b[2 * i]);
  if (shown_dim_ != model_->dim || change > 1e-3 * size) {
    shown_bounds_ = b;
    shown_dim_ = model_->dim;
    reset_camera();
  } else {
    render();
  }
}

void MeshView::set_color_by(ColorBy mode) {
  if ((mode == ColorBy::Displacement || mode == ColorBy::VonMises) && !results_) mode = ColorBy::Body;
  const bool changed = mode != color_by_;
  color_by_ = mode;
  if (grid_) apply_coloring();
  if (changed) emit colorByChanged(mode);
}

void MeshView::apply_coloring() {
  if (!grid_) return;
  if ((color_by_ == ColorBy::Displacement || color_by_ == ColorBy::VonMises) && !results_) color_by_ = ColorBy::Body;
  legend_->VisibilityOn();
  if (color_by_ == ColorBy::Body || color_by_ == ColorBy::Subdomain) {
    const bool body = color_by_ == ColorBy::Body;
    int n = 1;
    if (body) {
      n = static_cast<int>(model_->bodies.size());
    } else if (vtkDataArray* sub = grid_->GetCellData()->GetArray("subdomain_id")) {
      n = static_cast<int>(sub->GetRange()[1]) + 1;
    }
    n = std::max(n, 1);
    categories_->ResetAnnotations();
    categories_->SetNumberOfTableValues(n);
    for (int i = 0; i < n; ++i) {
      const auto& c = kCategories[static_cast<size_t>(i) % kCategories.size()];
      categories_->SetTableValue(i, c[0], c[1], c[2], 1.0);
      const std::string name = body ? model_->bodies[static_cast<size_t>(i)].name : "subdomain " + std::to_string(i);
      categories_->SetAnnotation(vtkVariant(i), name);
    }
    categories_->SetRange(0, n - 1);
    categories_->Build();
    mapper_->SetLookupTable(categories_);
    mapper_->SetScalarModeToUseCellFieldData();
    mapper_->SelectColorArray(body ? "body_id" : "subdomain_id");
    mapper_->SetScalarRange(0, n - 1);
    mapper_->ScalarVisibilityOn();
    legend_->SetLookupTable(categories_);
    legend_->SetTitle(body ? "body" : "subdomain");
    legend_->SetDrawAnnotations(1);
  } else {
    const bool disp = color_by_ == ColorBy::Displacement;
    vtkDataArray* a = grid_->GetPointData()->GetArray(disp ? "displacement" : "von_mises");
    double range[2] = {0, 1};
    if (a) a->GetRange(range, disp ? -1 : 0);  // component -1: the magnitude of the vectors
    if (!(range[1] > range[0])) range[1] = range[0] + 1e-30;
    continuous_->SetVectorModeToMagnitude();
    continuous_->SetRange(range[0], range[1]);
    mapper_->SetLookupTable(continuous_);
    mapper_->SetScalarModeToUsePointFieldData();
    mapper_->SelectColorArray(disp ? "displacement" : "von_mises");
    mapper_->SetScalarRange(range[0], range[1]);
    mapper_->ScalarVisibilityOn();
    legend_->SetLookupTable(continuous_);
    legend_->SetTitle(disp ? "|u|" : "von Mises");
    legend_->SetDrawAnnotations(0);
  }
  render();
}

void MeshView::set_deformation_scale(double scale) {
  scale_ = std::max(0.0, scale);
  warp_->SetScaleFactor(results_ ? scale_ : 0.0);
  render();
}

double MeshView::suggested_deformation_scale() const {
  if (!results_ || !grid_) return 1.0;
  vtkDataArray* u = grid_->GetPointData()->GetArray("displacement");
  const auto b = bounds();
  double size = 0;
  for (int i = 0; i < 3; ++i) size = std::max(size, b[2 * i + 1] - b[2 * i]);
  double range[2] = {0, 0};
  if (u) u->GetRange(range, -1);
  if (!(range[1] > 0)) return 1.0;
  const double raw = 0.1 * size / range[1];
  return std::pow(10.0, std::round(std::log10(raw)));  // a round number: 1, 10, 100, ...
}

void MeshView::reset_camera() {
  vtkCamera* cam = renderer_->GetActiveCamera();
  if (model_ && model_->dim == 2) {
    cam->SetPosition(0, 0, 1);
    cam->SetFocalPoint(0, 0, 0);
    cam->SetViewUp(0, 1, 0);
    cam->ParallelProjectionOn();
  } else {
    cam->SetPosition(1, -1.6, 1.2);
    cam->SetFocalPoint(0, 0, 0);
    cam->SetViewUp(0, 0, 1);
    cam->ParallelProjectionOff();
  }
  renderer_->ResetCamera();
  if (model_ && model_->dim == 2 && width() > 0 && height() > 0) {  // fit width and height, 8 % margin
    const auto b = bounds();
    const double aspect = static_cast<double>(width()) / height();
    cam->SetParallelScale(1.08 * std::max(0.5 * (b[3] - b[2]), 0.5 * (b[1] - b[0]) / aspect));
  } else {
    cam->Zoom(1.1);
  }
  camera_fitted_ = true;
  render();
}

void MeshView::resizeEvent(QResizeEvent* event) {
  QVTKOpenGLNativeWidget::resizeEvent(event);
  if (camera_fitted_ && model_) reset_camera();
}

void MeshView::mousePressEvent(QMouseEvent* event) {
  camera_fitted_ = false;
  QVTKOpenGLNativeWidget::mousePressEvent(event);
}

void MeshView::wheelEvent(QWheelEvent* event) {
  camera_fitted_ = false;
  QVTKOpenGLNativeWidget::wheelEvent(event);
}

void MeshView::export_vtu(const std::filesystem::path& file) const {
  if (!model_) throw std::runtime_error("no model to export");
  if (results_)
    write_vtu(file, *model_, *results_);
  else
    write_mesh_vtu(file, *model_);
}

long MeshView::drawn_cells() const { return grid_ && actor_->GetVisibility() ? grid_->GetNumberOfCells() : 0; }

void MeshView::render_now() { window_->Render(); }

void MeshView::render() {
  if (isVisible()) window_->Render();
  update();
}

}  // namespace rollsim::ui
