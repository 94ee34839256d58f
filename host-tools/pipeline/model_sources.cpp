#include "pipeline/model_sources.hpp"

#include <filesystem>
#include <set>

#include "mesh/mesh_loader.hpp"
#include "pipeline/progress.hpp"
#include "scan/scan_simulator.hpp"
#include "spinhash/limits.hpp"

namespace spinhash::pipeline {

bool load_model_meshes(const std::vector<std::string>& inputs, std::vector<ModelMesh>* out,
                       std::string* error, bool quiet) {
  std::vector<std::string> files;
  for (const std::string& in : inputs) {
    std::vector<std::string> found = host::list_mesh_files(in, error);
    if (found.empty()) {
      if (error->empty()) *error = in + ": no mesh files";
      return false;
    }
    files.insert(files.end(), found.begin(), found.end());
  }
  std::set<std::string> names;
  Progress progress("load meshes", static_cast<uint32_t>(files.size()), quiet);
  for (const std::string& f : files) {
    ModelMesh m;
    m.name = std::filesystem::path(f).stem().string();
    if (m.name.empty() || m.name.size() >= kMaxModelNameBytes) {
      *error = f + ": model name must be 1 to " + std::to_string(kMaxModelNameBytes - 1) + " bytes";
      return false;
    }
    if (!names.insert(m.name).second) {
      *error = f + ": a second model named '" + m.name + "'";
      return false;
    }
    std::string why;
    if (!host::load_mesh(f, &m.mesh, &why)) {
      *error = f + ": " + why;
      return false;
    }
    out->push_back(std::move(m));
    progress.tick(static_cast<uint32_t>(out->size()));
  }
  return true;
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
    out->push_back(host::ModelCloud{m.name, std::move(scan.xyz)});
    progress.tick(static_cast<uint32_t>(out->size()));
  }
  return true;
}

}  // namespace spinhash::pipeline
