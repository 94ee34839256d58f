// Database::open: one valid blob, then one corruption per check, each sealed
// again (CRCs, fingerprint) so that the check under test is the one that fires.
// No file I/O and no assumption about the host byte order (runs under QEMU).
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "blob/blob_writer.hpp"
#include "db/tiny_blob.hpp"
#include "spinhash/vehicle_class.hpp"
#include "support/blob_patch.hpp"
#include "support/golden_files.hpp"

using spinhash::Database;
using spinhash::kVehicleClassCount;
using spinhash::kVehicleGroupCount;
using spinhash::parse_vehicle_class;
using spinhash::parse_vehicle_group;
using spinhash::Status;
using spinhash::vehicle_class_name;
using spinhash::vehicle_group_name;
using spinhash::vehicle_group_of;
using spinhash::VehicleClass;
using spinhash::VehicleGroup;
using spinhash::test::BlobPatch;
namespace blob = spinhash::blob;
namespace host = spinhash::host;

namespace {

constexpr uint32_t kModels = 3;
constexpr uint32_t kFeaturesPerModel = 20;
constexpr uint64_t kSeed = 7;

const host::BlobContent& tiny() {
  static const host::BlobContent content = host::make_tiny_blob_content(kModels, kFeaturesPerModel, kSeed);
  return content;
}

const std::vector<uint8_t>& tiny_blob() {
  static const std::vector<uint8_t> bytes = spinhash::test::write_native(tiny());
  return bytes;
}

BlobPatch fresh() { return BlobPatch(tiny_blob()); }

template <typename T>
bool same(const T* a, const std::vector<T>& b) {
  return std::memcmp(a, b.data(), b.size() * sizeof(T)) == 0;
}

}  // namespace

TEST_CASE("crc32c and fnv1a64 match their published check values") {
  const char* digits = "123456789";
  CHECK(spinhash::crc32c(digits, 9) == 0xE3069283u);
  CHECK(spinhash::crc32c(digits + 4, 5, spinhash::crc32c(digits, 4)) == 0xE3069283u);
  CHECK(spinhash::crc32c(digits, 0) == 0u);
  CHECK(spinhash::fnv1a64("", 0) == 0xCBF29CE484222325ull);
  CHECK(spinhash::fnv1a64("a", 1) == 0xAF63DC4C8601EC8Cull);
}

TEST_CASE("a valid blob opens and its accessors return the written values") {
  const host::BlobContent& c = tiny();
  BlobPatch b = fresh();
  Database db;
  REQUIRE(b.open(&db) == Status::kOk);
  REQUIRE(db.is_open());
  CHECK(db.header().total_size == b.size());
  CHECK(db.model_count() == kModels);
  CHECK(db.feature_count() == kModels * kFeaturesPerModel);
  CHECK(db.spin_dims() == c.params.bins_alpha * c.params.bins_beta);
  CHECK(std::memcmp(&db.params(), &c.params, sizeof(blob::Params)) == 0);
  for (uint32_t i = 0; i < kModels; ++i) {
    CHECK(std::memcmp(&db.model(i), &c.models[i], sizeof(blob::ModelRecord)) == 0);
  }
  CHECK(same(db.positions(), c.positions));
  CHECK(same(db.normals(), c.normals));
  CHECK(same(db.feature_models(), c.feature_models));
  CHECK(same(db.spin(0), c.spins));
  CHECK(db.spin(1) == db.spin(0) + db.spin_dims());
  CHECK(same(db.grid_offsets(), c.grid_offsets));
  CHECK(same(db.lsh_bits(0), c.lsh_bits));
  CHECK(db.lsh_bits(1) == db.lsh_bits(0) + c.params.lsh_bits);
  CHECK(same(db.lsh_offsets(0), c.lsh_offsets));
  CHECK(db.lsh_offsets(1) == db.lsh_offsets(0) + c.params.lsh_buckets + 1u);
  CHECK(same(db.lsh_entries(), c.lsh_entries));
}

TEST_CASE("feature_params and find_model") {
  BlobPatch b = fresh();
  Database db;
  REQUIRE(b.open(&db) == Status::kOk);
  const spinhash::FeatureParams f = db.feature_params();
  CHECK(f.support_radius == tiny().params.support_radius);
  CHECK(f.bins_alpha == tiny().params.bins_alpha);
  CHECK(f.spin_quant_scale == tiny().params.spin_quant_scale);
  CHECK(db.find_model("tiny_0") == 0);
  CHECK(db.find_model("tiny_2") == 2);
  CHECK(db.find_model("tiny_") == -1);
  CHECK(db.find_model("tiny_22") == -1);
  CHECK(db.find_model("") == -1);
  CHECK(db.find_model(nullptr) == -1);
  const std::string long_name(100, 'x');
  CHECK(db.find_model(long_name.c_str()) == -1);
  CHECK(Database().find_model("tiny_0") == -1);
}

TEST_CASE("the opposite byte order is written swapped and refused with kBlobWrongByteOrder") {
  const host::ByteOrder other = host::opposite_byte_order(host::ByteOrder::kNative);
  std::vector<uint8_t> bytes;
  std::string error;
  REQUIRE(host::serialize_blob(tiny(), other, &bytes, &error));
  CHECK(error.empty());
  BlobPatch b(bytes);
  REQUIRE(b.size() == tiny_blob().size());
  CHECK(std::memcmp(b.header().magic, blob::kMagic, 8) == 0);
  CHECK(host::byteswap_scalar(b.header().byte_order) == blob::kByteOrderMark);
  CHECK(host::byteswap_scalar(b.header().total_size) == b.size());
  // Section CRCs are over the bytes as written, stored in the blob's order.
  for (uint32_t i = 0; i < blob::kSectionIdCount; ++i) {
    const blob::SectionEntry& e = b.entry(i);
    const uint64_t offset = host::byteswap_scalar(e.offset);
    const uint64_t size = host::byteswap_scalar(e.size);
    CHECK(host::byteswap_scalar(e.crc) == spinhash::crc32c(b.data() + offset, size));
  }
  CHECK(b.open() == Status::kBlobWrongByteOrder);
}

TEST_CASE("null pointer, zero size or null out are invalid arguments") {
  BlobPatch b = fresh();
  Database db;
  CHECK(Database::open(nullptr, b.size(), &db) == Status::kInvalidArgument);
  CHECK(Database::open(b.data(), 0, &db) == Status::kInvalidArgument);
  CHECK(Database::open(b.data(), b.size(), nullptr) == Status::kInvalidArgument);
  CHECK_FALSE(db.is_open());
}

TEST_CASE("an unaligned base pointer is refused with kMisalignedBuffer") {
  const std::vector<uint8_t>& bytes = tiny_blob();
  host::AlignedBytes buffer(bytes.size() + blob::kSectionAlignment);
  for (size_t shift : {size_t{1}, size_t{4}, size_t{8}, size_t{32}}) {
    std::memcpy(buffer.data() + shift, bytes.data(), bytes.size());
    Database db;
    CHECK(Database::open(buffer.data() + shift, bytes.size(), &db) == Status::kMisalignedBuffer);
  }
}

TEST_CASE("truncated blobs are refused with kBlobTruncated") {
  BlobPatch b = fresh();
  for (size_t length :
       {size_t{1}, size_t{63}, size_t{64}, size_t{100}, size_t{384}, b.size() / 2, b.size() - 1}) {
    CAPTURE(length);
    CHECK(b.open_prefix(length) == Status::kBlobTruncated);
  }
}

TEST_CASE("a truncated blob whose header was shortened too loses a section: out of bounds") {
  BlobPatch b = fresh();
  b.header().total_size -= 4;
  b.reseal_header();
  CHECK(b.open_prefix(b.size() - 4) == Status::kBlobSectionOutOfBounds);
}

TEST_CASE("bytes beyond the declared total size are refused with kBlobSizeMismatch") {
  std::vector<uint8_t> longer = tiny_blob();
  longer.resize(longer.size() + 64, 0);
  BlobPatch b(longer);
  CHECK(b.open() == Status::kBlobSizeMismatch);
}

TEST_CASE("wrong magic or an unknown byte-order mark is kBlobBadMagic") {
  BlobPatch b = fresh();
  b.header().magic[7] = 'X';
  CHECK(b.open() == Status::kBlobBadMagic);
  BlobPatch c = fresh();
  c.header().byte_order = 0x01020305u;
  CHECK(c.open() == Status::kBlobBadMagic);
}

TEST_CASE("a byte-swapped byte-order mark alone is kBlobWrongByteOrder") {
  BlobPatch b = fresh();
  b.header().byte_order = host::byteswap_scalar(blob::kByteOrderMark);
  CHECK(b.open() == Status::kBlobWrongByteOrder);
}

TEST_CASE(
    "versions 1-4 (no vehicle class, no calibration) and the next version are kBlobUnsupportedVersion") {
  for (uint32_t version : {1u, 2u, 3u, 4u, blob::kFormatVersion + 1u}) {
    BlobPatch b = fresh();
    b.header().version = version;
    b.reseal_header();
    CHECK(b.open() == Status::kBlobUnsupportedVersion);
  }
}

TEST_CASE("a flipped header CRC or table byte is kBlobHeaderChecksum") {
  BlobPatch b = fresh();
  b.header().header_crc ^= 1u;
  CHECK(b.open() == Status::kBlobHeaderChecksum);
  BlobPatch c = fresh();
  c.entry(3).reserved ^= 0x10u;
  CHECK(c.open() == Status::kBlobHeaderChecksum);
  BlobPatch d = fresh();
  d.header().reserved[0] ^= 1u;  // covered by the header CRC, which is checked first
  CHECK(d.open() == Status::kBlobHeaderChecksum);
}

TEST_CASE("section count zero or above kMaxSections is kBlobCountOverflow") {
  for (uint32_t count : {0u, spinhash::kMaxSections + 1u, 0xFFFFFFFFu}) {
    BlobPatch b = fresh();
    b.header().section_count = count;
    b.reseal_header();
    CHECK(b.open() == Status::kBlobCountOverflow);
  }
}

TEST_CASE("a section table beyond the end is kBlobTruncated") {
  BlobPatch b = fresh();
  const size_t length = 200;  // header fits, 10-entry table does not
  b.header().total_size = length;
  CHECK(b.open_prefix(length) == Status::kBlobTruncated);
}

TEST_CASE("a flipped section byte is kBlobSectionChecksum") {
  for (uint32_t id = 1; id <= blob::kSectionIdCount; ++id) {
    CAPTURE(id);
    BlobPatch b = fresh();
    b.payload(id)[b.entry_of(id).size - 1] ^= 0x01u;
    CHECK(b.open() == Status::kBlobSectionChecksum);
  }
}

TEST_CASE("an unknown section id is kBlobUnknownSection") {
  for (uint32_t id : {0u, blob::kSectionIdCount + 1u}) {
    BlobPatch b = fresh();
    b.entry(4).id = id;
    b.reseal_header();
    CHECK(b.open() == Status::kBlobUnknownSection);
  }
}

TEST_CASE("a duplicated section id is kBlobDuplicateSection") {
  BlobPatch b = fresh();
  b.entry(9).id = b.entry(8).id;
  b.reseal_header();
  CHECK(b.open() == Status::kBlobDuplicateSection);
}

TEST_CASE("an offset that is not a multiple of 64 is kBlobSectionMisaligned") {
  BlobPatch b = fresh();
  b.entry_of(blob::kFeatNormals).offset += 4;
  b.reseal();
  CHECK(b.open() == Status::kBlobSectionMisaligned);
}

TEST_CASE("an offset beyond the end or an overflowing size is kBlobSectionOutOfBounds") {
  BlobPatch b = fresh();
  b.entry_of(blob::kFeatSpins).offset = (b.size() / 64u + 1u) * 64u;  // aligned, past the end
  b.reseal_header();
  CHECK(b.open() == Status::kBlobSectionOutOfBounds);
  BlobPatch c = fresh();
  c.entry_of(blob::kFeatSpins).size = 0xFFFFFFFFFFFFFFC0ull;  // offset + size wraps
  c.reseal_header();
  CHECK(c.open() == Status::kBlobSectionOutOfBounds);
  BlobPatch d = fresh();
  d.entry_of(blob::kCalibration).size += 4;  // the last section
  d.reseal_header();
  CHECK(d.open() == Status::kBlobSectionOutOfBounds);
}

TEST_CASE("overlapping sections are kBlobSectionOverlap") {
  BlobPatch b = fresh();
  b.entry_of(blob::kFeatNormals).offset = b.entry_of(blob::kFeatPositions).offset;
  b.reseal();
  CHECK(b.open() == Status::kBlobSectionOverlap);
  BlobPatch c = fresh();  // inside the section table
  c.entry_of(blob::kFeatModels).offset = 256;
  c.reseal();
  CHECK(c.open() == Status::kBlobSectionOverlap);
  BlobPatch d = fresh();  // a size that runs into the next section
  d.entry_of(blob::kParams).size += 64;
  d.reseal();
  CHECK(d.open() == Status::kBlobSectionOverlap);
}

TEST_CASE("a missing section is kBlobMissingSection") {
  BlobPatch b = fresh();
  b.header().section_count = blob::kSectionIdCount - 1u;  // drops the last entry
  b.reseal_header();
  CHECK(b.open() == Status::kBlobMissingSection);
}

TEST_CASE("a params section of the wrong size is kBlobSizeMismatch") {
  BlobPatch b = fresh();
  b.entry_of(blob::kParams).size = sizeof(blob::Params) - 4u;
  b.reseal();
  CHECK(b.open() == Status::kBlobSizeMismatch);
}

TEST_CASE("counts outside their limits are kBlobCountOverflow, odd bucket counts kBlobBadParameter") {
  struct Case {
    const char* what;
    void (*patch)(blob::Params&);
    Status expected;
  };
  const Case cases[] = {
      {"no models", [](blob::Params& p) { p.model_count = 0; }, Status::kBlobCountOverflow},
      {"65536 models", [](blob::Params& p) { p.model_count = 65536; }, Status::kBlobCountOverflow},
      {"no features", [](blob::Params& p) { p.feature_count = 0; }, Status::kBlobCountOverflow},
      {"2^31 features", [](blob::Params& p) { p.feature_count = 0x80000000u; }, Status::kBlobCountOverflow},
      {"33 bins", [](blob::Params& p) { p.bins_beta = 33; }, Status::kBlobCountOverflow},
      {"no bins", [](blob::Params& p) { p.bins_alpha = 0; }, Status::kBlobCountOverflow},
      {"65 tables", [](blob::Params& p) { p.lsh_tables = 65; }, Status::kBlobCountOverflow},
      {"no bits", [](blob::Params& p) { p.lsh_bits = 0; }, Status::kBlobCountOverflow},
      {"65 bits", [](blob::Params& p) { p.lsh_bits = 65; }, Status::kBlobCountOverflow},
      {"2^29 buckets", [](blob::Params& p) { p.lsh_buckets = 1u << 29; }, Status::kBlobCountOverflow},
      {"no buckets", [](blob::Params& p) { p.lsh_buckets = 0; }, Status::kBlobCountOverflow},
      {"12 buckets", [](blob::Params& p) { p.lsh_buckets = 12; }, Status::kBlobBadParameter},
      {"no grid offsets", [](blob::Params& p) { p.grid_offset_count = 0; }, Status::kBlobCountOverflow},
  };
  for (const Case& k : cases) {
    CAPTURE(k.what);
    BlobPatch b = fresh();
    k.patch(b.params());
    b.reseal();
    CHECK(b.open() == k.expected);
  }
}

TEST_CASE("counts whose 32-bit products would wrap to the section size are kBlobSizeMismatch") {
  // 12 * 0x15555556 = 2^32 + 8: a 32-bit product would match a positions section of 8 bytes.
  BlobPatch b = fresh();
  b.params().feature_count = 0x15555556u;
  b.entry_of(blob::kFeatPositions).size = 8;
  b.reseal();
  CHECK(b.open() == Status::kBlobSizeMismatch);
  // 64 tables * (2^28 + 1) offsets * 4 bytes = 2^36 + 256 bytes.
  BlobPatch c = fresh();
  c.params().lsh_tables = 64;
  c.params().lsh_buckets = 1u << 28;
  c.entry_of(blob::kLshOffsets).size = 256;
  c.reseal();
  CHECK(c.open() == Status::kBlobSizeMismatch);
}

TEST_CASE("a section size that disagrees with its counts is kBlobSizeMismatch") {
  BlobPatch b = fresh();
  b.params().grid_offset_count += 1;
  b.reseal();
  CHECK(b.open() == Status::kBlobSizeMismatch);
  BlobPatch c = fresh();
  c.entry_of(blob::kLshEntries).size -= 4;
  c.reseal();
  CHECK(c.open() == Status::kBlobSizeMismatch);
}

TEST_CASE("non-finite or out-of-range float params are kBlobBadParameter") {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  struct Case {
    const char* what;
    float blob::Params::*field;
    float value;
  };
  const Case cases[] = {
      {"NaN support radius", &blob::Params::support_radius, nan},
      {"zero support radius", &blob::Params::support_radius, 0.0f},
      {"infinite voxel", &blob::Params::cloud_voxel, inf},
      {"negative basis spacing", &blob::Params::basis_spacing, -0.25f},
      {"zero normal radius", &blob::Params::normal_radius, 0.0f},
      {"zero support angle", &blob::Params::support_angle_deg, 0.0f},
      {"support angle 361", &blob::Params::support_angle_deg, 361.0f},
      {"zero quantisation scale", &blob::Params::spin_quant_scale, 0.0f},
      {"NaN d_c", &blob::Params::lsh_dc, nan},
      {"negative d_c", &blob::Params::lsh_dc, -1.0f},
      {"zero grid cell", &blob::Params::grid_cell, 0.0f},
  };
  for (const Case& k : cases) {
    CAPTURE(k.what);
    BlobPatch b = fresh();
    b.params().*k.field = k.value;
    b.reseal();
    CHECK(b.open() == Status::kBlobBadParameter);
  }
  BlobPatch ok = fresh();
  ok.params().support_angle_deg = 360.0f;
  ok.reseal();
  CHECK(ok.open() == Status::kOk);
}

TEST_CASE("a config fingerprint that does not match the params is kBlobBadParameter") {
  BlobPatch b = fresh();
  b.header().config_fingerprint ^= 1u;
  b.reseal_header();
  CHECK(b.open() == Status::kBlobBadParameter);
  BlobPatch c = fresh();
  c.params().reserved[5] = 1;  // reserved, but fingerprinted
  c.reseal(false);
  CHECK(c.open() == Status::kBlobBadParameter);
}

TEST_CASE("bad model names are kBlobBadModelTable") {
  BlobPatch b = fresh();
  std::memset(b.model(1).name, 'a', spinhash::kMaxModelNameBytes);  // no NUL
  b.reseal();
  CHECK(b.open() == Status::kBlobBadModelTable);
  BlobPatch c = fresh();
  std::memset(c.model(0).name, 0, spinhash::kMaxModelNameBytes);  // empty (a tail after a NUL is not zeroed)
  c.reseal();
  CHECK(c.open() == Status::kBlobBadModelTable);
  BlobPatch ok = fresh();  // 47 characters and the NUL fill the field exactly
  std::memset(ok.model(2).name, 'z', spinhash::kMaxModelNameBytes - 1u);
  ok.reseal();
  Database db;
  CHECK(ok.open(&db) == Status::kOk);
  CHECK(db.find_model(std::string(spinhash::kMaxModelNameBytes - 1u, 'z').c_str()) == 2);
}

TEST_CASE("every model's vehicle class is read back; a class outside the list is kBlobBadModelTable") {
  BlobPatch blob = fresh();  // the database views these bytes: they must outlive it
  Database db;
  REQUIRE(blob.open(&db) == Status::kOk);
  for (uint32_t i = 0; i < kModels; ++i) CHECK(db.model(i).vehicle_class == tiny().models[i].vehicle_class);
  CHECK(db.model(0).vehicle_class != 0u);  // the tiny blob gives every model a class
  for (uint32_t bad : {kVehicleClassCount, 0xFFu}) {
    CAPTURE(bad);
    BlobPatch b = fresh();
    b.model(1).vehicle_class = static_cast<uint8_t>(bad);
    b.reseal();
    CHECK(b.open() == Status::kBlobBadModelTable);
  }
  BlobPatch last = fresh();  // the last class and "unclassified" are valid
  last.model(0).vehicle_class = static_cast<uint8_t>(kVehicleClassCount - 1u);
  last.model(1).vehicle_class = 0u;
  last.reseal();
  CHECK(last.open() == Status::kOk);
}

TEST_CASE("a model's own group: only for a class in no group, a group of the list") {
  const auto with = [](uint32_t cls, uint32_t group) {
    BlobPatch b = fresh();
    b.model(1).vehicle_class = static_cast<uint8_t>(cls);
    b.model(1).vehicle_group = static_cast<uint8_t>(group);
    b.reseal();
    return b;
  };
  const auto other = static_cast<uint32_t>(VehicleClass::kOther),
             sedan = static_cast<uint32_t>(VehicleClass::kSedan),
             light = static_cast<uint32_t>(VehicleGroup::kLight),
             heavy = static_cast<uint32_t>(VehicleGroup::kHeavy);
  {
    BlobPatch b = with(other, light);  // an "other" buggy, a light vehicle
    Database db;
    REQUIRE(b.open(&db) == Status::kOk);
    CHECK(spinhash::model_group(db.model(1)) == VehicleGroup::kLight);
  }
  CHECK(with(static_cast<uint32_t>(VehicleClass::kUnclassified), heavy).open() == Status::kOk);
  CHECK(with(sedan, 0u).open() == Status::kOk);  // 0: the class's group
  // A class in a group fixes its models' group, even to the same group: one
  // way to say it. A group outside the list is no group.
  CHECK(with(sedan, light).open() == Status::kBlobBadModelTable);
  CHECK(with(sedan, heavy).open() == Status::kBlobBadModelTable);
  CHECK(with(other, kVehicleGroupCount).open() == Status::kBlobBadModelTable);
  CHECK(with(other, 0xFFu).open() == Status::kBlobBadModelTable);
  // The group an answer climbs through: the model's own, else its class's.
  CHECK(vehicle_group_of(other, light) == VehicleGroup::kLight);
  CHECK(vehicle_group_of(other, 0u) == VehicleGroup::kNone);
  CHECK(vehicle_group_of(sedan, 0u) == VehicleGroup::kLight);
  CHECK(vehicle_group_of(sedan, heavy) == VehicleGroup::kLight);  // not allowed: the class's
  CHECK_FALSE(spinhash::model_group_allowed(sedan, heavy));
  CHECK(spinhash::model_group_allowed(other, heavy));
}

TEST_CASE("class names: every id has a name that parses back to it; others do not parse") {
  for (uint32_t id = 0; id < kVehicleClassCount; ++id) {
    VehicleClass c = VehicleClass::kOther;
    CHECK(parse_vehicle_class(vehicle_class_name(id), &c));
    CHECK(static_cast<uint32_t>(c) == id);
  }
  CHECK(std::string(vehicle_class_name(kVehicleClassCount)) == "unknown");
  CHECK_FALSE(parse_vehicle_class("Sedan", nullptr));
  CHECK_FALSE(parse_vehicle_class("sedans", nullptr));
  CHECK_FALSE(parse_vehicle_class("", nullptr));
  CHECK_FALSE(parse_vehicle_class(nullptr, nullptr));
  CHECK(parse_vehicle_class("apc", nullptr));
}

TEST_CASE("class groups: every class has a group of the list, and the group is the class list's column") {
  for (uint32_t id = 0; id < kVehicleGroupCount; ++id) {
    VehicleGroup g = VehicleGroup::kNone;
    CHECK(parse_vehicle_group(vehicle_group_name(id), &g));
    CHECK(static_cast<uint32_t>(g) == id);
  }
  CHECK(std::string(vehicle_group_name(kVehicleGroupCount)) == "unknown");
  CHECK_FALSE(parse_vehicle_group("Light", nullptr));
  CHECK_FALSE(parse_vehicle_group(nullptr, nullptr));
  for (uint32_t id = 0; id < kVehicleClassCount; ++id)
    CHECK(static_cast<uint32_t>(vehicle_group_of(id)) < kVehicleGroupCount);
  // The hierarchy the answers climb: cars, SUVs, vans and pickups are light;
  // lorries and buses heavy; tracked and wheeled armoured vehicles armoured.
  for (VehicleClass c : {VehicleClass::kSedan, VehicleClass::kSuv, VehicleClass::kVan, VehicleClass::kPickup,
                         VehicleClass::kCar})
    CHECK(vehicle_group_of(c) == VehicleGroup::kLight);
  for (VehicleClass c : {VehicleClass::kTruck, VehicleClass::kBus})
    CHECK(vehicle_group_of(c) == VehicleGroup::kHeavy);
  for (VehicleClass c : {VehicleClass::kTracked, VehicleClass::kApc})
    CHECK(vehicle_group_of(c) == VehicleGroup::kArmoured);
  // "other" spans every size and "unclassified" says nothing: no group.
  CHECK(vehicle_group_of(VehicleClass::kOther) == VehicleGroup::kNone);
  CHECK(vehicle_group_of(VehicleClass::kUnclassified) == VehicleGroup::kNone);
  CHECK(vehicle_group_of(kVehicleClassCount) == VehicleGroup::kNone);
  CHECK(std::string(vehicle_group_name(vehicle_group_of(VehicleClass::kApc))) == "armoured");
}

// A named corruption of a fresh blob; check_corruptions reseals each and
// expects `open` to give one status.
struct Corruption {
  const char* what;
  void (*patch)(BlobPatch&);
};
template <size_t N>
void check_corruptions(const Corruption (&cases)[N], Status expected) {
  for (const Corruption& k : cases) {
    CAPTURE(k.what);
    BlobPatch b = fresh();
    k.patch(b);
    b.reseal();
    CHECK(b.open() == expected);
  }
}

TEST_CASE("feature ranges that do not tile the features are kBlobBadModelTable") {
  const Corruption cases[] = {
      {"gap", [](BlobPatch& b) { b.model(1).first_feature += 1; }},
      {"empty", [](BlobPatch& b) { b.model(2).feature_count = 0; }},
      {"short of the end", [](BlobPatch& b) { b.model(2).feature_count -= 1; }},
      {"past the end", [](BlobPatch& b) { b.model(2).feature_count += 1; }},
      {"out of order", [](BlobPatch& b) { std::swap(b.model(0), b.model(1)); }},
  };
  check_corruptions(cases, Status::kBlobBadModelTable);
}

TEST_CASE("bad grids are kBlobBadModelTable") {
  // Model 1 of the tiny blob has a 2 x 2 x 1 grid: offsets [0, a, b, c, 20].
  const Corruption cases[] = {
      {"zero dimension", [](BlobPatch& b) { b.model(0).grid_dims[2] = 0; }},
      {"too many cells",
       [](BlobPatch& b) {
         b.model(2).grid_dims[0] = 1u << 10;
         b.model(2).grid_dims[1] = 1u << 10;
         b.model(2).grid_dims[2] = 2;
       }},
      {"dims whose product wraps 32 bits",
       [](BlobPatch& b) {
         b.model(2).grid_dims[0] = 1u << 16;
         b.model(2).grid_dims[1] = 1u << 16;
       }},
      {"offsets past the section", [](BlobPatch& b) { b.model(2).grid_offset_base += 1; }},
      {"ranges overlapping", [](BlobPatch& b) { b.model(1).grid_offset_base -= 1; }},
      {"non-monotonic",
       [](BlobPatch& b) {
         uint32_t* off = b.section<uint32_t>(blob::kGridOffsets) + b.model(1).grid_offset_base;
         off[1] = kFeaturesPerModel;
         off[2] = 0;
       }},
      {"not starting at 0",
       [](BlobPatch& b) { b.section<uint32_t>(blob::kGridOffsets)[b.model(0).grid_offset_base] = 1; }},
      {"not ending at the feature count",
       [](BlobPatch& b) {
         uint32_t* off = b.section<uint32_t>(blob::kGridOffsets) + b.model(1).grid_offset_base;
         off[4] = kFeaturesPerModel - 1u;
       }},
      {"NaN origin", [](BlobPatch& b) { b.model(0).grid_origin[1] = std::nanf(""); }},
      {"infinite bbox", [](BlobPatch& b) { b.model(0).bbox_max[0] = INFINITY; }},
      {"inverted bbox", [](BlobPatch& b) { b.model(0).bbox_min[2] = b.model(0).bbox_max[2] + 1.0f; }},
  };
  check_corruptions(cases, Status::kBlobBadModelTable);
}

TEST_CASE("bad nearest-feature fields are kBlobBadModelTable") {
  const Corruption cases[] = {
      {"zero dimension", [](BlobPatch& b) { b.model(1).field_dims[0] = 0; }},
      {"dims whose product wraps 32 bits",
       [](BlobPatch& b) {
         b.model(2).field_dims[0] = 1u << 16;
         b.model(2).field_dims[1] = 1u << 16;
       }},
      {"entries past the section", [](BlobPatch& b) { b.model(2).field_base += 1; }},
      {"ranges overlapping", [](BlobPatch& b) { b.model(1).field_base -= 1; }},
      {"an entry past the model's features",
       [](BlobPatch& b) {
         b.section<uint16_t>(blob::kNearestField)[b.model(2).field_base] = kFeaturesPerModel;
       }},
      {"a field on a model of a blob without one",
       [](BlobPatch& b) {
         b.params().field_entry_count = 0;
         b.params().field_slots = 0;
         b.params().field_cell = 0.0f;
         b.params().field_reach = 0.0f;
         // The payload's bytes become padding, which must be zero.
         std::memset(b.payload(blob::kNearestField), 0, b.entry_of(blob::kNearestField).size);
         b.entry_of(blob::kNearestField).size = 0;
       }},
  };
  check_corruptions(cases, Status::kBlobBadModelTable);
}

TEST_CASE("a field half described in the params is kBlobBadParameter") {
  struct Case {
    const char* what;
    void (*patch)(blob::Params&);
  };
  const Case cases[] = {
      {"no slots", [](blob::Params& p) { p.field_slots = 0; }},
      {"too many slots", [](blob::Params& p) { p.field_slots = spinhash::kMaxFieldSlots + 1u; }},
      {"no cell", [](blob::Params& p) { p.field_cell = 0.0f; }},
      {"NaN cell", [](blob::Params& p) { p.field_cell = std::nanf(""); }},
      {"negative reach", [](blob::Params& p) { p.field_reach = -0.1f; }},
  };
  for (const Case& k : cases) {
    CAPTURE(k.what);
    BlobPatch b = fresh();
    k.patch(b.params());
    b.reseal();
    CHECK(b.open() == Status::kBlobBadParameter);
  }
}

TEST_CASE("bad features are kBlobBadFeature") {
  struct Case {
    const char* what;
    void (*patch)(BlobPatch&);
  };
  const Case cases[] = {
      {"NaN position",
       [](BlobPatch& b) { b.section<float>(blob::kFeatPositions)[3 * 5 + 1] = std::nanf(""); }},
      {"infinite position", [](BlobPatch& b) { b.section<float>(blob::kFeatPositions)[0] = -INFINITY; }},
      {"zero normal",
       [](BlobPatch& b) {
         int16_t* n = b.section<int16_t>(blob::kFeatNormals) + 3 * 7;
         n[0] = n[1] = n[2] = 0;
       }},
      {"long normal",
       [](BlobPatch& b) {
         int16_t* n = b.section<int16_t>(blob::kFeatNormals) + 3 * 59;
         n[0] = n[1] = n[2] = 32767;
       }},
      {"model id out of range", [](BlobPatch& b) { b.section<uint16_t>(blob::kFeatModels)[59] = kModels; }},
      {"model id of another model", [](BlobPatch& b) { b.section<uint16_t>(blob::kFeatModels)[20] = 0; }},
  };
  for (const Case& k : cases) {
    CAPTURE(k.what);
    BlobPatch b = fresh();
    k.patch(b);
    b.reseal();
    CHECK(b.open() == Status::kBlobBadFeature);
  }
}

TEST_CASE("bad LSH bits, offsets or entries are kBlobBadIndex") {
  struct Case {
    const char* what;
    void (*patch)(BlobPatch&);
  };
  const Case cases[] = {
      {"entry = feature_count",
       [](BlobPatch& b) {
         b.section<uint32_t>(blob::kLshEntries)[kModels * kFeaturesPerModel + 3] =
             kModels * kFeaturesPerModel;
       }},
      {"entry huge", [](BlobPatch& b) { b.section<uint32_t>(blob::kLshEntries)[0] = 0xFFFFFFFFu; }},
      {"bit dimension = spin dims",
       [](BlobPatch& b) {
         b.section<blob::LshBit>(blob::kLshBits)[4].dim =
             static_cast<uint16_t>(b.params().bins_alpha * b.params().bins_beta);
       }},
      {"threshold 256", [](BlobPatch& b) { b.section<blob::LshBit>(blob::kLshBits)[0].threshold = 256; }},
      {"offsets not starting at 0",
       [](BlobPatch& b) {
         b.section<uint32_t>(blob::kLshOffsets)[b.params().lsh_buckets + 1u] = 1;  // table 1
       }},
      {"offsets not ending at feature_count",
       [](BlobPatch& b) { b.section<uint32_t>(blob::kLshOffsets)[b.params().lsh_buckets] += 1; }},
      {"offsets decreasing",
       [](BlobPatch& b) {
         uint32_t* off = b.section<uint32_t>(blob::kLshOffsets);
         off[1] = off[b.params().lsh_buckets];
         off[2] = 0;
       }},
  };
  for (const Case& k : cases) {
    CAPTURE(k.what);
    BlobPatch b = fresh();
    k.patch(b);
    b.reseal();
    CHECK(b.open() == Status::kBlobBadIndex);
  }
}

TEST_CASE("a failed open leaves the output untouched") {
  BlobPatch good = fresh();
  Database db;
  REQUIRE(good.open(&db) == Status::kOk);
  const float* positions = db.positions();
  BlobPatch bad = fresh();
  bad.section<float>(blob::kFeatPositions)[0] = std::nanf("");
  bad.reseal();
  CHECK(bad.open(&db) == Status::kBlobBadFeature);
  CHECK(db.positions() == positions);
  CHECK(db.model_count() == kModels);
}

TEST_CASE("the writer refuses inconsistent content and says why") {
  std::vector<uint8_t> out{1, 2, 3};
  std::string error;
  host::BlobContent short_normals = tiny();
  short_normals.normals.pop_back();
  CHECK_FALSE(host::serialize_blob(short_normals, host::ByteOrder::kNative, &out, &error));
  CHECK(out.empty());
  CHECK(error.find("normals") != std::string::npos);

  host::BlobContent nan_position = tiny();
  nan_position.positions[4] = std::nanf("");
  CHECK_FALSE(host::serialize_blob(nan_position, host::ByteOrder::kBig, &out, &error));
  CHECK(error.find(spinhash::status_name(Status::kBlobBadFeature)) != std::string::npos);

  host::BlobContent ok = tiny();
  ok.params.reserved[0] = 9;                   // reserved bytes are written as zero
  std::memset(ok.models[0].name + 7, 'q', 8);  // after the NUL: zeroed too
  REQUIRE(host::serialize_blob(ok, host::ByteOrder::kNative, &out, &error));
  CHECK(out == tiny_blob());
}

TEST_CASE("tiny blob content is deterministic and its LSH buckets agree with bucket_of") {
  const host::BlobContent a = host::make_tiny_blob_content(4, 9, 123);
  const host::BlobContent b = host::make_tiny_blob_content(4, 9, 123);
  CHECK(a.positions == b.positions);
  CHECK(a.lsh_entries == b.lsh_entries);
  const blob::Params& p = a.params;
  const uint32_t dims = p.bins_alpha * p.bins_beta;
  for (uint32_t t = 0; t < p.lsh_tables; ++t) {
    const uint32_t* off = &a.lsh_offsets[t * (p.lsh_buckets + 1u)];
    for (uint32_t bucket = 0; bucket < p.lsh_buckets; ++bucket) {
      for (uint32_t j = off[bucket]; j < off[bucket + 1u]; ++j) {
        const uint32_t f = a.lsh_entries[t * p.feature_count + j];
        uint64_t key = 0;
        for (uint32_t k = 0; k < p.lsh_bits; ++k) {
          const blob::LshBit& bit = a.lsh_bits[t * p.lsh_bits + k];
          if (a.spins[f * dims + bit.dim] > bit.threshold) key |= uint64_t{1} << k;
        }
        CHECK(blob::bucket_of(key, t, p.lsh_buckets) == bucket);
      }
    }
  }
}

// ---- Hardening: the remaining corruptions of a blob (each header and section field), and
// exhaustive sweeps (every truncation, every single-byte flip) that also run
// on the cross targets, where no fuzzer runs.

TEST_CASE("versions 0 and 0xFFFFFFFF are kBlobUnsupportedVersion") {
  for (uint32_t version : {0u, 0xFFFFFFFFu}) {
    CAPTURE(version);
    BlobPatch b = fresh();
    b.header().version = version;
    b.reseal_header();
    CHECK(b.open() == Status::kBlobUnsupportedVersion);
  }
}

TEST_CASE("every float parameter NaN, +inf or -inf is kBlobBadParameter") {
  float blob::Params::*const fields[] = {
      &blob::Params::cloud_voxel,    &blob::Params::normal_radius,     &blob::Params::basis_spacing,
      &blob::Params::support_radius, &blob::Params::support_angle_deg, &blob::Params::spin_quant_scale,
      &blob::Params::lsh_dc,         &blob::Params::grid_cell};
  const float values[] = {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                          -std::numeric_limits<float>::infinity()};
  for (size_t f = 0; f < sizeof fields / sizeof fields[0]; ++f) {
    for (float v : values) {
      CAPTURE(f);
      CAPTURE(v);
      BlobPatch b = fresh();
      b.params().*fields[f] = v;
      b.reseal();
      CHECK(b.open() == Status::kBlobBadParameter);
    }
  }
}

TEST_CASE("non-finite model bounds and grid origins are kBlobBadModelTable") {
  const float bad[] = {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                       -std::numeric_limits<float>::infinity()};
  for (float v : bad) {
    for (int axis = 0; axis < 3; ++axis) {
      CAPTURE(v);
      CAPTURE(axis);
      float* fields[] = {nullptr, nullptr, nullptr};
      for (int which = 0; which < 3; ++which) {
        BlobPatch b = fresh();
        blob::ModelRecord& m = b.model(kModels - 1u);
        fields[0] = &m.grid_origin[axis];
        fields[1] = &m.bbox_min[axis];
        fields[2] = &m.bbox_max[axis];
        *fields[which] = v;
        b.reseal();
        CHECK(b.open() == Status::kBlobBadModelTable);
      }
    }
  }
}

TEST_CASE("an empty model table section is kBlobSizeMismatch") {
  BlobPatch b = fresh();
  b.entry_of(blob::kModels).size = 0;
  b.reseal();
  CHECK(b.open() == Status::kBlobSizeMismatch);
}

TEST_CASE("every truncation of a valid blob is refused") {
  BlobPatch b = fresh();
  CHECK(b.open_prefix(0) == Status::kInvalidArgument);
  uint32_t accepted = 0;
  for (size_t length = 1; length < b.size(); ++length)
    accepted += b.open_prefix(length) == Status::kOk ? 1u : 0u;
  CHECK(accepted == 0);
}

namespace {

// True if byte `at` lies in no payload and not in the header or table: padding.
bool is_padding(const blob::SectionEntry* table, uint32_t sections, size_t at) {
  if (at < sizeof(blob::Header) + sections * sizeof(blob::SectionEntry)) return false;
  for (uint32_t i = 0; i < sections; ++i)
    if (at >= table[i].offset && at < table[i].offset + table[i].size) return false;
  return true;
}

// Database::open of `bytes` with byte `at` changed by `flip`.
Status open_flipped(uint8_t* bytes, size_t size, size_t at, uint8_t flip) {
  bytes[at] ^= flip;
  Database db;
  const Status s = Database::open(bytes, size, &db);
  bytes[at] ^= flip;
  return s;
}

constexpr uint8_t kFlips[] = {0xFFu, 0x01u, 0x80u};  // every bit, the lowest, the highest

}  // namespace

TEST_CASE("every single-byte change of a blob is refused, padding included") {
  BlobPatch b = fresh();
  uint32_t accepted = 0, padding = 0;
  for (size_t at = 0; at < b.size(); ++at) {
    padding += is_padding(&b.entry(0), blob::kSectionIdCount, at) ? 1u : 0u;
    for (uint8_t flip : kFlips) {
      if (open_flipped(b.data(), b.size(), at, flip) == Status::kOk) {
        ++accepted;
        CAPTURE(at);
        CAPTURE(static_cast<int>(flip));
        CHECK(false);
      }
    }
  }
  CHECK(accepted == 0);
  CHECK(padding > 0);  // the tiny blob has gaps between payloads, as real ones do
  CHECK(b.open() == Status::kOk);
}

TEST_CASE("a changed padding byte of the golden blob is kBlobNotZeroed") {
  // Padding is covered by no checksum: every byte of it, flipped, is refused.
  host::AlignedBytes golden = spinhash::test::golden_blob(true);
  const auto* table = reinterpret_cast<const blob::SectionEntry*>(golden.data() + sizeof(blob::Header));
  uint32_t padding = 0;
  for (size_t at = 0; at < golden.size(); ++at) {
    if (!is_padding(table, blob::kSectionIdCount, at)) continue;
    ++padding;
    CAPTURE(at);
    CHECK(open_flipped(golden.data(), golden.size(), at, 0x01u) == Status::kBlobNotZeroed);
  }
  CHECK(padding >= 32u);
}

TEST_CASE("non-zero reserved fields and name tails are kBlobNotZeroed, even re-sealed") {
  const Corruption cases[] = {
      {"header reserved", [](BlobPatch& b) { b.header().reserved[23] = 1; }},
      {"table entry reserved", [](BlobPatch& b) { b.entry(4).reserved = 1; }},
      {"table entry reserved2", [](BlobPatch& b) { b.entry(10).reserved2 = 0x80000000u; }},
      {"params reserved", [](BlobPatch& b) { b.params().reserved[47] = 2; }},
      {"model reserved", [](BlobPatch& b) { b.model(2).reserved[0] = 3; }},
      {"model reserved, last byte", [](BlobPatch& b) { b.model(0).reserved[1] = 0x40; }},
      {"a name's tail", [](BlobPatch& b) { b.model(1).name[spinhash::kMaxModelNameBytes - 1u] = 'x'; }},
      {"padding after the feature models (120 bytes)",
       [](BlobPatch& b) {
         const blob::SectionEntry& e = b.entry_of(blob::kFeatModels);
         b.data()[e.offset + e.size] = 1;
       }},
  };
  check_corruptions(cases, Status::kBlobNotZeroed);
}

TEST_CASE("single-byte corruptions re-sealed past the checksums never escape the blob") {
  // With valid CRCs the structural checks alone must catch what matters; a
  // corruption they allow (a name byte, a spin value) must still give a view
  // whose arrays all lie inside the blob.
  // Every byte of the header, table, params and models; a prime stride through
  // the feature and index arrays (keeps the sweep quick under QEMU).
  constexpr size_t kArrayStride = 7;
  const std::vector<uint8_t>& original = tiny_blob();
  const size_t arrays_start = fresh().entry_of(blob::kFeatPositions).offset;
  uint32_t accepted = 0;
  for (size_t at = 0; at < original.size(); at += at < arrays_start ? 1 : kArrayStride) {
    BlobPatch b(original);
    b.data()[at] ^= 0xFFu;
    b.reseal();
    Database db;
    if (b.open(&db) != Status::kOk) continue;
    ++accepted;
    const uint8_t* lo = b.data();
    const uint8_t* hi = b.data() + b.size();
    auto inside = [&](const void* p, size_t bytes) {
      const uint8_t* q = static_cast<const uint8_t*>(p);
      return q >= lo && q + bytes <= hi;
    };
    const size_t n = db.feature_count();
    const blob::Params& p = db.params();
    CAPTURE(at);
    CHECK(inside(db.positions(), 3 * n * sizeof(float)));
    CHECK(inside(db.normals(), 3 * n * sizeof(int16_t)));
    CHECK(inside(db.feature_models(), n * sizeof(uint16_t)));
    CHECK(inside(db.spin(0), n * db.spin_dims()));
    CHECK(inside(db.grid_offsets(), p.grid_offset_count * sizeof(uint32_t)));
    CHECK(inside(db.lsh_bits(0), static_cast<size_t>(p.lsh_tables) * p.lsh_bits * sizeof(blob::LshBit)));
    CHECK(inside(db.lsh_offsets(0),
                 static_cast<size_t>(p.lsh_tables) * (p.lsh_buckets + 1u) * sizeof(uint32_t)));
    CHECK(inside(db.lsh_entries(), static_cast<size_t>(p.lsh_tables) * n * sizeof(uint32_t)));
    for (uint32_t m = 0; m < db.model_count(); ++m)
      CHECK(db.model(m).first_feature + db.model(m).feature_count <= n);
  }
  CHECK(accepted > 0);  // spin values, positions within range: allowed by design
}
