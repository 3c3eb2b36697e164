#pragma once
// VTK's own threads. The writers' loops (array ranges, appended data) are small; under VTK's TBB backend each hands
// them to TBB workers that then spin idle: 2.5 % of the main job's CPU time on a second thread, for nothing. The
// batch binary runs VTK's SMP loops on the calling thread instead (the window keeps TBB for its filters).
namespace rollsim {

/// VTK's SMP tools on the calling thread from now on (vtkSMPTools' Sequential backend); false if VTK has none.
bool run_vtk_sequentially();

}  // namespace rollsim
