#include "process/ProcessRegistry.h"

#include "process/rolling/RollingProcess.h"

namespace rollsim {

const std::vector<const Process*>& process_registry() {
  static const RollingProcess rolling;
  static const std::vector<const Process*> registry{&rolling};
  return registry;
}

const Process* find_process(const std::string& name) {
  for (const Process* p : process_registry())
    if (p->name() == name) return p;
  return nullptr;
}

const Process* process_of(const json& project) {
  const auto p = project.find("process");
  return p == project.end() ? nullptr : find_process(p->value("type", ""));
}

std::vector<std::string> process_outputs() {
  std::vector<std::string> files;
  for (const Process* p : process_registry())
    for (std::string& f : p->outputs()) files.push_back(std::move(f));
  return files;
}

const ObjectSchema& process_schema() {
  static const ObjectSchema s = [] {
    ObjectSchema o{
        "process", "A process that generates bodies, contacts and conditions, selected by `type`.", {}, "type", {}};
    for (const Process* p : process_registry()) o.variants[p->name()] = &p->schema();
    o.default_variant = process_registry().front()->name();  // a section without `type` is the first (rolling)
    return o;
  }();
  return s;
}

json expand_process(const json& project) {
  const Process* p = process_of(project);
  return p ? p->expand(project) : project;
}

}  // namespace rollsim
