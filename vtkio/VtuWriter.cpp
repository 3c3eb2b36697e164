#include "VtuWriter.h"

#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <stdexcept>

#include "ModelGrid.h"
#include "io/AtomicFile.h"

namespace rollsim {

namespace {

/// VTK encodes the file in memory and reports its own failures there; the bytes reach the disk through
/// write_file_atomically, whose every write is checked (VTK's own file output reported success on a cut-off file).
void write(const std::filesystem::path& file, vtkUnstructuredGrid* grid, const VtuEncoding& encoding) {
  for (const auto& [name, value] : encoding.values) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name.c_str());
    a->InsertNextValue(value);
    grid->GetFieldData()->AddArray(a);
  }
  vtkNew<vtkXMLUnstructuredGridWriter> w;
  w->WriteToOutputStringOn();
  w->SetInputData(grid);
  w->SetDataModeToAppended();
  w->EncodeAppendedDataOff();  // raw binary: a third smaller than base64, and nothing to encode
  if (encoding.compression == "zlib")
    w->SetCompressorTypeToZLib();
  else if (encoding.compression == "none")
    w->SetCompressorTypeToNone();
  else
    w->SetCompressorTypeToLZ4();
  if (w->Write() != 1 || w->GetErrorCode() != 0)
    throw WriteError("cannot write " + file.string() + ": VTK could not encode the grid");
  write_file_atomically(file, w->GetOutputString());
}

}  // namespace

void write_vtu(const std::filesystem::path& file, const Model& model, const Results& results,
               const std::vector<std::string>& selected, const VtuEncoding& encoding) {
  write(file, make_model_grid(model, &results, selected), encoding);
}

void write_vtu(const std::filesystem::path& file, const Model& model, const std::vector<BodyResults>& fields,
               const std::vector<std::string>& selected, const VtuEncoding& encoding) {
  write(file, make_model_grid(model, fields, selected), encoding);
}

void write_mesh_vtu(const std::filesystem::path& file, const Model& model) {
  write(file, make_model_grid(model), VtuEncoding{});
}

}  // namespace rollsim
