// A LAZ writer for benchmark tiles only (research tooling, not shipped):
// point format 0, compressor 2 (pointwise chunked), POINT10 version 2, the
// mirror of host-tools/cloud/laz/ (arithmetic encoder, integer corrector,
// POINT10 v2 predictor, chunk table). The shared samples hold no format-0
// tile large enough to time a decoder on; this makes one from real points.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cloud/las_header.hpp"

namespace spinhash::experiment {

// Writes `records` (20-byte format-0 records) as a LAS 1.2 LAZ file with the
// scale, offset and bounds of `h`. False with *error on a write failure.
bool write_format0_laz(const std::string& path, const host::LasHeader& h, const std::vector<uint8_t>& records,
                       uint32_t chunk_size, std::string* error);

}  // namespace spinhash::experiment
