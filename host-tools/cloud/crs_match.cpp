#include "cloud/crs_match.hpp"

#include "cloud/crs_proj.hpp"

namespace spinhash::host {
namespace {

bool equivalent(const PJ* a, const PJ* b) {
  return proj_is_equivalent_to_with_ctx(crs_proj::context(), a, b,
                                        PJ_COMP_EQUIVALENT_EXCEPT_AXIS_ORDER_GEOGCRS) != 0;
}

}  // namespace

bool same_crs(const Crs& a, const Crs& b) {
  const std::string da = a.proj_definition(), db = b.proj_definition();
  if (da.empty() || db.empty()) return false;
  if (da == db) return true;
  const crs_proj::Parts pa = crs_proj::split(crs_proj::create(da));
  const crs_proj::Parts pb = crs_proj::split(crs_proj::create(db));
  if (!pa.horizontal || !pb.horizontal || !equivalent(pa.horizontal.get(), pb.horizontal.get())) return false;
  return !pa.vertical || !pb.vertical || equivalent(pa.vertical.get(), pb.vertical.get());
}

}  // namespace spinhash::host
