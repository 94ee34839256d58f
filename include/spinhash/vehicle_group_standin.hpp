// STAND-IN until the group column of vehicle_classes.h lands (another
// branch adds vehicle_group_of()); deleted at that merge. Groups: none,
// light, heavy, armoured.
#pragma once
#include <cstdint>

#include "spinhash/vehicle_class.hpp"

namespace spinhash {

enum class VehicleGroup : uint8_t { kNone = 0, kLight = 1, kHeavy = 2, kArmoured = 3 };
constexpr uint32_t kVehicleGroupCount = 4;

inline VehicleGroup vehicle_group_of(VehicleClass c) {
  switch (c) {
    case VehicleClass::kSedan:
    case VehicleClass::kVan:
    case VehicleClass::kPickup:
    case VehicleClass::kSuv:
    case VehicleClass::kCar: return VehicleGroup::kLight;
    case VehicleClass::kTruck:
    case VehicleClass::kBus: return VehicleGroup::kHeavy;
    case VehicleClass::kTracked:
    case VehicleClass::kApc: return VehicleGroup::kArmoured;
    default: return VehicleGroup::kNone;
  }
}

inline const char* vehicle_group_name(uint32_t id) {
  constexpr const char* kNames[] = {"none", "light", "heavy", "armoured"};
  return id < kVehicleGroupCount ? kNames[id] : "unknown";
}

}  // namespace spinhash
