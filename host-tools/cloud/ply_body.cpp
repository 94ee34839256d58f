#include "cloud/ply_body.hpp"

#include <charconv>
#include <cstring>
#include <string_view>

namespace spinhash::host::ply {
namespace {

constexpr int kAxes = 3;
constexpr const char* kAxisNames[kAxes] = {"x", "y", "z"};
// An ASCII value is at least one character and one separator.
constexpr std::size_t kMinAsciiBytesPerValue = 2;

bool fail(std::string* error, const std::string& message) {
  if (error) *error = "PLY: " + message;
  return false;
}

// Index of the property called name, or -1.
int find_property(const Element& e, const char* name) {
  for (std::size_t i = 0; i < e.properties.size(); ++i) {
    if (e.properties[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

// Validates the vertex element; axis[i] = axis (0..2) of property i, or -1.
bool check_vertex(const Header& h, std::size_t* vertex, std::vector<int>* axis, std::string* error) {
  *vertex = h.elements.size();
  for (std::size_t i = 0; i < h.elements.size(); ++i) {
    if (h.elements[i].name == "vertex") *vertex = i;
  }
  if (*vertex == h.elements.size()) return fail(error, "no vertex element");
  const Element& e = h.elements[*vertex];
  axis->assign(e.properties.size(), -1);
  for (int k = 0; k < kAxes; ++k) {
    const int p = find_property(e, kAxisNames[k]);
    if (p < 0) return fail(error, std::string("vertex element has no property ") + kAxisNames[k]);
    const Property& prop = e.properties[p];
    if (prop.is_list || is_integer(prop.type)) {
      return fail(error,
                  std::string("vertex property ") + kAxisNames[k] + " must be a float or double scalar");
    }
    (*axis)[p] = k;
  }
  return true;
}

// Where the body's values go: the vertex element's x y z, and optionally the
// items of one list property (a mesh's face indices).
struct Targets {
  std::size_t vertex = 0;
  std::vector<int> axis;  // axis (0..2) of each vertex property, or -1
  std::vector<double>* xyz = nullptr;
  std::size_t list_element = static_cast<std::size_t>(-1);
  std::size_t list_property = 0;
  std::vector<double>* list_items = nullptr;

  std::vector<double>* items_of(std::size_t element, std::size_t property) const {
    return element == list_element && property == list_property ? list_items : nullptr;
  }
};

// The face element's index list ("vertex_indices" or "vertex_index"), if any.
bool find_face_list(const Header& h, Targets* t, std::string* error) {
  for (std::size_t i = 0; i < h.elements.size(); ++i) {
    if (h.elements[i].name != "face") continue;
    int p = find_property(h.elements[i], "vertex_indices");
    if (p < 0) p = find_property(h.elements[i], "vertex_index");
    if (p < 0 || !h.elements[i].properties[p].is_list || !is_integer(h.elements[i].properties[p].type))
      return fail(error, "face element has no integer list property vertex_indices");
    t->list_element = i;
    t->list_property = static_cast<std::size_t>(p);
    return true;
  }
  return fail(error, "no face element (a point cloud, not a mesh)");
}

// ---- binary ----

struct BinaryCursor {
  const unsigned char* data;
  std::size_t size;
  std::size_t pos;
  bool big_endian;

  std::size_t remaining() const { return size - pos; }
  // Unsigned integer of n bytes in the file's byte order.
  uint64_t take_bits(std::size_t n) {
    uint64_t bits = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t byte = big_endian ? i : n - 1 - i;
      bits = (bits << 8) | data[pos + byte];
    }
    pos += n;
    return bits;
  }
};

double decode(Type type, uint64_t bits) {
  switch (type) {
    case Type::kInt8: return static_cast<int8_t>(bits);
    case Type::kUint8: return static_cast<uint8_t>(bits);
    case Type::kInt16: return static_cast<int16_t>(bits);
    case Type::kUint16: return static_cast<uint16_t>(bits);
    case Type::kInt32: return static_cast<int32_t>(bits);
    case Type::kUint32: return static_cast<uint32_t>(bits);
    case Type::kFloat32: {
      const auto b32 = static_cast<uint32_t>(bits);
      float f;
      std::memcpy(&f, &b32, sizeof f);
      return f;
    }
    case Type::kFloat64: {
      double d;
      std::memcpy(&d, &bits, sizeof d);
      return d;
    }
  }
  return 0.0;
}

// Fewest bytes one entry of the element can take (lists may be empty).
std::size_t min_binary_size(const Element& e) {
  std::size_t size = 0;
  for (const Property& p : e.properties) size += type_size(p.is_list ? p.count_type : p.type);
  return size;
}

// A list's items go to *items (count first, then the items) when items is not null.
bool read_binary_property(BinaryCursor* c, const Property& p, double* value, std::vector<double>* items,
                          const std::string& where, std::string* error) {
  if (!p.is_list) {
    if (c->remaining() < type_size(p.type)) return fail(error, "data truncated in " + where);
    *value = decode(p.type, c->take_bits(type_size(p.type)));
    return true;
  }
  const std::size_t count_size = type_size(p.count_type);
  if (c->remaining() < count_size) return fail(error, "data truncated in " + where);
  const double count = decode(p.count_type, c->take_bits(count_size));
  if (count < 0.0) return fail(error, "negative list length in " + where);
  const double bytes = count * static_cast<double>(type_size(p.type));
  if (bytes > static_cast<double>(c->remaining())) {
    return fail(error, "data truncated in a list of " + where);
  }
  if (items == nullptr) {
    c->pos += static_cast<std::size_t>(bytes);
    return true;
  }
  items->push_back(count);
  for (uint64_t i = 0; i < static_cast<uint64_t>(count); ++i)
    items->push_back(decode(p.type, c->take_bits(type_size(p.type))));
  return true;
}

// The entries of element `ei`, each property read by `read_property` (the
// binary or the ascii one); the vertex element's x, y and z go to t.xyz.
template <class Cursor, class ReadProperty>
bool read_element(Cursor* c, const Element& e, std::size_t ei, const Targets& t, ReadProperty read_property,
                  std::string* error) {
  const bool is_vertex = ei == t.vertex;
  if (is_vertex) t.xyz->reserve(kAxes * e.count);
  const std::string where = "element '" + e.name + "'";
  double point[kAxes] = {0.0, 0.0, 0.0};
  for (uint64_t n = 0; n < e.count; ++n) {
    for (std::size_t p = 0; p < e.properties.size(); ++p) {
      double value = 0.0;
      if (!read_property(c, e.properties[p], &value, t.items_of(ei, p), where, error)) return false;
      if (is_vertex && t.axis[p] >= 0) point[t.axis[p]] = value;
    }
    if (is_vertex) t.xyz->insert(t.xyz->end(), point, point + kAxes);
  }
  return true;
}

bool read_binary(const std::string& bytes, const Header& h, const Targets& t, std::string* error) {
  BinaryCursor c{reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), h.data_offset,
                 h.format == Format::kBinaryBigEndian};
  for (std::size_t ei = 0; ei < h.elements.size(); ++ei) {
    const Element& e = h.elements[ei];
    const std::size_t min_size = min_binary_size(e);
    if (e.count > 0 && (min_size == 0 || e.count > c.remaining() / min_size)) {
      return fail(error, "element '" + e.name + "' claims " + std::to_string(e.count) + " entries but only " +
                             std::to_string(c.remaining()) +
                             " bytes of data remain (truncated file or wrong count)");
    }
    if (!read_element(&c, e, ei, t, read_binary_property, error)) return false;
  }
  if (c.remaining() != 0) {
    return fail(error, std::to_string(c.remaining()) +
                           " bytes of unexpected data after the last element (wrong count?)");
  }
  return true;
}

}  // namespace

double binary_value(Type type, const unsigned char* p, bool big_endian) {
  BinaryCursor c{p, type_size(type), 0, big_endian};
  return decode(type, c.take_bits(type_size(type)));
}

namespace {

// ---- ascii ----

struct TextCursor {
  const std::string& text;
  std::size_t pos;

  static bool is_space(char ch) {
    return ch == ' ' || ch == '\t' || ch == '\n' || ch == '\r' || ch == '\v' || ch == '\f';
  }
  // Next whitespace-separated token; empty at the end of the text.
  std::string_view next() {
    while (pos < text.size() && is_space(text[pos])) ++pos;
    const std::size_t start = pos;
    while (pos < text.size() && !is_space(text[pos])) ++pos;
    return std::string_view(text).substr(start, pos - start);
  }
};

bool parse_number(std::string_view token, double* value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  const char* end = token.data() + token.size();
  const auto result = std::from_chars(token.data(), end, *value);
  return !token.empty() && result.ec == std::errc() && result.ptr == end;
}

bool read_ascii_value(TextCursor* c, double* value, const std::string& where, std::string* error) {
  const std::string_view token = c->next();
  if (token.empty()) return fail(error, "data ends early in " + where);
  if (!parse_number(token, value)) {
    return fail(error, "invalid number '" + std::string(token.substr(0, 32)) + "' in " + where);
  }
  return true;
}

bool read_ascii_property(TextCursor* c, const Property& p, double* value, std::vector<double>* items,
                         const std::string& where, std::string* error) {
  if (!read_ascii_value(c, value, where, error)) return false;
  if (!p.is_list) return true;
  const double count = *value;
  // Range first: casting a double beyond uint64 is undefined (found by fuzz_cloud_reader).
  // No PLY count type is wider than 32 bits.
  constexpr double kMaxListLength = 4294967295.0;
  if (!(count >= 0.0 && count <= kMaxListLength) ||
      count != static_cast<double>(static_cast<uint64_t>(count))) {
    return fail(error, "invalid list length in " + where);
  }
  if (items != nullptr) items->push_back(count);
  // Each item consumes a token or fails, so the loop is bounded by the file.
  for (uint64_t i = 0; i < static_cast<uint64_t>(count); ++i) {
    double item = 0.0;
    if (!read_ascii_value(c, &item, where, error)) return false;
    if (items != nullptr) items->push_back(item);
  }
  return true;
}

bool read_ascii(const std::string& bytes, const Header& h, const Targets& t, std::string* error) {
  TextCursor c{bytes, h.data_offset};
  for (std::size_t ei = 0; ei < h.elements.size(); ++ei) {
    const Element& e = h.elements[ei];
    const std::size_t min_size = kMinAsciiBytesPerValue * e.properties.size();
    const std::size_t remaining = bytes.size() - c.pos;
    // A final value may lack its separator, hence the +1.
    if (e.count > 0 && (min_size == 0 || e.count > (remaining + 1) / min_size)) {
      return fail(error, "element '" + e.name + "' claims " + std::to_string(e.count) +
                             " entries but the file is too short (truncated or wrong count)");
    }
    if (!read_element(&c, e, ei, t, read_ascii_property, error)) return false;
  }
  if (!c.next().empty()) return fail(error, "unexpected data after the last element (wrong count?)");
  return true;
}

bool read_targets(const std::string& bytes, const Header& header, const Targets& t, std::string* error) {
  if (header.data_offset > bytes.size()) return fail(error, "header offset beyond the file");
  return header.format == Format::kAscii ? read_ascii(bytes, header, t, error)
                                         : read_binary(bytes, header, t, error);
}

}  // namespace

bool read_body(const std::string& bytes, const Header& header, std::vector<double>* xyz, std::string* error) {
  xyz->clear();
  Targets t;
  t.xyz = xyz;
  const bool ok = check_vertex(header, &t.vertex, &t.axis, error) && read_targets(bytes, header, t, error);
  if (!ok) xyz->clear();
  return ok;
}

bool read_mesh_body(const std::string& bytes, const Header& header, std::vector<double>* xyz,
                    std::vector<double>* faces, std::string* error) {
  xyz->clear();
  faces->clear();
  Targets t;
  t.xyz = xyz;
  t.list_items = faces;
  const bool ok = check_vertex(header, &t.vertex, &t.axis, error) && find_face_list(header, &t, error) &&
                  read_targets(bytes, header, t, error);
  if (!ok) xyz->clear(), faces->clear();
  return ok;
}

}  // namespace spinhash::host::ply
