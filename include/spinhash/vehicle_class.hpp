// Vehicle classes (vehicle_classes.h is the list): the level an answer can
// give when the scan does not tell one model from another.
#pragma once
#include <cstdint>

#include "spinhash/vehicle_classes.h"

namespace spinhash {

enum class VehicleClass : uint8_t {
#define SPINHASH_CLASS_ENUM(id, Name, name, help) k##Name = id,
  SPINHASH_VEHICLE_CLASSES(SPINHASH_CLASS_ENUM)
#undef SPINHASH_CLASS_ENUM
};
constexpr uint32_t kVehicleClassCount = SPINHASH_CLASS_COUNT;

// "sedan", ...; "unknown" for an id outside the list.
const char* vehicle_class_name(uint32_t id) noexcept;
// The class named `name` (bytewise, lower case), or false.
bool parse_vehicle_class(const char* name, VehicleClass* out) noexcept;

}  // namespace spinhash
