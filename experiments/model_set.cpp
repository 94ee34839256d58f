#include "model_set.hpp"

#include "mesh/vehicle_generator.hpp"
#include "pipeline/build_database_file.hpp"
#include "pipeline/model_classes.hpp"

namespace spinhash::experiment {

std::vector<pipeline::ModelMesh> generated_models(uint32_t count, uint64_t fleet_seed) {
  std::vector<pipeline::ModelMesh> out;
  for (host::Mesh& m : host::generate_fleet(count, fleet_seed)) {
    std::string name = m.name;
    const VehicleClass cls = pipeline::class_from_name(name);  // the family: "sedan-03" is a sedan
    out.push_back(pipeline::ModelMesh{std::move(name), std::move(m), cls});
  }
  return out;
}

bool loaded_models(const std::vector<std::string>& inputs, uint32_t max_count,
                   std::vector<pipeline::ModelMesh>* out, std::string* error) {
  if (!pipeline::load_model_meshes(inputs, out, error, /*quiet=*/false)) return false;
  if (max_count > 0 && out->size() > max_count) out->resize(max_count);
  return true;
}

bool model_clouds(const std::vector<pipeline::ModelMesh>& meshes, std::vector<host::ModelCloud>* out,
                  std::string* error) {
  return pipeline::scan_models(meshes, pipeline::BuildSettings{}.scan_spacing, out, error, /*quiet=*/false);
}

}  // namespace spinhash::experiment
