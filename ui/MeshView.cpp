#include "MeshView.h"

#include <vtkActor.h>
#include <vtkAxesActor.h>
#include <vtkCamera.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkGeometryFilter.h>
#include <vtkHardwareSelector.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkLookupTable.h>
#include <vtkMatrix4x4.h>
#include <vtkOrientationMarkerWidget.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkProperty2D.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkSelection.h>
#include <vtkSelectionNode.h>
#include <vtkTextProperty.h>
#include <vtkUnstructuredGrid.h>
#include <vtkVariant.h>
#include <vtkWarpVector.h>

#include <QMouseEvent>
#include <QResizeEvent>
#include <QRubberBand>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>

#include "ModelGrid.h"
#include "PvdWriter.h"
#include "VtuWriter.h"
#include "io/OutputFields.h"

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
constexpr long kEdgesUpTo = 40000;    // cell edges are drawn on meshes up to this many cells
constexpr int kNamedCategories = 16;  // the legend names bodies / subdomains up to this many

}  // namespace

QColor category_color(int i) {
  const auto& c = kCategories[static_cast<size_t>(std::max(0, i)) % kCategories.size()];
  return QColor::fromRgbF(c[0], c[1], c[2]);
}

MeshView::MeshView(QWidget* parent) : QVTKOpenGLNativeWidget(parent) {
  setRenderWindow(window_);
  // no multisampling: 8 samples per pixel (VTK's default) doubled the frame time under software OpenGL (35 → 19
  // ms per frame of a 1e5-cell slab, docs/BENCHMARKS-GUI.md) for smoother edges only
  window_->SetMultiSamples(0);
  window_->AddRenderer(renderer_);
  renderer_->GradientBackgroundOn();
  renderer_->SetBackground(0.93, 0.94, 0.96);
  renderer_->SetBackground2(0.62, 0.67, 0.76);
  vtkNew<vtkInteractorStyleTrackballCamera> style;
  interactor()->SetInteractorStyle(style);

  surface_->SetInputConnection(warp_->GetOutputPort());
  surface_->PassThroughCellIdsOn();  // selected faces map back to the cells painted
  mapper_->SetInputConnection(surface_->GetOutputPort());
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
  legend_->SetPosition(0.8, 0.1);
  legend_->SetWidth(0.12);
  // fixed font sizes: fitted to the bar's width, a title such as "plastic strain" shrank to an unreadable size
  legend_->UnconstrainedFontSizeOn();
  legend_->GetTitleTextProperty()->SetFontSize(13);
  legend_->GetLabelTextProperty()->SetFontSize(11);
  legend_->GetAnnotationTextProperty()->SetFontSize(11);
  legend_->SetHeight(0.72);
  legend_->SetNumberOfLabels(5);
  legend_->SetLabelFormat("%-#8.3g");
  legend_->GetTitleTextProperty()->SetColor(0.1, 0.1, 0.1);
  legend_->GetLabelTextProperty()->SetColor(0.1, 0.1, 0.1);
  legend_->GetAnnotationTextProperty()->SetColor(0.1, 0.1, 0.1);
  legend_->GetTitleTextProperty()->ShadowOff();
  legend_->GetTitleTextProperty()->ItalicOff();  // upright, as the rest of the window
  legend_->GetLabelTextProperty()->ItalicOff();
  legend_->GetAnnotationTextProperty()->ItalicOff();
  legend_->GetLabelTextProperty()->ShadowOff();
  legend_->GetAnnotationTextProperty()->ShadowOff();
  // a pale box behind bar and labels: the view frames a rolling pass on the gap, where the slab runs under the bar
  legend_->DrawBackgroundOn();
  legend_->GetBackgroundProperty()->SetColor(1.0, 1.0, 1.0);
  legend_->GetBackgroundProperty()->SetOpacity(0.75);
  legend_->GetTitleTextProperty()->SetBackgroundColor(1.0, 1.0, 1.0);  // the title stands above the box
  legend_->GetTitleTextProperty()->SetBackgroundOpacity(0.75);
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
  increment_ = -1;
  rebuild_grid();
  emit incrementChanged(increment_);
}

void MeshView::set_results(std::shared_ptr<const Model> model, std::shared_ptr<const Results> results) {
  model_ = std::move(model);
  results_ = std::move(results);
  increment_ = -1;
  rebuild_grid();
  emit incrementChanged(increment_);
}

void MeshView::set_increment(int index) {
  if (index < -1 || index >= increment_count()) index = -1;
  if (index == increment_) return;
  increment_ = index;
  rebuild_grid();
  emit incrementChanged(increment_);
}

std::array<double, 2> MeshView::color_range() const {
  const double* r = mapper_->GetScalarRange();
  return {r[0], r[1]};
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
  if (results_ && increment_ >= 0) {
    const IncrementResults& shown = results_->increments[static_cast<size_t>(increment_)];
    grid_ = make_model_grid(model_of(shown, *model_), shown.bodies);
  } else {
    grid_ = make_model_grid(results_ && results_->model ? *results_->model : *model_, results_.get());
  }
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
  centres_.assign(static_cast<size_t>(grid_->GetNumberOfCells()), {0, 0, 0});
  for (vtkIdType c = 0; c < grid_->GetNumberOfCells(); ++c) {
    const vtkIdType* ids = nullptr;
    vtkIdType n = 0;
    grid_->GetCellPoints(c, n, ids);
    auto& centre = centres_[static_cast<size_t>(c)];
    for (vtkIdType k = 0; k < n; ++k) {
      const double* x = grid_->GetPoint(ids[k]);
      for (int i = 0; i < 3; ++i) centre[static_cast<size_t>(i)] += x[i] / static_cast<double>(n);
    }
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

namespace {
/// The colourable field of the output registry named `mode` (null for the categorical colourings).
const OutputField* result_field(const ColorBy& mode) {
  for (const OutputField& f : output_fields())
    if (f.colourable && QString::fromStdString(f.name) == mode) return &f;
  return nullptr;
}

/// A colour bar's title: the field's short name and its unit in the project's consistent units, on two lines (the
/// bar is narrow: one long line was shrunk to an unreadable size), "plastic strain\n[-]", "von Mises\n[stress]".
std::string bar_title(const OutputField& f) { return f.legend + "\n[" + f.unit + "]"; }

/// The grid's array of a field: point data for a node field, cell data for a cell field.
vtkDataArray* field_array(vtkUnstructuredGrid* grid, const OutputField& f) {
  vtkDataSetAttributes* data = f.location == FieldLocation::Node
                                   ? static_cast<vtkDataSetAttributes*>(grid->GetPointData())
                                   : static_cast<vtkDataSetAttributes*>(grid->GetCellData());
  return data->GetArray(f.name.c_str());
}
}  // namespace

bool MeshView::can_color_by(const ColorBy& mode) const {
  if (mode == color_by::Body || mode == color_by::Subdomain) return true;
  const OutputField* f = result_field(mode);
  return f && results_ && grid_ && field_array(grid_, *f);
}

void MeshView::set_color_by(const ColorBy& requested) {
  const ColorBy mode = can_color_by(requested) ? requested : color_by::Body;
  const bool changed = mode != color_by_;
  color_by_ = mode;
  if (grid_) apply_coloring();
  if (changed) emit colorByChanged(mode);
}

void MeshView::apply_coloring() {
  if (!grid_) return;
  if (!can_color_by(color_by_)) color_by_ = color_by::Body;
  legend_->VisibilityOn();
  if (color_by_ == color_by::Body || color_by_ == color_by::Subdomain) {
    const bool body = color_by_ == color_by::Body;
    int n = 1;
    if (body) {
      n = static_cast<int>(model_->bodies.size());
    } else if (auto* sub = vtkIntArray::SafeDownCast(grid_->GetCellData()->GetArray("subdomain_id"))) {
      // scanned, not GetRange(): set_partition writes the values without marking the grid modified
      const int* v = sub->GetPointer(0);
      n = sub->GetNumberOfValues() ? *std::max_element(v, v + sub->GetNumberOfValues()) + 1 : 1;
    }
    n = std::max(n, 1);
    categories_->ResetAnnotations();
    categories_->SetNumberOfTableValues(n);
    colours_->SetNumberOfTableValues(n);
    for (int i = 0; i < n; ++i) {
      const auto& c = kCategories[static_cast<size_t>(i) % kCategories.size()];
      categories_->SetTableValue(i, c[0], c[1], c[2], 1.0);
      colours_->SetTableValue(i, c[0], c[1], c[2], 1.0);
      const std::string name = body ? model_->bodies[static_cast<size_t>(i)].name : "subdomain " + std::to_string(i);
      categories_->SetAnnotation(vtkVariant(i), name);
    }
    categories_->SetRange(0, n - 1);
    categories_->Build();
    colours_->SetTableRange(0, n - 1);  // n colours over [0, n-1]: id k falls in bin k
    colours_->Build();
    mapper_->SetLookupTable(colours_);
    mapper_->SetScalarModeToUseCellFieldData();
    mapper_->SelectColorArray(body ? "body_id" : "subdomain_id");
    mapper_->SetScalarRange(0, n - 1);
    mapper_->ScalarVisibilityOn();
    // up to 16 categories each gets its name beside its colour; more (a 4×4×4 FETI partition has 64) would
    // overflow the view, so the bar shows the id range with numbered ticks instead
    const bool named = n <= kNamedCategories;
    legend_->SetLookupTable(named ? categories_.GetPointer() : colours_.GetPointer());
    legend_->SetTitle(body ? "body" : "subdomain");
    legend_->SetDrawAnnotations(named ? 1 : 0);
    legend_->SetDrawTickLabels(named ? 0 : 1);
    legend_->SetLabelFormat("%-.0f");
  } else {
    const OutputField& field = *result_field(color_by_);
    const char* name = field.name.c_str();
    vtkDataArray* a = field_array(grid_, field);
    double range[2] = {0, 1};
    if (a) a->GetRange(range, field.components > 1 ? -1 : 0);  // component -1: the magnitude of the vectors
    if (!(range[1] > range[0])) range[1] = range[0] + 1e-30;
    continuous_->SetVectorModeToMagnitude();
    continuous_->SetRange(range[0], range[1]);
    mapper_->SetLookupTable(continuous_);
    if (field.location == FieldLocation::Node)
      mapper_->SetScalarModeToUsePointFieldData();
    else
      mapper_->SetScalarModeToUseCellFieldData();
    mapper_->SelectColorArray(name);
    mapper_->SetScalarRange(range[0], range[1]);
    mapper_->ScalarVisibilityOn();
    legend_->SetLookupTable(continuous_);
    legend_->SetTitle(bar_title(field).c_str());
    legend_->SetDrawAnnotations(0);
    legend_->SetDrawTickLabels(1);
    legend_->SetLabelFormat("%-#8.3g");
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
  framed_.reset();
  fit(bounds());
}

void MeshView::frame(const std::array<double, 6>& box) {
  framed_ = box;
  fit(box);
}

void MeshView::fit(const std::array<double, 6>& box) {
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
  std::array<double, 6> b = box;
  renderer_->ResetCamera(b.data());
  if (model_ && model_->dim == 2 && width() > 0 && height() > 0) {  // fit width and height, 8 % margin
    // the legend with its names (drawn left of the swatches) takes the right 38 %: the mesh is fitted into and
    // centred on the rest
    constexpr double legend = 0.38;
    const double aspect = (1.0 - legend) * width() / height();
    cam->SetParallelScale(1.08 * std::max(0.5 * (b[3] - b[2]), 0.5 * (b[1] - b[0]) / aspect));
    double focal[3], position[3];
    cam->GetFocalPoint(focal);
    cam->GetPosition(position);
    const double shift = legend * width() / height() * cam->GetParallelScale();
    cam->SetFocalPoint(focal[0] + shift, focal[1], focal[2]);
    cam->SetPosition(position[0] + shift, position[1], position[2]);
  } else {
    cam->Zoom(1.1);
  }
  camera_fitted_ = true;
  render();
}

void MeshView::resizeEvent(QResizeEvent* event) {
  QVTKOpenGLNativeWidget::resizeEvent(event);
  if (camera_fitted_ && model_) framed_ ? fit(*framed_) : reset_camera();
}

void MeshView::mousePressEvent(QMouseEvent* event) {
  camera_fitted_ = false;
  QVTKOpenGLNativeWidget::mousePressEvent(event);
}

// QVTKOpenGLNativeWidget hands every event to VTK's interactor in event(): a paint drag must not reach it (the
// camera would turn while painting).
bool MeshView::event(QEvent* event) {
  auto* mouse = dynamic_cast<QMouseEvent*>(event);
  const bool press = event->type() == QEvent::MouseButtonPress && mouse && mouse->button() == Qt::LeftButton;
  if (!mouse || tool_ == PaintTool::Camera || paint_body_ < 0 || !(painting_ || press))
    return QVTKOpenGLNativeWidget::event(event);
  if (press) {
    paint_press(mouse->pos());
  } else if (event->type() == QEvent::MouseMove) {
    paint_move(mouse->pos());
  } else if (event->type() == QEvent::MouseButtonRelease) {
    paint_release(mouse->pos());
  }
  return true;
}

void MeshView::paint_press(QPoint at) {
  painting_ = true;
  press_ = at;
  ++stroke_;
  if (tool_ == PaintTool::Brush) {
    emit painted(cells_in_circle(paint_body_, at, brush_radius_), stroke_);
    return;
  }
  if (!band_) band_ = new QRubberBand(QRubberBand::Rectangle, this);
  band_->setGeometry(QRect(at, QSize()));
  band_->show();
}

void MeshView::paint_move(QPoint at) {
  if (tool_ == PaintTool::Brush)
    emit painted(cells_in_circle(paint_body_, at, brush_radius_), stroke_);
  else if (band_)
    band_->setGeometry(QRect(press_, at).normalized());
}

void MeshView::paint_release(QPoint at) {
  painting_ = false;
  if (tool_ == PaintTool::Box && band_) {
    band_->hide();
    emit painted(cells_in_box(paint_body_, QRect(press_, at).normalized()), stroke_);
  }
}

void MeshView::set_paint_tool(PaintTool tool) {
  tool_ = tool;
  setCursor(tool == PaintTool::Camera ? Qt::ArrowCursor : Qt::CrossCursor);
}

long MeshView::cell_offset(int body) const {
  long offset = 0;
  for (int b = 0; b < body; ++b) offset += model_->bodies[static_cast<size_t>(b)].mesh.num_elements();
  return offset;
}

std::vector<QPointF> MeshView::projected_centres(int body) const {
  std::vector<QPointF> out;
  if (!model_ || body < 0 || body >= static_cast<int>(model_->bodies.size())) return out;
  vtkMatrix4x4* m =
      renderer_->GetActiveCamera()->GetCompositeProjectionTransformMatrix(renderer_->GetTiledAspectRatio(), -1, 1);
  const long first = cell_offset(body), n = model_->bodies[static_cast<size_t>(body)].mesh.num_elements();
  out.reserve(static_cast<size_t>(n));
  const double w = width(), h = height();
  for (long c = first; c < first + n; ++c) {
    const auto& x = centres_[static_cast<size_t>(c)];
    double ndc[3];
    for (int r = 0; r < 3; ++r)
      ndc[r] =
          m->GetElement(r, 0) * x[0] + m->GetElement(r, 1) * x[1] + m->GetElement(r, 2) * x[2] + m->GetElement(r, 3);
    const double ww =
        m->GetElement(3, 0) * x[0] + m->GetElement(3, 1) * x[1] + m->GetElement(3, 2) * x[2] + m->GetElement(3, 3);
    out.emplace_back((ndc[0] / ww + 1) * 0.5 * w, (1 - ndc[1] / ww) * 0.5 * h);  // widget y grows downwards
  }
  return out;
}

std::vector<int> MeshView::visible_cells(int body, QRect box) {
  const double dpr = devicePixelRatioF();
  const int hpx = static_cast<int>(height() * dpr);
  vtkNew<vtkHardwareSelector> selector;
  selector->SetRenderer(renderer_);
  selector->SetFieldAssociation(vtkDataObject::FIELD_ASSOCIATION_CELLS);
  selector->SetArea(static_cast<unsigned>(std::max(0.0, box.left() * dpr)),
                    static_cast<unsigned>(std::max(0, hpx - 1 - static_cast<int>(box.bottom() * dpr))),
                    static_cast<unsigned>(std::max(0.0, box.right() * dpr)),
                    static_cast<unsigned>(std::max(0, hpx - 1 - static_cast<int>(box.top() * dpr))));
  vtkSmartPointer<vtkSelection> selection;
  selection.TakeReference(selector->Select());
  std::vector<int> cells;
  const long first = cell_offset(body), n = model_->bodies[static_cast<size_t>(body)].mesh.num_elements();
  vtkDataArray* original = surface_->GetOutput()->GetCellData()->GetArray("vtkOriginalCellIds");
  for (unsigned i = 0; original && selection && i < selection->GetNumberOfNodes(); ++i) {
    auto* ids = vtkIdTypeArray::SafeDownCast(selection->GetNode(i)->GetSelectionList());
    for (vtkIdType k = 0; ids && k < ids->GetNumberOfTuples(); ++k) {
      const auto c = static_cast<vtkIdType>(original->GetTuple1(ids->GetValue(k)));
      if (c >= first && c < first + n) cells.push_back(static_cast<int>(c - first));
    }
  }
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  return cells;
}

std::vector<int> MeshView::cells_in_circle(int body, QPoint centre, int radius) {
  const QRect box(centre - QPoint(radius, radius), centre + QPoint(radius, radius));
  const std::vector<QPointF> at = projected_centres(body);
  const double r2 = static_cast<double>(radius) * radius;
  auto inside = [&](int e) {
    const QPointF d = at[static_cast<size_t>(e)] - QPointF(centre);
    return d.x() * d.x() + d.y() * d.y() <= r2;
  };
  std::vector<int> cells;
  if (through_) {
    for (int e = 0; e < static_cast<int>(at.size()); ++e)
      if (inside(e)) cells.push_back(e);
  } else {
    for (const int e : visible_cells(body, box))
      if (inside(e)) cells.push_back(e);
  }
  return cells;
}

std::vector<int> MeshView::cells_in_box(int body, QRect box) {
  if (!through_) return visible_cells(body, box);
  std::vector<int> cells;
  const std::vector<QPointF> at = projected_centres(body);
  const QRectF area(box);
  for (int e = 0; e < static_cast<int>(at.size()); ++e)
    if (area.contains(at[static_cast<size_t>(e)])) cells.push_back(e);
  return cells;
}

void MeshView::set_partition(int body, const std::vector<int>& map) {
  if (!grid_ || !model_ || body < 0 || body >= static_cast<int>(model_->bodies.size())) return;
  auto* sub = vtkIntArray::SafeDownCast(grid_->GetCellData()->GetArray("subdomain_id"));
  const long first = cell_offset(body), n = model_->bodies[static_cast<size_t>(body)].mesh.num_elements();
  if (!sub || static_cast<long>(map.size()) != n) return;
  for (long e = 0; e < n; ++e) sub->SetValue(first + e, map[static_cast<size_t>(e)]);
  if (!recolour_faces(*sub)) {
    sub->Modified();
    grid_->Modified();  // the warp and surface filters pass the new ids to the mapper
  }
  if (color_by_ == color_by::Subdomain)
    apply_coloring();
  else
    set_color_by(color_by::Subdomain);
}

bool MeshView::recolour_faces(vtkIntArray& cell_ids) {
  // The grid's array is written without Modified(): marking the grid would re-run the warp and surface filters
  // over every cell (~3 frames on 1e5 hexahedra) for a change that only recolours faces. The drawn faces get the
  // new ids through their grid cell instead; the grid's values are what the filters read when they next run.
  surface_->Update();  // nothing to do unless something else changed since the last frame
  vtkPolyData* faces = surface_->GetOutput();
  auto* cell = vtkIdTypeArray::SafeDownCast(faces->GetCellData()->GetArray("vtkOriginalCellIds"));
  auto* face_ids = vtkIntArray::SafeDownCast(faces->GetCellData()->GetArray("subdomain_id"));
  if (!cell || !face_ids || face_ids->GetNumberOfValues() != cell->GetNumberOfValues()) return false;
  for (vtkIdType f = 0; f < cell->GetNumberOfValues(); ++f) face_ids->SetValue(f, cell_ids.GetValue(cell->GetValue(f)));
  face_ids->Modified();  // the mapper uploads the colours again; the filters stay as they are
  return true;
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

void MeshView::export_pvd(const std::filesystem::path& file) const {
  if (!model_ || !results_ || results_->increments.empty())
    throw std::runtime_error("no run with increments to export");
  write_increment_collection(file, *model_, *results_);
}

long MeshView::drawn_cells() const { return grid_ && actor_->GetVisibility() ? grid_->GetNumberOfCells() : 0; }

void MeshView::render_now() { window_->Render(); }

void MeshView::render() {
  if (isVisible()) window_->Render();
  update();
}

}  // namespace rollsim::ui
