#include "PvdWriter.h"

#include <cstdio>
#include <string>

#include "VtuWriter.h"
#include "io/AtomicFile.h"

namespace rollsim {

namespace {
std::string xml_attribute(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}
}  // namespace

std::vector<std::pair<std::string, double>> state_values(const Results& results, double load_factor) {
  std::vector<std::pair<std::string, double>> values{{"load_factor", load_factor}};
  if (results.process && results.process->clock.known())
    values.emplace_back(results.process->clock.name, results.process->clock.at(load_factor));
  return values;
}

std::vector<std::filesystem::path> write_increment_collection(const std::filesystem::path& pvd, const Model& model,
                                                              const Results& results,
                                                              const std::vector<std::string>& selected,
                                                              const std::function<bool()>& stop,
                                                              const std::string& compression) {
  const std::string stem = pvd.stem().string();
  const ProcessClock clock = results.process ? results.process->clock : ProcessClock{};
  std::vector<std::filesystem::path> files;
  std::string xml =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <!-- timestep: " +
      (clock.known() ? clock.name + " [" + clock.unit + "]" : std::string("load factor")) +
      " -->\n"
      "  <Collection>\n";
  for (size_t i = 0; i < results.increments.size() && !(stop && stop()); ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "_%04zu.vtu", i + 1);
    const std::filesystem::path file = pvd.parent_path() / (stem + name);
    const double load_factor = results.increments[i].load_factor;
    write_vtu(file, model_of(results.increments[i], model), results.increments[i].bodies, selected,
              {compression, state_values(results, load_factor)});
    files.push_back(file);
    char step[40];
    std::snprintf(step, sizeof step, "%.17g", clock.at(load_factor));
    xml += "    <DataSet timestep=\"" + std::string(step) + "\" group=\"\" part=\"0\" file=\"" +
           xml_attribute(file.filename().string()) + "\"/>\n";
  }
  xml += "  </Collection>\n</VTKFile>\n";
  write_file_atomically(pvd, xml);
  return files;
}

}  // namespace rollsim
