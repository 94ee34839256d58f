// Field-by-field byte swapping of the blob's structs (char arrays and
// reserved bytes are left as they are). No-ops unless `swap` is true.
#pragma once
#include "spinhash/blob_format.hpp"

namespace spinhash {
namespace host {

void swap_fields(blob::Header* h, bool swap);
void swap_fields(blob::SectionEntry* e, bool swap);
void swap_fields(blob::Params* p, bool swap);
void swap_fields(blob::ModelRecord* m, bool swap);
void swap_fields(blob::LshBit* b, bool swap);
void swap_fields(blob::CalibrationHeader* h, bool swap);
void swap_fields(blob::CalibrationPass* p, bool swap);
void swap_fields(blob::CalibrationCell* c, bool swap);

}  // namespace host
}  // namespace spinhash
