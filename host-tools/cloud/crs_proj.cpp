#include "cloud/crs_proj.hpp"

#include <cstdlib>
#include <cstring>

namespace spinhash::host::crs_proj {
namespace {

struct ThreadContext {
  PJ_CONTEXT* ctx = nullptr;
  ThreadContext() {
    ctx = proj_context_create();
    if (ctx != nullptr) proj_log_level(ctx, PJ_LOG_NONE);
  }
  ~ThreadContext() { proj_context_destroy(ctx); }
  ThreadContext(const ThreadContext&) = delete;
  ThreadContext& operator=(const ThreadContext&) = delete;
};

}  // namespace

PJ_CONTEXT* context() {
  thread_local ThreadContext t;
  return t.ctx;
}

Object none() { return Object(nullptr, proj_destroy); }

Object make(PJ* p) { return Object(p, proj_destroy); }

Object create(const std::string& definition) {
  if (definition.empty()) return none();
  return make(proj_create(context(), definition.c_str()));
}

Object unbound(Object crs) {
  if (crs && proj_get_type(crs.get()) == PJ_TYPE_BOUND_CRS)
    return make(proj_get_source_crs(context(), crs.get()));
  return crs;
}

Parts split(Object whole) {
  Parts p;
  whole = unbound(std::move(whole));
  if (!whole) return p;
  const PJ_TYPE type = proj_get_type(whole.get());
  if (type == PJ_TYPE_COMPOUND_CRS) {
    p.horizontal = unbound(make(proj_crs_get_sub_crs(context(), whole.get(), 0)));
    p.vertical = unbound(make(proj_crs_get_sub_crs(context(), whole.get(), 1)));
  } else if (type == PJ_TYPE_VERTICAL_CRS) {
    p.vertical = std::move(whole);
  } else {
    p.horizontal = std::move(whole);
  }
  return p;
}

uint32_t epsg_id(const PJ* object) {
  if (object == nullptr) return 0;
  const char* auth = proj_get_id_auth_name(object, 0);
  const char* code = proj_get_id_code(object, 0);
  if (auth == nullptr || code == nullptr || std::strcmp(auth, "EPSG") != 0) return 0;
  char* end = nullptr;
  const unsigned long v = std::strtoul(code, &end, 10);
  return end != code && *end == '\0' && v < 0xffffffffu ? static_cast<uint32_t>(v) : 0;
}

std::string last_error() {
  const int e = proj_context_errno(context());
  const char* s = e != 0 ? proj_context_errno_string(context(), e) : nullptr;
  return s != nullptr ? s : "not a CRS PROJ knows";
}

}  // namespace spinhash::host::crs_proj
