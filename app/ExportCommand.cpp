// `rollsim export-ccx PROJECT OUT.inp`: the same model as CalculiX input.
#include <iostream>
#include <stdexcept>

#include "Commands.h"
#include "io/AtomicFile.h"
#include "io/CalculixWriter.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"

namespace rollsim::app {

int export_ccx_command(const std::string& project, const std::string& out) {
  try {
    const Model model = build_model(load_project(project));
    write_file_atomically(out, calculix_input(model));
  } catch (const ProjectError& e) {
    std::cerr << "rollsim: error: " << e.what() << "\n";
    return 2;
  } catch (const std::invalid_argument& e) {
    std::cerr << "rollsim: error: " << project << ": " << e.what() << "\n";
    return 2;
  } catch (const std::runtime_error& e) {  // the output file cannot be written
    std::cerr << "rollsim: error: " << e.what() << "\n";
    return 2;
  }
  std::cout << out << "\n";
  return 0;
}

}  // namespace rollsim::app
