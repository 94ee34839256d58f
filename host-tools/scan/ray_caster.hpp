// Embree wrapper: a scene of triangle meshes and batched closest-hit
// queries. Device and scene are owned (RAII); results are deterministic.
#pragma once

#include "mesh/mesh.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

// Embree's opaque handles, so users of this header need not include Embree.
typedef struct RTCDeviceTy* RTCDevice;
typedef struct RTCSceneTy* RTCScene;

namespace spinhash::host {

struct Ray {
  Eigen::Vector3f origin;
  Eigen::Vector3f direction;  // need not be unit; distance is in its units
};

struct RayHit {
  float distance = std::numeric_limits<float>::infinity();  // infinity: missed
  int32_t geometry = -1;  // which add_mesh call (0, 1, ...) made the surface hit; -1: missed
  bool hit() const { return geometry >= 0; }
};

class RayCaster {
 public:
  RayCaster();
  ~RayCaster();
  RayCaster(const RayCaster&) = delete;
  RayCaster& operator=(const RayCaster&) = delete;

  // Adds a mesh whose vertices are first shifted by -origin (so the float
  // scene stays precise far from the origin). Call before commit().
  bool add_mesh(const Mesh& mesh, const Eigen::Vector3d& origin, std::string* error);
  // Builds the acceleration structure; cast() needs it.
  bool commit(std::string* error);
  // Closest hit of every ray, in the shifted frame of add_mesh.
  bool cast(const std::vector<Ray>& rays, std::vector<RayHit>* hits, std::string* error) const;

 private:
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  std::string device_error_;
  uint32_t geometries_ = 0;
  bool committed_ = false;
};

}  // namespace spinhash::host
