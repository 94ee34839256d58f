#include "cloud/ply_header.hpp"

#include <algorithm>
#include <charconv>
#include <sstream>

namespace spinhash::host::ply {
namespace {

struct TypeName {
  const char* name;
  Type type;
};

// PLY's original names and the sized aliases many writers use.
constexpr TypeName kTypeNames[] = {
    {"char", Type::kInt8},       {"int8", Type::kInt8},       {"uchar", Type::kUint8},
    {"uint8", Type::kUint8},     {"short", Type::kInt16},     {"int16", Type::kInt16},
    {"ushort", Type::kUint16},   {"uint16", Type::kUint16},   {"int", Type::kInt32},
    {"int32", Type::kInt32},     {"uint", Type::kUint32},     {"uint32", Type::kUint32},
    {"float", Type::kFloat32},   {"float32", Type::kFloat32}, {"double", Type::kFloat64},
    {"float64", Type::kFloat64},
};

bool fail(std::string* error, std::size_t line, const std::string& message) {
  if (error) *error = "PLY header line " + std::to_string(line) + ": " + message;
  return false;
}

bool parse_type(const std::string& name, Type* type) {
  for (const TypeName& t : kTypeNames) {
    if (name == t.name) {
      *type = t.type;
      return true;
    }
  }
  return false;
}

std::vector<std::string> split_words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> words;
  std::string word;
  while (in >> word) words.push_back(word);
  return words;
}

bool parse_count(const std::string& text, uint64_t* count) {
  const char* end = text.data() + text.size();
  const auto result = std::from_chars(text.data(), end, *count);
  return result.ec == std::errc() && result.ptr == end;
}

bool parse_format(const std::vector<std::string>& w, Header* header, std::size_t line, std::string* error) {
  if (w.size() != 3) return fail(error, line, "expected 'format <type> 1.0'");
  if (w[1] == "ascii") {
    header->format = Format::kAscii;
  } else if (w[1] == "binary_little_endian") {
    header->format = Format::kBinaryLittleEndian;
  } else if (w[1] == "binary_big_endian") {
    header->format = Format::kBinaryBigEndian;
  } else {
    return fail(error, line, "unknown format '" + w[1] + "'");
  }
  if (w[2] != "1.0") return fail(error, line, "unsupported PLY version '" + w[2] + "'");
  return true;
}

bool parse_element(const std::vector<std::string>& w, Header* header, std::size_t line, std::string* error) {
  if (w.size() != 3) return fail(error, line, "expected 'element <name> <count>'");
  Element element;
  element.name = w[1];
  if (!parse_count(w[2], &element.count)) {
    return fail(error, line, "invalid element count '" + w[2] + "'");
  }
  for (const Element& e : header->elements) {
    if (e.name == element.name) return fail(error, line, "duplicate element '" + w[1] + "'");
  }
  header->elements.push_back(element);
  return true;
}

bool parse_property(const std::vector<std::string>& w, Header* header, std::size_t line, std::string* error) {
  if (header->elements.empty()) return fail(error, line, "property before any element");
  Property p;
  if (w.size() == 5 && w[1] == "list") {
    p.is_list = true;
    if (!parse_type(w[2], &p.count_type) || !is_integer(p.count_type)) {
      return fail(error, line, "invalid list count type '" + w[2] + "'");
    }
    if (!parse_type(w[3], &p.type)) return fail(error, line, "unknown type '" + w[3] + "'");
    p.name = w[4];
  } else if (w.size() == 3 && w[1] != "list") {
    if (!parse_type(w[1], &p.type)) return fail(error, line, "unknown type '" + w[1] + "'");
    p.name = w[2];
  } else {
    return fail(error, line, "expected 'property <type> <name>' or 'property list ...'");
  }
  Element& element = header->elements.back();
  for (const Property& q : element.properties) {
    if (q.name == p.name) return fail(error, line, "duplicate property '" + p.name + "'");
  }
  element.properties.push_back(p);
  return true;
}

// Reads one header line (without '\n' or a trailing '\r') at *pos.
bool next_line(const std::string& bytes, std::size_t* pos, std::string* line) {
  const std::size_t limit = std::min(bytes.size(), kMaxHeaderBytes);
  const std::size_t end = bytes.find('\n', *pos);
  if (end == std::string::npos || end >= limit) return false;
  *line = bytes.substr(*pos, end - *pos);
  if (!line->empty() && line->back() == '\r') line->pop_back();
  *pos = end + 1;
  return true;
}

}  // namespace

std::size_t type_size(Type type) {
  switch (type) {
    case Type::kInt8:
    case Type::kUint8: return 1;
    case Type::kInt16:
    case Type::kUint16: return 2;
    case Type::kInt32:
    case Type::kUint32:
    case Type::kFloat32: return 4;
    case Type::kFloat64: return 8;
  }
  return 0;
}

bool is_integer(Type type) { return type != Type::kFloat32 && type != Type::kFloat64; }

bool parse_header(const std::string& bytes, Header* header, std::string* error) {
  *header = Header{};
  std::size_t pos = 0;
  std::string line;
  if (!next_line(bytes, &pos, &line) || line != "ply") {
    return fail(error, 1, "not a PLY file (no 'ply' magic line)");
  }
  bool have_format = false;
  for (std::size_t number = 2;; ++number) {
    if (!next_line(bytes, &pos, &line)) {
      return fail(error, number,
                  "missing end_header (header cut short or longer than " + std::to_string(kMaxHeaderBytes) +
                      " bytes)");
    }
    const std::vector<std::string> w = split_words(line);
    if (w.empty()) continue;
    const std::string& key = w[0];
    if (key == "comment" || key == "obj_info") continue;
    if (key == "end_header") {
      if (w.size() != 1) return fail(error, number, "text after end_header");
      break;
    }
    bool ok = false;
    if (key == "format") {
      if (have_format) return fail(error, number, "second format line");
      ok = have_format = parse_format(w, header, number, error);
    } else if (!have_format) {
      return fail(error, number, "'" + key + "' before the format line");
    } else if (key == "element") {
      ok = parse_element(w, header, number, error);
    } else if (key == "property") {
      ok = parse_property(w, header, number, error);
    } else {
      return fail(error, number, "unknown keyword '" + key + "'");
    }
    if (!ok) return false;
  }
  if (!have_format) return fail(error, 2, "missing format line");
  header->data_offset = pos;
  return true;
}

}  // namespace spinhash::host::ply
