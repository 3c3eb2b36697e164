#pragma once
// solver.petsc_options pass through to PETSc's options database, where some options open files or start programs:
// `-ksp_monitor ascii:PATH` and `-log_view :PATH` write PATH, `-options_file PATH` reads more options from one,
// `-info PATH` logs into one, `-on_error_attach_debugger` runs a debugger. A project file must not be able to
// overwrite any file its user can write, so those are refused with the option named; everything else (monitors
// and views to the terminal, `::ascii_info` formats, solver settings) passes. Header-only: the schema's check.
#include <sstream>
#include <string>
#include <vector>

namespace rollsim {

namespace petsc_options_detail {
inline bool is_option(const std::string& token) {
  return token.size() > 1 && token[0] == '-' &&
         ((token[1] >= 'a' && token[1] <= 'z') || (token[1] >= 'A' && token[1] <= 'Z') || token[1] == '_');
}
/// The file a viewer specification TYPE:FILE:FORMAT:MODE names ("" when none): `ascii:out.txt`, `:log.txt`.
inline std::string viewer_file(const std::string& value) {
  const size_t colon = value.find(':');
  if (colon == std::string::npos) return "";
  return value.substr(colon + 1, value.find(':', colon + 1) - colon - 1);
}
}  // namespace petsc_options_detail

/// The problem with `options` (an option that opens a file or starts a program), or "".
inline std::string petsc_options_problem(const std::string& options) {
  using namespace petsc_options_detail;
  std::istringstream in(options);
  std::vector<std::string> tokens;
  for (std::string t; in >> t;) tokens.push_back(t);
  const std::string advice =
      ": a project may not make PETSc open files or start programs (it could overwrite any "
      "file you can write); monitors and views print to the terminal without a file name";
  for (size_t i = 0; i < tokens.size(); ++i) {
    if (!is_option(tokens[i])) continue;
    const std::string name = tokens[i].substr(1);
    const std::string value = i + 1 < tokens.size() && !is_option(tokens[i + 1]) ? tokens[i + 1] : "";
    const std::string given = "`" + tokens[i] + (value.empty() ? "" : " " + value) + "`";
    if (name.find("debugger") != std::string::npos || name.find("emacs") != std::string::npos)
      return given + " starts a program" + advice;
    if (name == "options_file" || name == "options_file_yaml" || name.find("filename") != std::string::npos)
      return given + " names a file" + advice;
    const bool file_first = name == "info" || name == "history" || name == "log_trace" || name == "malloc_dump";
    const std::string file = file_first ? value.substr(0, value.find(':')) : viewer_file(value);
    if (!file.empty()) return given + " names the file '" + file + "'" + advice;
  }
  return "";
}

}  // namespace rollsim
