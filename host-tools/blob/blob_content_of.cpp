#include "blob/blob_content_of.hpp"

namespace spinhash {
namespace host {
namespace {

template <typename T>
std::vector<T> copy(const T* data, uint64_t count) {
  return std::vector<T>(data, data + count);
}

}  // namespace

BlobContent content_of(const Database& db) {
  BlobContent c;
  const blob::Params& p = db.params();
  const uint64_t n = p.feature_count;
  c.params = p;
  for (uint32_t m = 0; m < p.model_count; ++m) c.models.push_back(db.model(m));
  c.positions = copy(db.positions(), 3u * n);
  c.normals = copy(db.normals(), 3u * n);
  c.feature_models = copy(db.feature_models(), n);
  c.spins = copy(db.spin(0), n * db.spin_dims());
  c.grid_offsets = copy(db.grid_offsets(), p.grid_offset_count);
  c.lsh_bits = copy(db.lsh_bits(0), static_cast<uint64_t>(p.lsh_tables) * p.lsh_bits);
  c.lsh_offsets = copy(db.lsh_offsets(0), static_cast<uint64_t>(p.lsh_tables) * (p.lsh_buckets + 1ull));
  c.lsh_entries = copy(db.lsh_entries(), static_cast<uint64_t>(p.lsh_tables) * n);
  c.nearest_field = copy(db.nearest_field(), p.field_entry_count);
  const Calibration& cal = db.calibration();
  c.calibration.header = cal.header();
  c.calibration.passes.clear();
  c.calibration.cells.clear();
  for (uint32_t i = 0; i < cal.pass_count(); ++i) {
    const blob::CalibrationPass& rec = cal.pass_record(i);
    c.calibration.passes.push_back(rec);
    for (uint32_t l = 1; l <= kCalibratedLevels; ++l)
      for (uint32_t b = 0; b < cal.band_count(); ++b)
        c.calibration.cells.push_back(
            *cal.cell(static_cast<AnswerPass>(rec.pass), static_cast<AnswerLevel>(l), b));
  }
  return c;
}

}  // namespace host
}  // namespace spinhash
