#include "VtuWriter.h"

#include <vtkNew.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <stdexcept>

#include "ModelGrid.h"

namespace rollsim {

namespace {

void write(const std::filesystem::path& file, vtkUnstructuredGrid* grid) {
  const auto tmp = file.parent_path() / ("." + file.filename().string() + ".tmp");
  vtkNew<vtkXMLUnstructuredGridWriter> w;
  w->SetFileName(tmp.string().c_str());
  w->SetInputData(grid);
  w->SetDataModeToAppended();
  w->SetCompressorTypeToNone();  // zlib cost 5x the write time for a 2x smaller file
  std::error_code ec;
  const bool written = w->Write() == 1;
  if (written) std::filesystem::rename(tmp, file, ec);
  if (!written || ec) {
    std::filesystem::remove(tmp, ec);  // no temporary left behind
    throw std::runtime_error("cannot write " + file.string());
  }
}

}  // namespace

void write_vtu(const std::filesystem::path& file, const Model& model, const Results& results,
               const std::vector<std::string>& selected) {
  write(file, make_model_grid(model, &results, selected));
}

void write_vtu(const std::filesystem::path& file, const Model& model, const std::vector<BodyResults>& fields,
               const std::vector<std::string>& selected) {
  write(file, make_model_grid(model, fields, selected));
}

void write_mesh_vtu(const std::filesystem::path& file, const Model& model) { write(file, make_model_grid(model)); }

}  // namespace rollsim
