#include "cloud/crs_transform.hpp"

#include <proj.h>

#include <cmath>

#include "cloud/cloud_error.hpp"

namespace spinhash::host {
namespace {

constexpr int kBoundsDensity = 21;  // points per edge when transforming a box (PROJ's advice)

}  // namespace

// Its own context: a source may be read on another thread than it was made on.
struct CrsTransform::Impl {
  PJ_CONTEXT* ctx = nullptr;
  PJ* pj = nullptr;
};

CrsTransform::CrsTransform(const std::string& from, const std::string& to) : impl_(std::make_unique<Impl>()) {
  impl_->ctx = proj_context_create();
  proj_log_level(impl_->ctx, PJ_LOG_NONE);
  PJ* raw = proj_create_crs_to_crs(impl_->ctx, from.c_str(), to.c_str(), nullptr);
  if (raw != nullptr) {
    impl_->pj = proj_normalize_for_visualization(impl_->ctx, raw);  // easting, northing on both sides
    proj_destroy(raw);
  }
  if (impl_->pj == nullptr) {
    const int e = proj_context_errno(impl_->ctx);
    const std::string why = e != 0 ? proj_context_errno_string(impl_->ctx, e) : "no transformation found";
    proj_context_destroy(impl_->ctx);
    throw CloudError("PROJ cannot reproject to the work CRS: " + why);
  }
}

CrsTransform::~CrsTransform() {
  proj_destroy(impl_->pj);
  proj_context_destroy(impl_->ctx);
}

void CrsTransform::apply(double* xyz, size_t n) const {
  for (size_t i = 0; i < n; ++i) {
    double* p = xyz + 3 * i;
    if (!std::isfinite(p[0]) || !std::isfinite(p[1])) continue;
    const PJ_COORD c = proj_trans(impl_->pj, PJ_FWD, proj_coord(p[0], p[1], 0, 0));
    const bool ok = std::isfinite(c.xy.x) && std::isfinite(c.xy.y);
    p[0] = ok ? c.xy.x : NAN;
    p[1] = ok ? c.xy.y : NAN;
  }
}

bool CrsTransform::bounds(const double min[2], const double max[2], double out_min[2],
                          double out_max[2]) const {
  return proj_trans_bounds(impl_->ctx, impl_->pj, PJ_FWD, min[0], min[1], max[0], max[1], &out_min[0],
                           &out_min[1], &out_max[0], &out_max[1], kBoundsDensity) != 0;
}

}  // namespace spinhash::host
