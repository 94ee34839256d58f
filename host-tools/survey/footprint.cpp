#include "survey/footprint.hpp"

#include <proj.h>

#include <cmath>
#include <stdexcept>

#include "pipeline/json_line.hpp"

namespace spinhash::survey {

Ring footprint(const SceneObject& o, double metres_per_unit) {
  const double h = static_cast<double>(o.heading_deg) * M_PI / 180.0;
  const double ux = std::cos(h), uy = std::sin(h);
  const double l = 0.5 * static_cast<double>(o.extent[0]) / metres_per_unit,
               w = 0.5 * static_cast<double>(o.extent[1]) / metres_per_unit;
  const double corner[4][2] = {{-l, -w}, {l, -w}, {l, w}, {-l, w}};
  Ring r;
  for (int i = 0; i < 4; ++i) {
    r[i][0] = o.center[0] + corner[i][0] * ux - corner[i][1] * uy;
    r[i][1] = o.center[1] + corner[i][0] * uy + corner[i][1] * ux;
  }
  r[4] = r[0];
  return r;
}

std::string ring_json(const Ring& ring, int digits) {
  std::string s = "[";
  for (size_t i = 0; i < ring.size(); ++i)
    s += std::string(i ? "," : "") + "[" + pipeline::json_number(ring[i][0], digits) + "," +
         pipeline::json_number(ring[i][1], digits) + "]";
  return s + "]";
}

struct ToWgs84::Impl {
  PJ_CONTEXT* ctx = nullptr;
  PJ* pj = nullptr;
};

ToWgs84::ToWgs84(const std::string& definition) : impl_(std::make_unique<Impl>()) {
  impl_->ctx = proj_context_create();
  proj_log_level(impl_->ctx, PJ_LOG_NONE);  // failures come back as the exception's message
  PJ* raw = proj_create_crs_to_crs(impl_->ctx, definition.c_str(), "EPSG:4326", nullptr);
  if (raw != nullptr) {
    impl_->pj = proj_normalize_for_visualization(impl_->ctx, raw);  // lon, lat order
    proj_destroy(raw);
  }
  if (impl_->pj == nullptr) {
    const std::string why = proj_context_errno_string(impl_->ctx, proj_context_errno(impl_->ctx));
    proj_context_destroy(impl_->ctx);
    throw std::runtime_error("PROJ cannot transform " + definition.substr(0, 80) + " to WGS 84: " + why);
  }
}

ToWgs84::~ToWgs84() {
  proj_destroy(impl_->pj);
  proj_context_destroy(impl_->ctx);
}

Ring ToWgs84::transform(const Ring& native) const {
  Ring out;
  for (size_t i = 0; i < native.size(); ++i) {
    const PJ_COORD c = proj_trans(impl_->pj, PJ_FWD, proj_coord(native[i][0], native[i][1], 0, 0));
    out[i][0] = c.xy.x, out[i][1] = c.xy.y;  // NaN (null in JSON) when out of the CRS's domain
  }
  return out;
}

}  // namespace spinhash::survey
