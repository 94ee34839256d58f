// PLY header parsing for the point-cloud reader. Every field is validated;
// element counts are only numbers here (the body reader bounds them by the
// bytes actually present before trusting them).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace spinhash::host::ply {

enum class Format { kAscii, kBinaryLittleEndian, kBinaryBigEndian };
enum class Type { kInt8, kUint8, kInt16, kUint16, kInt32, kUint32, kFloat32, kFloat64 };

struct Property {
  std::string name;
  Type type = Type::kFloat32;  // the item type for a list
  bool is_list = false;
  Type count_type = Type::kUint8;  // lists only: integer type of the count
};

struct Element {
  std::string name;
  uint64_t count = 0;
  std::vector<Property> properties;
};

struct Header {
  Format format = Format::kAscii;
  std::vector<Element> elements;
  std::size_t data_offset = 0;  // first byte after "end_header\n"
};

// Longest header accepted: a file without end_header in this many bytes is
// not a PLY file we can read.
constexpr std::size_t kMaxHeaderBytes = 64 * 1024;

std::size_t type_size(Type type);
bool is_integer(Type type);
// Parses the header at the start of bytes; false with *error if malformed.
bool parse_header(const std::string& bytes, Header* header, std::string* error);

}  // namespace spinhash::host::ply
