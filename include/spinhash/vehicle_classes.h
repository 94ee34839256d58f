/* The one list of vehicle classes a database model can carry (blob format 4,
 * ModelRecord::vehicle_class). The class ids are stored in blobs: entries
 * are only ever appended, never renumbered. Everything that names a class
 * is produced from this list: spinhash::VehicleClass and
 * vehicle_class_name() (vehicle_class.hpp), the C API's
 * spinhash_class_name(), the build's manifest and folder names, the CLI's
 * JSON and Python's spinhash.CLASS_NAMES.
 *
 * Entries: C(id, Name, "name", "what it covers")
 *
 * Compiles as C99: no // comments inside the list. */
#ifndef SPINHASH_VEHICLE_CLASSES_H
#define SPINHASH_VEHICLE_CLASSES_H

#define SPINHASH_VEHICLE_CLASSES(C)                                          \
  C(0, Unclassified, "unclassified", "no class was given at build time")     \
  C(1, Sedan, "sedan", "passenger car: saloon, hatchback, estate, coupe")    \
  C(2, Van, "van", "panel van, minibus, MPV")                                \
  C(3, Pickup, "pickup", "pickup truck: cab and open bed")                   \
  C(4, Truck, "truck", "lorry, box truck, tractor unit")                     \
  C(5, Bus, "bus", "bus, coach")                                             \
  C(6, Tracked, "tracked", "tracked vehicle: tank, tracked carrier, digger") \
  C(7, Apc, "apc", "wheeled armoured vehicle")                               \
  C(8, Suv, "suv", "sport utility vehicle, off-roader, jeep")                \
  C(9, Car, "car", "passenger car of unknown body type")                     \
  C(10, Other, "other", "a vehicle of none of these classes (tractor, trailer, buggy)")

/* Number of classes; ids are 0 .. SPINHASH_CLASS_COUNT - 1. */
#define SPINHASH_CLASS_COUNT 11

#endif /* SPINHASH_VEHICLE_CLASSES_H */
