#include "spinhash/vehicle_class.hpp"

#include "spinhash/blob_format.hpp"

namespace spinhash {
namespace {

#define SPINHASH_CLASS_NAME(id, Name, name, group, help) name,
constexpr const char* kClassNames[] = {SPINHASH_VEHICLE_CLASSES(SPINHASH_CLASS_NAME)};
#undef SPINHASH_CLASS_NAME
static_assert(sizeof(kClassNames) / sizeof(kClassNames[0]) == kVehicleClassCount,
              "SPINHASH_CLASS_COUNT matches SPINHASH_VEHICLE_CLASSES");
#define SPINHASH_CLASS_ID(id, Name, name, group, help) id,
constexpr uint32_t kClassIds[] = {SPINHASH_VEHICLE_CLASSES(SPINHASH_CLASS_ID)};
#undef SPINHASH_CLASS_ID
#define SPINHASH_CLASS_GROUP(id, Name, name, group, help) VehicleGroup::k##group,
constexpr VehicleGroup kClassGroups[] = {SPINHASH_VEHICLE_CLASSES(SPINHASH_CLASS_GROUP)};
#undef SPINHASH_CLASS_GROUP

#define SPINHASH_GROUP_NAME(id, Name, name, help) name,
constexpr const char* kGroupNames[] = {SPINHASH_VEHICLE_GROUPS(SPINHASH_GROUP_NAME)};
#undef SPINHASH_GROUP_NAME
static_assert(sizeof(kGroupNames) / sizeof(kGroupNames[0]) == kVehicleGroupCount,
              "SPINHASH_GROUP_COUNT matches SPINHASH_VEHICLE_GROUPS");
#define SPINHASH_GROUP_ID(id, Name, name, help) id,
constexpr uint32_t kGroupIds[] = {SPINHASH_VEHICLE_GROUPS(SPINHASH_GROUP_ID)};
#undef SPINHASH_GROUP_ID

constexpr bool ids_are_positions(const uint32_t* ids, uint32_t count) {
  for (uint32_t k = 0; k < count; ++k)
    if (ids[k] != k) return false;
  return true;
}
static_assert(ids_are_positions(kClassIds, kVehicleClassCount),
              "class ids run 0, 1, 2, ... in list order (the name table is indexed by id)");
static_assert(ids_are_positions(kGroupIds, kVehicleGroupCount),
              "group ids run 0, 1, 2, ... in list order (the name table is indexed by id)");

constexpr uint32_t kMaxNameBytes = 32;  // longer names match nothing

bool same_name(const char* a, const char* b) {
  for (uint32_t k = 0; k < kMaxNameBytes; ++k) {
    if (a[k] != b[k]) return false;
    if (a[k] == '\0') return true;
  }
  return false;
}

// The id of `name` in names[0 .. count), or count.
uint32_t find_name(const char* name, const char* const* names, uint32_t count) {
  if (name == nullptr) return count;
  for (uint32_t id = 0; id < count; ++id)
    if (same_name(name, names[id])) return id;
  return count;
}

}  // namespace

const char* vehicle_class_name(uint32_t id) noexcept {
  return id < kVehicleClassCount ? kClassNames[id] : "unknown";
}

bool parse_vehicle_class(const char* name, VehicleClass* out) noexcept {
  const uint32_t id = find_name(name, kClassNames, kVehicleClassCount);
  if (id == kVehicleClassCount) return false;
  if (out != nullptr) *out = static_cast<VehicleClass>(id);
  return true;
}

VehicleGroup vehicle_group_of(uint32_t class_id) noexcept {
  return class_id < kVehicleClassCount ? kClassGroups[class_id] : VehicleGroup::kNone;
}

VehicleGroup vehicle_group_of(uint32_t class_id, uint32_t own_group) noexcept {
  return model_group_allowed(class_id, own_group) && own_group != 0u ? static_cast<VehicleGroup>(own_group)
                                                                     : vehicle_group_of(class_id);
}

bool model_group_allowed(uint32_t class_id, uint32_t own_group) noexcept {
  return own_group == 0u || (own_group < kVehicleGroupCount && class_id < kVehicleClassCount &&
                             vehicle_group_of(class_id) == VehicleGroup::kNone);
}

VehicleGroup model_group(const blob::ModelRecord& model) noexcept {
  return vehicle_group_of(model.vehicle_class, model.vehicle_group);
}

VehicleGroup vehicle_group_of(VehicleClass vehicle_class) noexcept {
  return vehicle_group_of(static_cast<uint32_t>(vehicle_class));
}

const char* vehicle_group_name(uint32_t id) noexcept {
  return id < kVehicleGroupCount ? kGroupNames[id] : "unknown";
}

bool parse_vehicle_group(const char* name, VehicleGroup* out) noexcept {
  const uint32_t id = find_name(name, kGroupNames, kVehicleGroupCount);
  if (id == kVehicleGroupCount) return false;
  if (out != nullptr) *out = static_cast<VehicleGroup>(id);
  return true;
}

}  // namespace spinhash
