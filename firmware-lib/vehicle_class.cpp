#include "spinhash/vehicle_class.hpp"

namespace spinhash {
namespace {

#define SPINHASH_CLASS_NAME(id, Name, name, help) name,
constexpr const char* kClassNames[] = {SPINHASH_VEHICLE_CLASSES(SPINHASH_CLASS_NAME)};
#undef SPINHASH_CLASS_NAME
static_assert(sizeof(kClassNames) / sizeof(kClassNames[0]) == kVehicleClassCount,
              "SPINHASH_CLASS_COUNT matches SPINHASH_VEHICLE_CLASSES");
#define SPINHASH_CLASS_ID(id, Name, name, help) id,
constexpr uint32_t kClassIds[] = {SPINHASH_VEHICLE_CLASSES(SPINHASH_CLASS_ID)};
#undef SPINHASH_CLASS_ID
constexpr bool ids_are_positions() {
  for (uint32_t k = 0; k < kVehicleClassCount; ++k)
    if (kClassIds[k] != k) return false;
  return true;
}
static_assert(ids_are_positions(),
              "class ids run 0, 1, 2, ... in list order (the name table is indexed by id)");

constexpr uint32_t kMaxClassNameBytes = 32;  // longer names match nothing

bool same_name(const char* a, const char* b) {
  for (uint32_t k = 0; k < kMaxClassNameBytes; ++k) {
    if (a[k] != b[k]) return false;
    if (a[k] == '\0') return true;
  }
  return false;
}

}  // namespace

const char* vehicle_class_name(uint32_t id) noexcept {
  return id < kVehicleClassCount ? kClassNames[id] : "unknown";
}

bool parse_vehicle_class(const char* name, VehicleClass* out) noexcept {
  if (name == nullptr) return false;
  for (uint32_t id = 0; id < kVehicleClassCount; ++id) {
    if (!same_name(name, kClassNames[id])) continue;
    if (out != nullptr) *out = static_cast<VehicleClass>(id);
    return true;
  }
  return false;
}

}  // namespace spinhash
