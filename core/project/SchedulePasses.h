#pragma once
// A rolling schedule's pass made ready to run, the same way for every front end (`rollsim run`, the window): its
// project from the schedule, validated as any project, built into its model, its slab cooled in air first where the
// pass says so (the project then asked again: its slab_temperature is the cooled mean) and given what it brings.
#include "model/Model.h"
#include "process/rolling/RollingSchedule.h"
#include "project/Project.h"

namespace rollsim {

struct PassSetup {
  Project project;
  Model model;
};

/// Pass k of `schedule` (made from `whole`, the schedule's project) ready to run; throws ProjectError for a pass
/// whose project is invalid, AnalysisError where what it brings cannot be applied.
PassSetup set_up_pass(ScheduleRun& schedule, size_t k, const Project& whole);

}  // namespace rollsim
