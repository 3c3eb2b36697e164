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

std::vector<std::filesystem::path> write_increment_collection(const std::filesystem::path& pvd, const Model& model,
                                                              const Results& results,
                                                              const std::vector<std::string>& selected) {
  const std::string stem = pvd.stem().string();
  std::vector<std::filesystem::path> files;
  std::string xml =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <Collection>\n";
  for (size_t i = 0; i < results.increments.size(); ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "_%04zu.vtu", i + 1);
    const std::filesystem::path file = pvd.parent_path() / (stem + name);
    write_vtu(file, model, results.increments[i].bodies, selected);
    files.push_back(file);
    char step[40];
    std::snprintf(step, sizeof step, "%.17g", results.increments[i].load_factor);
    xml += "    <DataSet timestep=\"" + std::string(step) + "\" group=\"\" part=\"0\" file=\"" +
           xml_attribute(file.filename().string()) + "\"/>\n";
  }
  xml += "  </Collection>\n</VTKFile>\n";
  write_file_atomically(pvd, xml);
  return files;
}

}  // namespace rollsim
