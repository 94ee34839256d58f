#include "world_mesh.hpp"

#include "csv_table.hpp"
#include "mesh/mesh_writer.hpp"
#include "output_dir.hpp"
#include "spinhash/vehicle_class.hpp"

namespace spinhash::experiment {

void settle(host::Mesh* m) {
  const host::Box3 b = m->bounding_box();
  Eigen::Matrix4d t = Eigen::Matrix4d::Identity();
  t.topRightCorner<3, 1>() = Eigen::Vector3d(-b.center().x(), -b.center().y(), -b.lo.z());
  m->apply_transform(t);
}

Eigen::Matrix4d linear_transform(const Eigen::Matrix3d& r) {
  Eigen::Matrix4d t = Eigen::Matrix4d::Identity();
  t.topLeftCorner<3, 3>() = r;
  return t;
}

std::vector<std::string> catalog_header() {
  return {"name", "class", "group", "source", "triangles", "length_m", "width_m", "height_m"};
}

std::vector<std::string> catalog_row(const host::Mesh& m, const std::string& klass, const std::string& source,
                                     const std::string& group) {
  std::string g = group;
  VehicleClass c = VehicleClass::kUnclassified;
  if (g.empty() && !klass.empty() && parse_vehicle_class(klass.c_str(), &c))
    g = vehicle_group_name(vehicle_group_of(c));
  const Eigen::Vector3d size = m.bounding_box().size();
  return {m.name,           klass,           g, source, std::to_string(m.triangle_count()), num(size.x(), 3),
          num(size.y(), 3), num(size.z(), 3)};
}

bool write_in_class_folder(const std::string& out, const std::string& klass, const std::string& source,
                           const host::Mesh& m, CsvTable* catalog, std::string* error,
                           const std::string& group) {
  const std::string dir = out + "/" + klass;
  if (!make_output_dir(dir, error) || !host::write_obj(dir + "/" + m.name + ".obj", m, error)) return false;
  catalog->add(catalog_row(m, klass, source, group));
  return true;
}

}  // namespace spinhash::experiment
