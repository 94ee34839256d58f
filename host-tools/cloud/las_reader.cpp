#include "cloud/las_reader.hpp"

#include <exception>

#include "cloud/cloud_error.hpp"
#include "cloud/las_points.hpp"

namespace spinhash::host {
namespace {

void read_all(LasRecordReader& reader, LasCloud* out) {
  const LasHeader& h = reader.header();
  const size_t batch = las_batch_records(h);
  std::vector<uint8_t> records(batch * h.record_length);
  double xyz[3];
  for (size_t n; (n = reader.read(records.data(), batch)) > 0;) {
    for (size_t i = 0; i < n; ++i) {
      const uint8_t* r = records.data() + i * h.record_length;
      las_record_xyz(h, r, xyz);
      out->xyz.insert(out->xyz.end(), xyz, xyz + 3);
      out->classification.push_back(las_record_class(h, r));
    }
  }
}

}  // namespace

bool parse_las(const std::string& bytes, LasCloud* out, std::string* error) {
  *out = LasCloud{};
  try {
    LasRecordReader reader(memory_source(bytes), laz::LayerChoice::kPipeline);
    out->header = reader.header();
    out->crs = reader.crs();
    read_all(reader, out);
    return true;
  } catch (const std::exception& e) {
    *out = LasCloud{};
    if (error) *error = e.what();
    return false;
  }
}

}  // namespace spinhash::host
