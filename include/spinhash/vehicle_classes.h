/* The one list of vehicle classes a database model can carry (blob format 4,
 * ModelRecord::vehicle_class), and the groups the classes fall into. The
 * class ids are stored in blobs: entries are only ever appended, never
 * renumbered. Everything that names a class or a group is produced from
 * these lists: spinhash::VehicleClass, vehicle_class_name(),
 * vehicle_group_of() and vehicle_group_name() (vehicle_class.hpp), the C
 * API's spinhash_class_name(), spinhash_class_group() and
 * spinhash_group_name(), the build's manifest and folder names, the CLI's
 * JSON, `spinhash info` and Python's spinhash.CLASS_NAMES,
 * spinhash.CLASS_GROUPS and spinhash.GROUP_NAMES.
 *
 * The hierarchy of an answer: vehicle, then group, then class, then model.
 * The group of a model is its class's, a function of the class, so
 * regrouping a class needs no new blob. Only a model of a class in no group
 * may carry a group of its own (ModelRecord::vehicle_group, the build
 * manifest's third word): an "other" buggy is a light vehicle.
 *
 * Groups: G(id, Name, "name", "what it covers"). Classes: C(id, Name,
 * "name", Group, "what it covers"), Group the Name of a group.
 * "other" is in no group: it gathers vehicles of every size (a buggy of
 * half a tonne, a farm tractor, a semi-trailer, a forklift), so no group
 * is true of all its members, and an "other" answer without a group of its
 * model goes from vehicle straight to class.
 *
 * Compiles as C99: no // comments inside the lists. */
#ifndef SPINHASH_VEHICLE_CLASSES_H
#define SPINHASH_VEHICLE_CLASSES_H

#define SPINHASH_VEHICLE_GROUPS(G)                                                               \
  G(0, None, "none", "no group: unclassified, or a class whose members span the groups (other)") \
  G(1, Light, "light", "light vehicle up to 3.5 t: cars, SUVs, vans and minibuses, pickups")     \
  G(2, Heavy, "heavy", "heavy vehicle over 3.5 t: lorries, tractor units, buses and coaches")    \
  G(3, Armoured, "armoured", "tracked or armoured vehicle: tanks, tracked carriers, wheeled APCs")

/* Number of groups; ids are 0 .. SPINHASH_GROUP_COUNT - 1. */
#define SPINHASH_GROUP_COUNT 4

#define SPINHASH_VEHICLE_CLASSES(C)                                                    \
  C(0, Unclassified, "unclassified", None, "no class was given at build time")         \
  C(1, Sedan, "sedan", Light, "passenger car: saloon, hatchback, estate, coupe")       \
  C(2, Van, "van", Light, "panel van, minibus, MPV")                                   \
  C(3, Pickup, "pickup", Light, "pickup truck: cab and open bed")                      \
  C(4, Truck, "truck", Heavy, "lorry, box truck, tractor unit")                        \
  C(5, Bus, "bus", Heavy, "bus, coach")                                                \
  C(6, Tracked, "tracked", Armoured, "tracked vehicle: tank, tracked carrier, digger") \
  C(7, Apc, "apc", Armoured, "wheeled armoured vehicle")                               \
  C(8, Suv, "suv", Light, "sport utility vehicle, off-roader, jeep")                   \
  C(9, Car, "car", Light, "passenger car of unknown body type")                        \
  C(10, Other, "other", None, "a vehicle of none of these classes (tractor, trailer, buggy)")

/* Number of classes; ids are 0 .. SPINHASH_CLASS_COUNT - 1. */
#define SPINHASH_CLASS_COUNT 11

#endif /* SPINHASH_VEHICLE_CLASSES_H */
