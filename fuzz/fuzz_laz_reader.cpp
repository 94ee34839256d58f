// The LAS/LAZ record reader (header, VLRs, CRS, LASzip VLR, chunk table,
// every item decoder) on arbitrary bytes: it must hand out whole records
// within the declared count or throw a CloudError with a message; never
// crash, hang, or allocate beyond what the bytes can hold. Points are read
// up to kMaxFuzzPoints (a LAZ chunk may legitimately code thousands of
// points a byte), once decoding every layer and once only the pipeline's.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "cloud/byte_source.hpp"
#include "cloud/las_points.hpp"
#include "cloud/point_source.hpp"
#include "fuzz_require.hpp"

namespace {
constexpr size_t kMaxFuzzPoints = 4096;

void read_records(const std::string& bytes, spinhash::host::laz::LayerChoice layers) {
  using namespace spinhash::host;
  try {
    LasRecordReader reader(memory_source(bytes), layers);
    const LasHeader& h = reader.header();
    const size_t batch = las_batch_records(h);
    spinhash::fuzz::require(batch * h.record_length <= kLasBatchBytes + h.record_length,
                            "an oversized batch");
    std::vector<uint8_t> records(batch * h.record_length);
    size_t total = 0;
    double xyz[3];
    while (total < kMaxFuzzPoints) {
      const size_t n = reader.read(records.data(), batch);
      if (n == 0) break;
      spinhash::fuzz::require(n <= batch, "more records than asked for");
      for (size_t i = 0; i < n; ++i) las_record_xyz(h, records.data() + i * h.record_length, xyz);
      total += n;
    }
    spinhash::fuzz::require(total <= h.point_count, "more points than the header declares");
    (void)reader.crs().describe();
  } catch (const CloudError& e) {
    spinhash::fuzz::require(std::strlen(e.what()) > 0, "failure without a message");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  read_records(bytes, spinhash::host::laz::LayerChoice::kAll);
  read_records(bytes, spinhash::host::laz::LayerChoice::kPipeline);
  return 0;
}
