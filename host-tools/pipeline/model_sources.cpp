#include "pipeline/model_sources.hpp"

#include <filesystem>
#include <set>

#include "mesh/mesh_loader.hpp"
#include "pipeline/model_classes.hpp"
#include "pipeline/progress.hpp"
#include "scan/scan_simulator.hpp"
#include "spinhash/limits.hpp"

namespace spinhash::pipeline {

bool load_model_meshes(const std::vector<std::string>& inputs, std::vector<ModelMesh>* out,
                       std::string* error, bool quiet) {
  std::vector<std::string> files, problems;  // problems: one line per input or file that failed
  for (const std::string& in : inputs) {
    std::string why;
    std::vector<std::string> found = host::list_mesh_files(in, &why);
    if (found.empty()) problems.push_back(why.empty() ? in + ": no mesh files" : why);
    files.insert(files.end(), found.begin(), found.end());
  }
  std::set<std::string> names;
  Progress progress("load meshes", static_cast<uint32_t>(files.size()), quiet);
  for (size_t i = 0; i < files.size(); ++i) {
    const std::string& f = files[i];
    ModelMesh m;
    m.name = std::filesystem::path(f).stem().string();
    m.vehicle_class = class_of_file(f);
    std::string why;
    if (m.name.empty() || m.name.size() >= kMaxModelNameBytes) {
      problems.push_back(f + ": model name must be 1 to " + std::to_string(kMaxModelNameBytes - 1) +
                         " bytes");
    } else if (!names.insert(m.name).second) {
      problems.push_back(f + ": a second model named '" + m.name + "'");
    } else if (!host::load_mesh(f, &m.mesh, &why)) {
      problems.push_back(f + ": " + why);
    } else {
      out->push_back(std::move(m));
    }
    progress.tick(static_cast<uint32_t>(i + 1));
  }
  if (problems.empty()) return true;
  error->clear();
  for (const std::string& p : problems) *error += p + "\n";
  const size_t empty_inputs = problems.size() - (files.size() - out->size());  // missing or mesh-less
  *error += std::to_string(problems.size()) + " of " + std::to_string(files.size() + empty_inputs) +
            " meshes unreadable";
  return false;
}

bool scan_models(const std::vector<ModelMesh>& meshes, double spacing, std::vector<host::ModelCloud>* out,
                 std::string* error, bool quiet) {
  Progress progress("scan models", static_cast<uint32_t>(meshes.size()), quiet);
  for (const ModelMesh& m : meshes) {
    host::ScanOptions opt = host::model_scan_options();
    opt.point_spacing = spacing;
    host::ScanResult scan = host::simulate_scan(m.mesh, opt);
    if (!scan.ok() || scan.xyz.empty()) {
      *error = m.name + ": scan failed: " + (scan.ok() ? std::string("no points") : scan.error);
      return false;
    }
    out->push_back(host::ModelCloud{m.name, std::move(scan.xyz), m.vehicle_class, m.vehicle_group});
    progress.tick(static_cast<uint32_t>(out->size()));
  }
  return true;
}

}  // namespace spinhash::pipeline
