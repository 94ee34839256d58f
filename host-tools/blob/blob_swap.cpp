#include "blob/blob_swap.hpp"

#include "blob/byte_order.hpp"

namespace spinhash {
namespace host {

void swap_fields(blob::Header* h, bool swap) {
  swap_in_place(&h->version, swap);
  swap_in_place(&h->byte_order, swap);
  swap_in_place(&h->total_size, swap);
  swap_in_place(&h->config_fingerprint, swap);
  swap_in_place(&h->section_count, swap);
  swap_in_place(&h->header_crc, swap);
}

void swap_fields(blob::SectionEntry* e, bool swap) {
  swap_in_place(&e->id, swap);
  swap_in_place(&e->reserved, swap);
  swap_in_place(&e->offset, swap);
  swap_in_place(&e->size, swap);
  swap_in_place(&e->crc, swap);
  swap_in_place(&e->reserved2, swap);
}

void swap_fields(blob::Params* p, bool swap) {
  swap_in_place(&p->model_count, swap);
  swap_in_place(&p->feature_count, swap);
  swap_in_place(&p->bins_alpha, swap);
  swap_in_place(&p->bins_beta, swap);
  swap_in_place(&p->lsh_tables, swap);
  swap_in_place(&p->lsh_bits, swap);
  swap_in_place(&p->lsh_buckets, swap);
  swap_in_place(&p->grid_offset_count, swap);
  swap_in_place(&p->cloud_voxel, swap);
  swap_in_place(&p->normal_radius, swap);
  swap_in_place(&p->basis_spacing, swap);
  swap_in_place(&p->support_radius, swap);
  swap_in_place(&p->support_angle_deg, swap);
  swap_in_place(&p->spin_quant_scale, swap);
  swap_in_place(&p->lsh_dc, swap);
  swap_in_place(&p->grid_cell, swap);
  swap_in_place(&p->field_entry_count, swap);
  swap_in_place(&p->field_slots, swap);
  swap_in_place(&p->field_cell, swap);
  swap_in_place(&p->field_reach, swap);
}

void swap_fields(blob::ModelRecord* m, bool swap) {
  swap_in_place(&m->first_feature, swap);
  swap_in_place(&m->feature_count, swap);
  swap_array_in_place(m->grid_dims, swap);
  swap_in_place(&m->grid_offset_base, swap);
  swap_array_in_place(m->grid_origin, swap);
  swap_array_in_place(m->bbox_min, swap);
  swap_array_in_place(m->bbox_max, swap);
  swap_array_in_place(m->field_dims, swap);
  swap_in_place(&m->field_base, swap);
}

void swap_fields(blob::LshBit* b, bool swap) {
  swap_in_place(&b->dim, swap);
  swap_in_place(&b->threshold, swap);
}

void swap_fields(blob::CalibrationHeader* h, bool swap) {
  swap_in_place(&h->pass_count, swap);
  swap_in_place(&h->level_count, swap);
  swap_in_place(&h->band_count, swap);
  swap_in_place(&h->target_precision, swap);
  swap_array_in_place(h->band_min_density, swap);
  swap_in_place(&h->scans_per_model, swap);
  swap_in_place(&h->models_left_out, swap);
  swap_in_place(&h->clutter_scans, swap);
  swap_in_place(&h->scans_per_left_out, swap);
  swap_in_place(&h->seed, swap);
  swap_in_place(&h->clutter, swap);
}

void swap_fields(blob::CalibrationPass* p, bool swap) {
  swap_in_place(&p->pass, swap);
  swap_in_place(&p->source, swap);
  swap_in_place(&p->runs, swap);
  swap_in_place(&p->target_precision, swap);
}

void swap_fields(blob::CalibrationCell* c, bool swap) {
  swap_in_place(&c->threshold, swap);
  swap_in_place(&c->precision, swap);
  swap_in_place(&c->recall, swap);
  swap_in_place(&c->positives, swap);
  swap_in_place(&c->negatives, swap);
  swap_in_place(&c->flagged, swap);
  swap_in_place(&c->state, swap);
  swap_in_place(&c->reserved, swap);
}

}  // namespace host
}  // namespace spinhash
