// Ingestion and resampling: re-centring in double, density equalisation and
// uniform basis-point selection, each over a CellGrid.
#pragma once
#include <cstdint>

#include "geometry/cell_grid.hpp"
#include "spinhash/features.hpp"

namespace spinhash {

// Mean of the finite points in double (airborne clouds are georeferenced:
// UTM northings near 4e6 m leave float a 0.25 m step). Takes `keep` points
// spread evenly over the cloud (deterministic thinning; all when keep >=
// count), writes the finite ones minus that mean as float into out and
// returns how many were finite.
uint32_t recentre(const CloudView& cloud, uint32_t keep, double origin[3], float* out);

// One point per occupied cell of `grid` (built over `points`): the cell centroid.
uint32_t equalise_density(const CellGrid& grid, const float* points, float* out);

// One basis point per occupied cell of `grid`: the oriented point nearest the
// centroid of the cell's oriented points. Writes point indices; returns count.
uint32_t select_basis_points(const CellGrid& grid, const float* points, const uint8_t* has_normal,
                             uint32_t* out);

// Keeps `keep` of the n indices, evenly spread (deterministic thinning).
uint32_t thin_evenly(uint32_t* indices, uint32_t n, uint32_t keep);

}  // namespace spinhash
