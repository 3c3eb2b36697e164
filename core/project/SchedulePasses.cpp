#include "project/SchedulePasses.h"

#include "project/ModelBuilder.h"

namespace rollsim {

PassSetup set_up_pass(ScheduleRun& schedule, size_t k, const Project& whole) {
  const auto make = [&] {
    json j = schedule.pass_project(k);
    j["name"] = whole.name() + "-pass-" + std::to_string(k + 1);
    PassSetup s;
    s.project = parse_project(j.dump(), whole.source);
    s.model = build_model(s.project);
    return s;
  };
  PassSetup s = make();
  if (schedule.cools(k)) {
    schedule.cool(k, s.model);
    s = make();
  }
  schedule.apply(k, s.model);
  return s;
}

}  // namespace rollsim
