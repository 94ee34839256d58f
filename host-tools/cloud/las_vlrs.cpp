#include "cloud/las_vlrs.hpp"

#include <algorithm>

#include "cloud/point_source.hpp"

namespace spinhash::host {
namespace {

constexpr size_t kVlrHeaderBytes = 54;   // reserved, user id, record id, length, description
constexpr size_t kEvlrHeaderBytes = 60;  // the same with a 64-bit length
constexpr size_t kUserIdAt = 2, kUserIdBytes = 16, kRecordIdAt = 18, kLengthAt = 20;

uint64_t le(const uint8_t* p, int bytes) {
  uint64_t v = 0;
  for (int i = bytes - 1; i >= 0; --i) v = (v << 8) | p[i];
  return v;
}

std::string user_id(const uint8_t* p) {
  const char* s = reinterpret_cast<const char*>(p + kUserIdAt);
  return std::string(s, std::find(s, s + kUserIdBytes, '\0'));
}

// Walks n records from `at`; stops before `end` (records must fit).
void walk(ByteSource& src, uint64_t at, uint64_t end, uint64_t n, bool extended, std::vector<Vlr>* out,
          std::vector<std::string>* warnings) {
  const size_t head = extended ? kEvlrHeaderBytes : kVlrHeaderBytes;
  for (uint64_t i = 0; i < n; ++i) {
    if (at > end || end - at < head) {
      if (warnings)
        warnings->push_back("LAS: the header declares " + std::to_string(n) +
                            (extended ? " EVLRs" : " VLRs") + ", only " + std::to_string(i) +
                            " fit; the rest are ignored");
      return;
    }
    uint8_t b[kEvlrHeaderBytes];
    src.read_at(at, b, head);
    Vlr v;
    v.user_id = user_id(b);
    v.record_id = static_cast<uint16_t>(le(b + kRecordIdAt, 2));
    v.length = le(b + kLengthAt, extended ? 8 : 2);
    v.extended = extended;
    at += head;
    const uint64_t room = end - at;
    if (v.length <= room && v.length <= kMaxLoadedVlrBytes) {
      v.data.resize(static_cast<size_t>(v.length));
      if (!v.data.empty()) src.read_at(at, v.data.data(), v.data.size());
      v.loaded = true;
    }
    out->push_back(std::move(v));
    if (out->back().length > room) {
      if (warnings) warnings->push_back("LAS: a VLR's payload runs past the point data; the VLRs end there");
      return;
    }
    at += out->back().length;
  }
}

}  // namespace

std::vector<Vlr> read_vlrs(ByteSource& src, const LasHeader& h, std::vector<std::string>* warnings) {
  std::vector<Vlr> vlrs;
  walk(src, h.header_size, h.offset_to_points, h.vlr_count, false, &vlrs, warnings);
  if (h.evlr_count > 0 && h.evlr_offset >= h.offset_to_points && h.evlr_offset < src.size())
    walk(src, h.evlr_offset, src.size(), h.evlr_count, true, &vlrs, warnings);
  return vlrs;
}

const Vlr* find_vlr(const std::vector<Vlr>& vlrs, const std::string& user_id, uint16_t record_id) {
  for (const Vlr& v : vlrs)
    if (v.loaded && v.record_id == record_id && v.user_id == user_id) return &v;
  return nullptr;
}

}  // namespace spinhash::host
