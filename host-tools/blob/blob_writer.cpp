#include "blob/blob_writer.hpp"

#include <cstring>
#include <type_traits>

#include "blob/aligned_bytes.hpp"
#include "blob/blob_layout.hpp"
#include "blob/blob_swap.hpp"
#include "spinhash/database.hpp"

namespace spinhash {
namespace host {
namespace {

constexpr uint64_t kTableOffset = sizeof(blob::Header);

// Reserved bytes are written as zero whatever the caller left in them, so the
// fingerprint and CRCs depend only on meaningful fields.
blob::Params normalized(blob::Params p) {
  std::memset(p.reserved, 0, sizeof(p.reserved));
  return p;
}

blob::ModelRecord normalized(blob::ModelRecord m) {
  std::memset(m.reserved, 0, sizeof(m.reserved));
  const void* nul = std::memchr(m.name, '\0', sizeof(m.name));
  if (nul != nullptr) {  // zero the tail; a missing NUL is left for validation to refuse
    char* tail = static_cast<char*>(const_cast<void*>(nul));
    std::memset(tail, 0, static_cast<size_t>(m.name + sizeof(m.name) - tail));
  }
  return m;
}

// Copies values into an image of the final size in the target byte order.
class ImageWriter {
 public:
  ImageWriter(uint8_t* image, bool swap) : image_(image), swap_(swap) {}

  template <typename T>
  void put(uint64_t offset, T value) {
    if constexpr (std::is_arithmetic<T>::value) {
      swap_in_place(&value, swap_);
    } else {
      swap_fields(&value, swap_);
    }
    std::memcpy(image_ + offset, &value, sizeof(T));
  }

  template <typename T>
  void put_all(uint64_t offset, const std::vector<T>& values) {
    for (const T& v : values) {
      put(offset, v);
      offset += sizeof(T);
    }
  }

  bool swap() const { return swap_; }
  uint8_t* image() const { return image_; }

 private:
  uint8_t* image_;
  bool swap_;
};

void write_payloads(const BlobContent& c, const BlobLayout& l, ImageWriter* w) {
  auto at = [&l](uint32_t id) { return l.sections[id - 1u].offset; };
  w->put(at(blob::kParams), normalized(c.params));
  uint64_t offset = at(blob::kModels);
  for (const blob::ModelRecord& m : c.models) {
    w->put(offset, normalized(m));
    offset += sizeof(blob::ModelRecord);
  }
  w->put_all(at(blob::kFeatPositions), c.positions);
  w->put_all(at(blob::kFeatNormals), c.normals);
  w->put_all(at(blob::kFeatModels), c.feature_models);
  w->put_all(at(blob::kFeatSpins), c.spins);
  w->put_all(at(blob::kGridOffsets), c.grid_offsets);
  w->put_all(at(blob::kLshBits), c.lsh_bits);
  w->put_all(at(blob::kLshOffsets), c.lsh_offsets);
  w->put_all(at(blob::kLshEntries), c.lsh_entries);
  w->put_all(at(blob::kNearestField), c.nearest_field);
  offset = at(blob::kCalibration);
  w->put(offset, c.calibration.header);
  offset += sizeof(blob::CalibrationHeader);
  w->put_all(offset, c.calibration.passes);
  w->put_all(offset + c.calibration.passes.size() * sizeof(blob::CalibrationPass), c.calibration.cells);
}

// Checksums over the bytes as written (so they verify on the target), table,
// fingerprint, header, and the header CRC last.
void seal(const BlobLayout& l, ImageWriter* w) {
  uint8_t* img = w->image();
  for (uint32_t i = 0; i < blob::kSectionIdCount; ++i) {
    const SectionPlacement& s = l.sections[i];
    blob::SectionEntry e{};
    e.id = s.id;
    e.offset = s.offset;
    e.size = s.size;
    e.crc = crc32c(img + s.offset, static_cast<size_t>(s.size));
    w->put(kTableOffset + i * sizeof(blob::SectionEntry), e);
  }
  blob::Header h{};
  std::memcpy(h.magic, blob::kMagic, sizeof(h.magic));
  h.version = blob::kFormatVersion;
  h.byte_order = blob::kByteOrderMark;
  h.total_size = l.total_size;
  h.config_fingerprint = fnv1a64(img + l.sections[blob::kParams - 1u].offset, sizeof(blob::Params));
  h.section_count = blob::kSectionIdCount;
  w->put(0u, h);
  const size_t covered = sizeof(blob::Header) + blob::kSectionIdCount * sizeof(blob::SectionEntry);
  h.header_crc = crc32c(img, covered);  // header_crc is still zero in the image
  w->put(0u, h);
}

void build_image(const BlobContent& c, const BlobLayout& l, bool swap, uint8_t* image) {
  ImageWriter w(image, swap);
  write_payloads(c, l, &w);
  seal(l, &w);
}

}  // namespace

bool serialize_blob(const BlobContent& c, ByteOrder order, std::vector<uint8_t>* out, std::string* error) {
  if (out == nullptr || error == nullptr) return false;
  out->clear();
  error->clear();
  BlobLayout layout{};
  if (!plan_blob_layout(c, &layout, error)) return false;
  if (layout.total_size > SIZE_MAX) {
    *error = "blob of " + std::to_string(layout.total_size) + " bytes does not fit in memory";
    return false;
  }
  const size_t total = static_cast<size_t>(layout.total_size);
  AlignedBytes native(total);
  build_image(c, layout, false, native.data());
  Database db;
  const Status s = Database::open(native.data(), native.size(), &db);
  if (s != Status::kOk) {
    *error = std::string("content fails validation: ") + status_name(s);
    return false;
  }
  if (resolve_byte_order(order) == native_byte_order()) {
    out->assign(native.data(), native.data() + total);
  } else {
    out->assign(total, 0u);
    build_image(c, layout, true, out->data());
  }
  return true;
}

bool open_content(const BlobContent& content, AlignedBytes* bytes, Database* db, std::string* error) {
  std::vector<uint8_t> blob;
  if (!serialize_blob(content, ByteOrder::kNative, &blob, error)) return false;
  *bytes = AlignedBytes::copy_of(blob);
  const Status s = Database::open(bytes->data(), bytes->size(), db);
  if (s != Status::kOk) {
    *error = std::string("Database::open: ") + status_name(s);
    return false;
  }
  return true;
}

}  // namespace host
}  // namespace spinhash
