#include "scan/ray_caster.hpp"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>

namespace spinhash::host {
namespace {

// Rays per rtcIntersect1M call: large enough to amortise the call, small
// enough to stay in cache.
constexpr std::size_t kRayBatch = 1024;
// One build thread: scenes are small and results must not depend on load.
constexpr const char* kDeviceConfig = "threads=1";

bool fail(std::string* error, const std::string& message) {
  if (error) *error = message;
  return false;
}

RTCRayHit to_embree(const Ray& ray) {
  RTCRayHit rh{};
  rh.ray.org_x = ray.origin.x();
  rh.ray.org_y = ray.origin.y();
  rh.ray.org_z = ray.origin.z();
  rh.ray.dir_x = ray.direction.x();
  rh.ray.dir_y = ray.direction.y();
  rh.ray.dir_z = ray.direction.z();
  rh.ray.tnear = 0.0f;
  rh.ray.tfar = std::numeric_limits<float>::infinity();
  rh.ray.mask = 0xFFFFFFFFu;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  return rh;
}

}  // namespace

RayCaster::RayCaster() {
  device_ = rtcNewDevice(kDeviceConfig);
  if (device_ == nullptr) {
    device_error_ = "cannot create the Embree device";
    return;
  }
  scene_ = rtcNewScene(device_);
  if (scene_ == nullptr) device_error_ = "cannot create the Embree scene";
}

RayCaster::~RayCaster() {
  if (scene_) rtcReleaseScene(scene_);
  if (device_) rtcReleaseDevice(device_);
}

bool RayCaster::add_mesh(const Mesh& mesh, const Eigen::Vector3d& origin, std::string* error) {
  if (!device_error_.empty()) return fail(error, device_error_);
  if (committed_) return fail(error, "ray caster: add_mesh after commit");
  const std::string problem = mesh.validate();
  if (!problem.empty()) return fail(error, "ray caster: " + problem);
  const uint32_t id = geometries_++;            // counted even when empty: ids = call order
  if (mesh.triangle_count() == 0) return true;  // nothing to hit

  RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
  if (geometry == nullptr) return fail(error, "cannot create an Embree geometry");
  // rtcSetNewGeometryBuffer pads the buffer as Embree's SIMD loads need.
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.vertex_count()));
  auto* indices = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), mesh.triangle_count()));
  if (vertices == nullptr || indices == nullptr) {
    rtcReleaseGeometry(geometry);
    return fail(error, "Embree cannot allocate the mesh buffers");
  }
  for (std::size_t i = 0; i < mesh.vertex_count(); ++i) {
    const Eigen::Vector3d p = mesh.vertex(i) - origin;
    for (int k = 0; k < 3; ++k) vertices[3 * i + k] = static_cast<float>(p[k]);
  }
  std::copy(mesh.triangles.begin(), mesh.triangles.end(), indices);
  rtcCommitGeometry(geometry);
  rtcAttachGeometryByID(scene_, geometry, id);
  rtcReleaseGeometry(geometry);
  return true;
}

bool RayCaster::commit(std::string* error) {
  if (!device_error_.empty()) return fail(error, device_error_);
  rtcCommitScene(scene_);
  const RTCError code = rtcGetDeviceError(device_);
  if (code != RTC_ERROR_NONE) {
    return fail(error, "Embree scene build failed (code " + std::to_string(code) + ")");
  }
  committed_ = true;
  return true;
}

bool RayCaster::cast(const std::vector<Ray>& rays, std::vector<RayHit>* hits, std::string* error) const {
  if (!committed_) return fail(error, "ray caster: cast before commit");
  if (hits == nullptr) return fail(error, "ray caster: null output");
  hits->assign(rays.size(), RayHit{});
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  std::vector<RTCRayHit> batch(kRayBatch);
  for (std::size_t start = 0; start < rays.size(); start += kRayBatch) {
    const std::size_t count = std::min(kRayBatch, rays.size() - start);
    for (std::size_t i = 0; i < count; ++i) batch[i] = to_embree(rays[start + i]);
    rtcIntersect1M(scene_, &context, batch.data(), static_cast<unsigned>(count), sizeof(RTCRayHit));
    for (std::size_t i = 0; i < count; ++i) {
      if (batch[i].hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;
      (*hits)[start + i].distance = batch[i].ray.tfar;
      (*hits)[start + i].geometry = static_cast<int32_t>(batch[i].hit.geomID);
    }
  }
  return true;
}

}  // namespace spinhash::host
