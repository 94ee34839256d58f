// Vehicle classes and their groups (vehicle_classes.h is the list): the
// levels an answer can give when the scan does not tell one model from
// another. The hierarchy: vehicle, then group, then class, then model.
#pragma once
#include <cstdint>

#include "spinhash/vehicle_classes.h"

namespace spinhash {
namespace blob {
struct ModelRecord;
}

enum class VehicleClass : uint8_t {
#define SPINHASH_CLASS_ENUM(id, Name, name, group, help) k##Name = id,
  SPINHASH_VEHICLE_CLASSES(SPINHASH_CLASS_ENUM)
#undef SPINHASH_CLASS_ENUM
};
constexpr uint32_t kVehicleClassCount = SPINHASH_CLASS_COUNT;

enum class VehicleGroup : uint8_t {
#define SPINHASH_GROUP_ENUM(id, Name, name, help) k##Name = id,
  SPINHASH_VEHICLE_GROUPS(SPINHASH_GROUP_ENUM)
#undef SPINHASH_GROUP_ENUM
};
constexpr uint32_t kVehicleGroupCount = SPINHASH_GROUP_COUNT;

// "sedan", ...; "unknown" for an id outside the list.
const char* vehicle_class_name(uint32_t id) noexcept;
// The class named `name` (bytewise, lower case), or false.
bool parse_vehicle_class(const char* name, VehicleClass* out) noexcept;

// The group a class belongs to (its column of vehicle_classes.h);
// VehicleGroup::kNone for an id outside the list.
VehicleGroup vehicle_group_of(VehicleClass vehicle_class) noexcept;
VehicleGroup vehicle_group_of(uint32_t class_id) noexcept;
// A model's group (blob::ModelRecord::vehicle_group): `own_group` where it
// names one and the class is in no group (an "other" buggy is a light
// vehicle, a tractor a heavy one), else the class's.
VehicleGroup vehicle_group_of(uint32_t class_id, uint32_t own_group) noexcept;
// Whether a model of class `class_id` may carry `own_group`: 0 (none of
// its own), or a group id when the class is in no group. A class in a
// group fixes its models' group: one answer per model, whatever the byte.
bool model_group_allowed(uint32_t class_id, uint32_t own_group) noexcept;
// A database model's group: vehicle_group_of(its class, its own group).
VehicleGroup model_group(const blob::ModelRecord& model) noexcept;
// "light", ...; "unknown" for an id outside the list.
const char* vehicle_group_name(uint32_t id) noexcept;
inline const char* vehicle_group_name(VehicleGroup group) noexcept {
  return vehicle_group_name(static_cast<uint32_t>(group));
}
// The group named `name` (bytewise, lower case), or false.
bool parse_vehicle_group(const char* name, VehicleGroup* out) noexcept;

}  // namespace spinhash
