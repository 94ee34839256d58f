// How far the members of a vehicle class vary in size, and whether a scan's
// measured shape lies within that range (not in the paper). The class
// margin says which of the database's classes explains a scan best, not
// whether any of them is this vehicle's: a real 1.2 m tall racing saloon
// lies between the fleet's sedans and vans and was named a van,
// confidently. The envelope is the class's
// own members' boxes, read from the database; the tolerances come from what
// an airborne scan measures well (the top, the terrain) and badly (the
// bottom of a side, the hidden end of an occluded vehicle).
#pragma once
#include <cstdint>

#include "match/likelihood.hpp"
#include "match/oriented_point.hpp"
#include "spinhash/config.hpp"
#include "spinhash/database.hpp"

namespace spinhash {

// The range of the members' model boxes (model frame, z up; length and width
// the longer and shorter horizontal side of each box).
struct ClassEnvelope {
  uint32_t members = 0;
  float length_max = 0.0f;  // m
  float width_max = 0.0f;   // m
  float height_min = 0.0f;  // m: box height (the model cloud's top above its lowest point)
  float height_max = 0.0f;  // m
};

// The envelope of the database's models of `vehicle_class` (O(models), no
// state: the blob holds every box). members == 0 when the class has none.
ClassEnvelope class_envelope(const Database& db, uint32_t vehicle_class);
// The same over the database's models of `group` (model_group(), vehicle_class.hpp).
ClassEnvelope group_envelope(const Database& db, uint32_t group);

// The scan's shape as an airborne scan measures it, under the class
// leader's pose. Length and width are the query features' spans along the
// longer and shorter horizontal axis of the pose (the second outermost
// feature each side: one stray is noise), lower bounds where an occluder
// hides an end. The height is the top above the terrain when the extractor
// found terrain: well measured both ways. Without terrain it is the scan's
// vertical span lifted by `bottom_gap`, how far above the leader's box
// bottom (under the pose) the scan's lowest features stop: the top above
// that bottom, which says the vehicle's height only when the scan shows its
// lower part (a van's pose sunk under a saloon's scan leaves the van's
// lower half without points).
struct ScanShape {
  float length = 0.0f;
  float width = 0.0f;
  float height = 0.0f;
  bool on_terrain = false;  // height from the terrain (else from the leader's box bottom)
  float bottom_gap = 0.0f;  // m, without terrain: the second lowest feature above the leader's box bottom
  float noise = 0.0f;       // m, sigma along the ray: the terrain's roughness, else sigma_surface
  float spacing = 0.0f;     // m, 1 / sqrt(density): the scan's point spacing on the vehicle, about
  float density = 0.0f;     // points per m^2 of the model top the scan spans (scan_density())
};

// top_above_terrain < 0: no terrain (FeatureSet::top_above_terrain);
// density: object points per m^2 of the model top the scan spans
// (scan_density()); `leader` and `pose`: the class's best model and its pose.
ScanShape measure_scan(const QueryFeatures& query, const blob::ModelRecord& leader, const RigidPose& pose,
                       float top_above_terrain, float terrain_sigma, float sigma_surface, float density);

// No measure of the scan says it is not of the class: not longer or wider
// than the longest or widest member by more than the scan's noise reaches
// beyond both ends (`end_tolerance` each, max_extent_overhang), not taller
// than the tallest member by more than the noise and the model boxes' unseen
// bottom, and not lower than the lowest member by more than the roof's
// sampling. Without terrain the scan must also show the vehicle's lower
// part (bottom_gap within a side's sample spacing): a scan that shows
// neither terrain nor the lower sides does not measure the height, and a
// van's roof explains a saloon's; and below min_height_density a scan
// without terrain never measures the height (that allowance is coarser than
// the step between classes). False for a class without members.
bool within_envelope(const ScanShape& scan, const ClassEnvelope& env, float end_tolerance,
                     const ClassesParams& p);

}  // namespace spinhash
