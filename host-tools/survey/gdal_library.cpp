#include "survey/gdal_library.hpp"

#include <dlfcn.h>

#include <mutex>

namespace spinhash::survey {
namespace {

struct Loaded {
  GdalLibrary library;
  std::string error;  // empty when loaded
};

Loaded load() {
  Loaded out;
  void* handle = dlopen(SPINHASH_GDAL_SONAME, RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* why = dlerror();
    out.error = std::string("GDAL (" SPINHASH_GDAL_SONAME ") cannot be loaded") +
                (why ? std::string(": ") + why : "");
    return out;
  }
#define SPINHASH_GDAL_RESOLVE(name)                                             \
  out.library.name = reinterpret_cast<decltype(&::name)>(dlsym(handle, #name)); \
  if (out.library.name == nullptr) {                                            \
    out.error = "GDAL (" SPINHASH_GDAL_SONAME ") has no function " #name;       \
    return out;                                                                 \
  }
  SPINHASH_GDAL_FUNCTIONS(SPINHASH_GDAL_RESOLVE)
#undef SPINHASH_GDAL_RESOLVE
  out.library.GDALAllRegister();
  return out;  // the handle stays open: the functions are used until exit
}

}  // namespace

const GdalLibrary* gdal_library(std::string* error) {
  static std::once_flag once;
  static Loaded loaded;
  std::call_once(once, [] { loaded = load(); });
  if (!loaded.error.empty()) {
    *error = loaded.error;
    return nullptr;
  }
  return &loaded.library;
}

}  // namespace spinhash::survey
