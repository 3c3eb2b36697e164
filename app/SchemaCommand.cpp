// `rollsim schema`: the project-file reference generated from the one schema.
#include <iostream>

#include "Commands.h"
#include "project/ProjectSchema.h"

namespace rollsim::app {

int schema_command() {
  std::cout << project_format_markdown();
  return 0;
}

}  // namespace rollsim::app
