// PROJ's objects for the CRS code of cloud/ (crs_resolve, crs_units,
// crs_match, crs_transform): one PROJ context per thread, opened once (its
// database costs a few hundred ms to open, a CRS then a few ms), objects
// freed by their owners, and a CRS split into its horizontal and vertical
// parts. PROJ objects are never shared between threads.
#pragma once

#include <proj.h>

#include <memory>
#include <string>

namespace spinhash::host::crs_proj {

using Object = std::unique_ptr<PJ, decltype(&proj_destroy)>;

// This thread's context (logging off: failures come back as messages).
PJ_CONTEXT* context();

Object none();
Object make(PJ* p);
// proj_create on a definition (EPSG code, WKT, PROJ string); null if PROJ cannot read it.
Object create(const std::string& definition);
// A bound CRS (a WKT with TOWGS84) stands for its source CRS.
Object unbound(Object crs);

struct Parts {
  Object horizontal = none(), vertical = none();
};

// A compound CRS's two parts; a vertical CRS alone; otherwise the CRS as
// the horizontal part. Bound parts are unbound.
Parts split(Object whole);

// The EPSG code in an object's own ID (AUTHORITY["EPSG", n] or the code it
// was made from); 0 when it has none. Never searches the database.
uint32_t epsg_id(const PJ* object);

// The last error of this thread's context, as text.
std::string last_error();

}  // namespace spinhash::host::crs_proj
