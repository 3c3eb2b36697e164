#pragma once
// Every process by name (process.type): the project schema's `process` variants, the model builder's expansion and
// run_project's measures come from here.
#include <string>
#include <vector>

#include "process/Process.h"

namespace rollsim {

/// Every process, in the order shown to users.
const std::vector<const Process*>& process_registry();
/// The process named `name`, or null.
const Process* find_process(const std::string& name);
/// The process of a project's validated `process` section (null without one).
const Process* process_of(const json& project);

/// The files any process writes (Process::outputs).
std::vector<std::string> process_outputs();

/// The `process` object of the project schema: `type` chooses a registry entry, whose fields follow.
const ObjectSchema& process_schema();

/// `project` with its process's bodies, materials, contacts and conditions appended (unchanged without one).
json expand_process(const json& project);

}  // namespace rollsim
