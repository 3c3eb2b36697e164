#include "VtkThreads.h"

// vtkSMPTools.h itself is not valid C++20 in VTK 9.1 (a template-id as a constructor's name); its API class is
#include <SMP/Common/vtkSMPToolsAPI.h>

namespace rollsim {

bool run_vtk_sequentially() { return vtk::detail::smp::vtkSMPToolsAPI::GetInstance().SetBackend("Sequential"); }

}  // namespace rollsim
